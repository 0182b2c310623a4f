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

CLI::Validator line_mask() {
    return CLI::Validator(
        [](std::string& s) -> std::string {
            bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
            std::string digits = hex ? s.substr(2) : s;
            bool ok = !digits.empty() && digits.size() <= 4 &&
                      digits.find_first_not_of(hex ? "0123456789abcdefABCDEF" : "0123456789") == std::string::npos;
            unsigned long v = ok ? std::stoul(digits, nullptr, hex ? 16 : 10) : 256;
            if (v > 255) return "must be a mask of the 8 data lines, 0 to 255 or 0x00 to 0xFF, not '" + s + "'";
            s = std::to_string(v);
            return "";
        },
        "MASK");
}

std::optional<std::uint8_t> byte_value(const std::string& text) {
    if (text.size() == 1) return static_cast<std::uint8_t>(text[0]);
    bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
    std::string_view digits = std::string_view(text).substr(hex ? 2 : 0);
    unsigned v = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, hex ? 16 : 10);
    bool plain = !digits.empty() && digits.size() <= 3 &&
                 digits.find_first_not_of(hex ? "0123456789abcdefABCDEF" : "0123456789") == std::string_view::npos;
    if (!plain || ec != std::errc{} || end != digits.data() + digits.size() || v > 255) return std::nullopt;
    return static_cast<std::uint8_t>(v);
}

}  // namespace cli
