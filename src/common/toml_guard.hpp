// A guard run before toml++ parses a file: toml++ 3.3.0 (Debian 12) reaches __builtin_unreachable on a
// bare non-ASCII character (upstream marzer/tomlplusplus#295), so such text is refused first.
#pragma once

#include <string_view>

namespace tape {

/// Throws Error(Errc::usage) at the first byte >= 0x80 that stands outside a TOML string (basic,
/// literal, multi-line basic or literal; quoted keys are strings too) or a # comment: the message names
/// `file` and the character, the position its line and column. Text that is no valid TOML otherwise is
/// left to the parser. Reads `text` only; never throws for a byte inside a string or a comment.
void reject_bare_non_ascii(std::string_view text, std::string_view file);

}  // namespace tape
