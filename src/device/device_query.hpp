// The settings part of a device string, "PATH?key=value&key=value", as every backend takes it: one
// parser, so that an unknown key, a key given twice or a bad value reads the same whatever the backend.
#pragma once

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tape {

/// value with every byte but letters, digits and - . _ ~ written %XX (as in a URL's query): a string
/// from outside (a USB serial) put into a device string cannot end its value or start another setting.
std::string percent_encoded(std::string_view value);

class DeviceQuery {
public:
    /// Splits rest (the device string after "backend:") at its first '?' into the path and the
    /// key=value pairs between '&'s (empty pairs skipped); %XX in a value is the byte XX. keys are the backend's
    /// settings; none for a backend that takes none. Throws Error(Errc::usage), "BACKEND device: ...", naming a key
    /// that is not one of keys, a key given twice, a pair that is not key=value, or a '%' in a value that is not
    /// followed by two hex digits.
    DeviceQuery(std::string_view backend, std::string_view rest, std::span<const std::string_view> keys);

    const std::string& path() const { return path_; }
    /// The value given for key, or nullopt.
    std::optional<std::string_view> value(std::string_view key) const;

    /// key's value as a whole number, or fallback when not given. Error(Errc::usage) naming key=value
    /// when it is none.
    unsigned number(std::string_view key, unsigned fallback) const;

    /// key's value as one of the named choices, or fallback when not given. Error(Errc::usage) naming
    /// key=value and listing the choices otherwise.
    template <typename T>
    T choice(std::string_view key, T fallback, std::initializer_list<std::pair<std::string_view, T>> choices) const {
        auto given = value(key);
        if (!given) return fallback;
        std::string names;
        for (const auto& [name, v] : choices) {
            if (name == *given) return v;
            names += (names.empty() ? "" : ", ") + std::string(name);
        }
        bad_value(key, *given, "is not one of " + names);
    }

    /// Error(Errc::usage) "BACKEND device: KEY=VALUE what", e.g. what = "is not a number".
    [[noreturn]] void bad_value(std::string_view key, std::string_view value, const std::string& what) const;
    /// Error(Errc::usage) "BACKEND device: message".
    [[noreturn]] void fail(const std::string& message) const;

private:
    /// value with its %XX decoded; Error(Errc::usage) naming key for a malformed one.
    std::string decoded(std::string_view key, std::string_view value) const;

    std::string backend_;
    std::string path_;
    std::vector<std::pair<std::string, std::string>> settings_;
};

}  // namespace tape
