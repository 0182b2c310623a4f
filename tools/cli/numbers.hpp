// Numeric options checked as text before CLI11 converts them: "-1" must not wrap round to 2^64-1 in an
// unsigned option, and "nan" or "1e-300" must not reach a duration cast.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

namespace cli {

/// A whole number in decimal digits, from min to max; the message names the range.
CLI::Validator whole_number(std::uint64_t min, std::uint64_t max);

/// A whole number with an optional sign ("-100", "+100", "100"), from min to max.
CLI::Validator signed_whole_number(std::int64_t min, std::int64_t max);

/// A finite decimal number from min to max (both included).
CLI::Validator real_number(double min, double max);

/// A mask of the eight data lines, in decimal or 0x hex (a wiring is read off as bits), 0 to 255; the
/// text is replaced by its decimal value.
CLI::Validator line_mask();

/// A byte option's value: one character (':'), a decimal byte value (17) or a hex one (0x11); nullopt
/// for anything else (a sign, spaces, an octal-looking 017 is decimal 17).
std::optional<std::uint8_t> byte_value(const std::string& text);

}  // namespace cli
