#include "device_query.hpp"

#include <algorithm>
#include <charconv>

#include "tape/error.hpp"

namespace tape {

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
        settings_.emplace_back(key, pair.substr(eq + 1));
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
