#include "cli/json.hpp"

#include "tape/code.hpp"

namespace cli {
namespace {

// Strings as nlohmann-json escapes them; bytes that are no UTF-8 replaced rather than thrown about.
std::string scalar(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

void append(std::string& out, const Json& value) {
    if (value.is_object()) {
        out += '{';
        bool first = true;
        for (const auto& [name, member] : value.items()) {
            out += first ? "" : ", ";
            first = false;
            out += scalar(Json(name));
            out += ": ";
            append(out, member);
        }
        out += '}';
    } else if (value.is_array()) {
        out += '[';
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (i) out += ", ";
            append(out, value[i]);
        }
        out += ']';
    } else {
        out += scalar(value);
    }
}

Json optional_number(const std::optional<std::uint64_t>& n) { return n ? Json(*n) : Json(nullptr); }

}  // namespace

std::string json_text(const Json& value) {
    std::string out;
    append(out, value);
    return out;
}

std::string json_string(const std::string& s) { return json_text(Json(s)); }

std::string json_number(const std::optional<std::uint64_t>& n) { return json_text(optional_number(n)); }

Json finding_value(const tape::Diagnostic& f) {
    return Json{{"rule", std::string(f.id())},
                {"severity", std::string(tape::severity_name(f.severity))},
                {"frame", optional_number(f.where.frame)},
                {"line", optional_number(f.where.line)},
                {"column", optional_number(f.where.column)},
                {"block", optional_number(f.where.block)},
                {"message", f.message}};
}

std::string finding_json(const tape::Diagnostic& f) { return json_text(finding_value(f)); }

Json label_value(const std::optional<tape::LeaderLabel>& label) {
    if (!label) return nullptr;
    return Json{{"text", label->text},
                {"first_frame", label->first + 1},
                {"frames", label->frames},
                {"code", std::string(tape::code_name(label->code))}};
}

std::string label_json(const std::optional<tape::LeaderLabel>& label) { return json_text(label_value(label)); }

}  // namespace cli
