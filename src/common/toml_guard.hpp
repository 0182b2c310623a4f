// toml++ 3.3.0 (Debian 12) reaches __builtin_unreachable on a byte above 0x7F outside a string or a
// comment, where the TOML grammar allows none: such a text is refused here, before it is parsed.
#pragma once

#include <string_view>

namespace tape {

/// Throws Error(Errc::usage) "FILE: line N: byte 0xXX outside a string or comment ..." for the first
/// byte above 0x7F that stands outside a TOML string or comment.
void reject_bare_non_ascii(std::string_view text, std::string_view file);

}  // namespace tape
