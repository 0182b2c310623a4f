// JSON for other programs, built with nlohmann-json and laid out on one line as tape(1) documents it:
// members in the order given, ", " between them and ": " after names.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "tape/error.hpp"
#include "tape/label.hpp"

namespace cli {

/// A JSON value whose members keep the order they were added in.
using Json = nlohmann::ordered_json;

/// value on one line: {"a": 1, "b": [2, 3]}. Strings are UTF-8 with controls escaped; bytes that are no
/// UTF-8 become U+FFFD, so that the text is always valid JSON.
std::string json_text(const Json& value);

/// A JSON string literal for s.
std::string json_string(const std::string& s);
/// A number, or null.
std::string json_number(const std::optional<std::uint64_t>& n);
/// {"rule", "severity", "frame", "line", "column", "block", "message"}: one finding as tape(1) documents it.
Json finding_value(const tape::Diagnostic& f);
std::string finding_json(const tape::Diagnostic& f);
/// {"text", "first_frame", "frames", "code"} or null.
Json label_value(const std::optional<tape::LeaderLabel>& label);
std::string label_json(const std::optional<tape::LeaderLabel>& label);

}  // namespace cli
