#include "device_query.hpp"

#include <algorithm>
#include <charconv>

#include "tape/error.hpp"

namespace tape {
namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

std::string percent_encoded(std::string_view value) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string out;
    for (char c : value) {
        auto b = static_cast<unsigned char>(c);
        bool plain = (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || b == '-' ||
                     b == '.' || b == '_' || b == '~';
        if (plain) {
            out += c;
        } else {
            out += '%';
            out += digits[b >> 4];
            out += digits[b & 15];
        }
    }
    return out;
}

std::string DeviceQuery::decoded(std::string_view key, std::string_view value) const {
    std::string out;
    for (std::size_t i = 0; i < value.size(); ++i) {
        if (value[i] != '%') {
            out += value[i];
            continue;
        }
        bool whole = i + 2 < value.size();
        int high = whole ? hex_digit(value[i + 1]) : -1, low = whole ? hex_digit(value[i + 2]) : -1;
        if (high < 0 || low < 0) bad_value(key, value, "has a '%' not followed by two hex digits (write %25 for '%')");
        out += static_cast<char>(high * 16 + low);
        i += 2;
    }
    return out;
}

DeviceQuery::DeviceQuery(std::string_view backend, std::string_view rest, std::span<const std::string_view> keys)
    : backend_(backend) {
    auto q = rest.find('?');
    path_ = std::string(rest.substr(0, q));
    std::string_view query = q == std::string_view::npos ? std::string_view{} : rest.substr(q + 1);
    while (!query.empty()) {
        auto amp = query.find('&');
        std::string_view pair = query.substr(0, amp);
        query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
        if (pair.empty()) continue;
        auto eq = pair.find('=');
        std::string_view key = pair.substr(0, eq);
        // The key is judged first: "file:x.ptp?baud" is better told that file: takes no settings.
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
            std::string known;
            for (auto k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
            fail("unknown setting '" + std::string(key) + "' " +
                 (keys.empty() ? "(" + backend_ + ": takes no settings)" : "(" + known + ")"));
        }
        if (eq == std::string_view::npos) fail("'" + std::string(pair) + "' is not key=value");
        // A second value would silently win over the first: the string is surely not what was meant.
        if (value(key)) fail(std::string(key) + " given twice");
        settings_.emplace_back(key, decoded(key, pair.substr(eq + 1)));
    }
}

std::optional<std::string_view> DeviceQuery::value(std::string_view key) const {
    for (const auto& [k, v] : settings_)
        if (k == key) return v;
    return std::nullopt;
}

unsigned DeviceQuery::number(std::string_view key, unsigned fallback) const {
    auto given = value(key);
    if (!given) return fallback;
    unsigned n = 0;
    auto [end, ec] = std::from_chars(given->data(), given->data() + given->size(), n);
    if (ec != std::errc{} || end != given->data() + given->size()) bad_value(key, *given, "is not a number");
    return n;
}

void DeviceQuery::bad_value(std::string_view key, std::string_view value, const std::string& what) const {
    fail(std::string(key) + "=" + std::string(value) + " " + what);
}

void DeviceQuery::fail(const std::string& message) const { throw Error(Errc::usage, backend_ + " device: " + message); }

}  // namespace tape
