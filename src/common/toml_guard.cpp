#include "toml_guard.hpp"

#include <cstdint>
#include <cstdio>
#include <string>

#include "tape/error.hpp"

namespace tape {
namespace {

enum class In { code, comment, basic, literal, multi_basic, multi_literal };

// The character at `at` as the user typed it, when it is whole UTF-8; its byte in hex otherwise.
std::string shown_at(std::string_view text, std::size_t at) {
    auto lead = static_cast<unsigned char>(text[at]);
    std::size_t length = lead >= 0xF0 && lead < 0xF5 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 && lead < 0xE0 ? 2 : 0;
    bool whole = length > 0 && at + length <= text.size();
    for (std::size_t k = 1; whole && k < length; ++k) whole = (static_cast<unsigned char>(text[at + k]) & 0xC0) == 0x80;
    if (whole) return "'" + std::string(text.substr(at, length)) + "'";
    char hex[16];
    std::snprintf(hex, sizeof hex, "byte 0x%02X", lead);
    return hex;
}

// Characters (not bytes) from the start of the line up to `at`, counted from 1.
std::uint64_t column_of(std::string_view text, std::size_t line_start, std::size_t at) {
    std::uint64_t column = 1;
    for (std::size_t k = line_start; k < at; ++k) column += (static_cast<unsigned char>(text[k]) & 0xC0) != 0x80;
    return column;
}

bool opens(std::string_view text, std::size_t at, std::string_view delimiter) {
    return text.substr(at, delimiter.size()) == delimiter;
}

// Past a multi-line string's closing delimiter: up to two more quotes belong to the string ("""a""""").
std::size_t past_close(std::string_view text, std::size_t at, char quote) {
    at += 3;
    for (int extra = 0; extra < 2 && at < text.size() && text[at] == quote; ++extra) ++at;
    return at;
}

// Where the scan goes from `code` at `i`: the state it enters and the index past what it consumed.
std::size_t enter(std::string_view text, std::size_t i, In& in) {
    if (text[i] == '#') return in = In::comment, i + 1;
    if (opens(text, i, "\"\"\"")) return in = In::multi_basic, i + 3;
    if (opens(text, i, "'''")) return in = In::multi_literal, i + 3;
    if (text[i] == '"') return in = In::basic, i + 1;
    if (text[i] == '\'') return in = In::literal, i + 1;
    return i + 1;
}

// One step inside a string or a comment (not at a newline): the index past what it consumed.
std::size_t inside(std::string_view text, std::size_t i, In& in) {
    char c = text[i];
    switch (in) {
        case In::basic:
            if (c == '\\') return i + 1 < text.size() && text[i + 1] != '\n' ? i + 2 : i + 1;
            if (c == '"') in = In::code;
            return i + 1;
        case In::literal:
            if (c == '\'') in = In::code;
            return i + 1;
        case In::multi_basic:
            if (c == '\\') return i + 1 < text.size() && text[i + 1] != '\n' ? i + 2 : i + 1;
            if (opens(text, i, "\"\"\"")) return in = In::code, past_close(text, i, '"');
            return i + 1;
        case In::multi_literal:
            if (opens(text, i, "'''")) return in = In::code, past_close(text, i, '\'');
            return i + 1;
        default:
            return i + 1;
    }
}

}  // namespace

void reject_bare_non_ascii(std::string_view text, std::string_view file) {
    In in = In::code;
    std::uint64_t line = 1;
    std::size_t line_start = 0;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '\n') {
            ++line;
            line_start = ++i;
            // A comment and a one-line string end with their line (an unclosed string is the parser's to say).
            if (in == In::comment || in == In::basic || in == In::literal) in = In::code;
            continue;
        }
        if (in != In::code) {
            i = inside(text, i, in);
            continue;
        }
        if (static_cast<unsigned char>(text[i]) >= 0x80) {
            Position where{.line = line, .column = column_of(text, line_start, i)};
            throw Error(Errc::usage, where,
                        shown_at(text, i) + " outside quotes: in " + std::string(file) +
                            " (TOML) text other than ASCII goes only in a string (name = \"...\") or after # "
                            "in a comment");
        }
        i = enter(text, i, in);
    }
}

}  // namespace tape
