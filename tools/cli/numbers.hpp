// Numeric options checked as text before CLI11 converts them: "-1" must not wrap round to 2^64-1 in an
// unsigned option, and "nan" or "1e-300" must not reach a duration cast.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>

namespace cli {

/// A whole number in decimal digits, from min to max; the message names the range.
CLI::Validator whole_number(std::uint64_t min, std::uint64_t max);

/// A whole number with an optional sign ("-100", "+100", "100"), from min to max.
CLI::Validator signed_whole_number(std::int64_t min, std::int64_t max);

/// A finite decimal number from min to max (both included).
CLI::Validator real_number(double min, double max);

}  // namespace cli
