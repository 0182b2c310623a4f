#include "cli/numbers.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

namespace cli {
namespace {

std::string trimmed_number(std::string number) {
    // 1e-300 is shown as written by %g, not as a 300-digit fraction.
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", std::stod(number));
    return buf;
}

}  // namespace

CLI::Validator whole_number(std::uint64_t min, std::uint64_t max) {
    std::string range = std::to_string(min) + " to " + std::to_string(max);
    return CLI::Validator(
        [min, max, range](std::string& text) -> std::string {
            std::uint64_t v = 0;
            auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
            bool digits_only = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
            if (!digits_only || ec != std::errc{} || end != text.data() + text.size() || v < min || v > max)
                return "must be a whole number from " + range + ", not '" + text + "'";
            return {};
        },
        range);
}

CLI::Validator signed_whole_number(std::int64_t min, std::int64_t max) {
    std::string range = std::to_string(min) + " to " + std::to_string(max);
    return CLI::Validator(
        [min, max, range](std::string& text) -> std::string {
            std::size_t sign = text.starts_with('-') || text.starts_with('+') ? 1 : 0;
            std::string_view digits = std::string_view(text).substr(sign);
            bool plain = !digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos;
            // from_chars takes a '-' but not a '+'.
            std::string_view number = text.starts_with('+') ? digits : std::string_view(text);
            std::int64_t v = 0;
            auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
            if (!plain || ec != std::errc{} || end != number.data() + number.size() || v < min || v > max)
                return "must be a whole number from " + range + ", not '" + text + "'";
            return {};
        },
        range);
}

CLI::Validator real_number(double min, double max) {
    std::string range = trimmed_number(std::to_string(min)) + " to " + trimmed_number(std::to_string(max));
    return CLI::Validator(
        [min, max, range](std::string& text) -> std::string {
            double v = 0;
            auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
            bool plain = !text.empty() && text.find_first_not_of("0123456789.eE+-") == std::string::npos;
            if (!plain || ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(v) || v < min ||
                v > max)
                return "must be a number from " + range + ", not '" + text + "'";
            return {};
        },
        range);
}

}  // namespace cli
