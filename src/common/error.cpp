#include "tape/error.hpp"

namespace tape {

std::string_view errc_name(Errc code) {
    switch (code) {
        case Errc::parity:
            return "parity";
        case Errc::not_in_code:
            return "not-in-code";
        case Errc::unknown_code:
            return "unknown-code";
        case Errc::bad_image:
            return "bad-image";
        case Errc::bad_text:
            return "bad-text";
        case Errc::bad_table:
            return "bad-table";
        case Errc::bad_program:
            return "bad-program";
        case Errc::exists:
            return "exists";
        case Errc::doubtful_frame:
            return "doubtful-frame";
        case Errc::blank_frame:
            return "blank-frame";
        case Errc::io:
            return "io";
        case Errc::usage:
            return "usage";
    }
    return "unknown";
}

bool is_data_error(Errc code) { return code != Errc::io && code != Errc::usage && code != Errc::exists; }

bool is_bad_frame(Errc code) { return code == Errc::parity || code == Errc::not_in_code; }

std::string_view severity_name(Severity s) {
    switch (s) {
        case Severity::note:
            return "note";
        case Severity::warning:
            return "warning";
        case Severity::error:
            return "error";
    }
    return "error";
}

std::string Position::describe() const {
    std::string s;
    if (frame) s = "frame " + std::to_string(*frame);
    if (line) {
        if (!s.empty()) s += ", ";
        s += "line " + std::to_string(*line);
        if (column) s += ", column " + std::to_string(*column);
    }
    return s;
}

}  // namespace tape
