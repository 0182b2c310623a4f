// Macro expressions as Fanuc Custom Macro B and LinuxCNC write them: #-references, [ ] expressions,
// functions and operators. Only checked for form; nothing is evaluated.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace tape::macro {

/// The length of the #-reference at s[i] ('#'): "#12", "#[#1+1]", "#<name>" (named: LinuxCNC);
/// 0 when s[i] starts none.
std::size_t reference_length(std::string_view s, std::size_t i, bool named);

/// The length of the bracket group at s[i] ('['), up to its matching ']'; npos when it is not closed.
std::size_t group_length(std::string_view s, std::size_t i);

/// The length of the value at s[i]: an optional sign, then a number, a #-reference, a [ ] group or
/// (LinuxCNC) a function with its group; 0 when none stands there.
std::size_t value_length(std::string_view s, std::size_t i, bool linuxcnc);

/// What is wrong with an expression (brackets, names, characters), or nullopt when it is well formed.
std::optional<std::string> check_expression(std::string_view expr, bool linuxcnc);

/// The letters of s[i..] that form a name ("WHILE", "sub"), upper-cased; empty when s[i] is no letter.
std::string name_at(std::string_view s, std::size_t i);

}  // namespace tape::macro
