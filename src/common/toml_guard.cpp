// A scan of TOML's lexical states (comment, basic and literal strings, their multi-line forms) that
// finds the bytes above 0x7F standing outside all of them (toml_guard.hpp).
#include "common/toml_guard.hpp"

#include <cstdio>
#include <string>
#include <tuple>
#include <utility>

#include "tape/error.hpp"

namespace tape {
namespace {

enum class State { bare, comment, basic, literal, multi_basic, multi_literal };

bool starts(std::string_view t, std::size_t i, std::string_view what) { return t.substr(i, what.size()) == what; }

// The state after the opening of a string or comment at i, and how many bytes the opening takes.
std::pair<State, std::size_t> opening(std::string_view t, std::size_t i) {
    if (t[i] == '#') return {State::comment, 1};
    if (starts(t, i, "\"\"\"")) return {State::multi_basic, 3};
    if (starts(t, i, "'''")) return {State::multi_literal, 3};
    if (t[i] == '"') return {State::basic, 1};
    if (t[i] == '\'') return {State::literal, 1};
    return {State::bare, 1};
}

// How many bytes close the string or comment of state s at i, or 0 when it does not close there.
std::size_t closing(State s, std::string_view t, std::size_t i) {
    switch (s) {
        case State::comment: return t[i] == '\n' ? 1 : 0;
        case State::basic: return t[i] == '"' || t[i] == '\n' ? 1 : 0;
        case State::literal: return t[i] == '\'' || t[i] == '\n' ? 1 : 0;
        case State::multi_basic: return starts(t, i, "\"\"\"") ? 3 : 0;
        case State::multi_literal: return starts(t, i, "'''") ? 3 : 0;
        default: return 0;
    }
}

}  // namespace

void reject_bare_non_ascii(std::string_view text, std::string_view file) {
    State s = State::bare;
    std::size_t line = 1;
    for (std::size_t i = 0; i < text.size();) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        std::size_t step = 1;
        if (s == State::bare) {
            if (c > 0x7F) {
                char hex[8];
                std::snprintf(hex, sizeof hex, "0x%02X", c);
                throw Error(Errc::usage, Position{.line = line},
                            std::string(file) + ": line " + std::to_string(line) + ": byte " + hex +
                                " outside a string or comment (TOML allows letters other than ASCII only in quotes)");
            }
            std::tie(s, step) = opening(text, i);
        } else if ((s == State::basic || s == State::multi_basic) && c == '\\' && i + 1 < text.size() &&
                   text[i + 1] != '\n') {
            step = 2;  // an escaped quote does not close the string
        } else if (std::size_t n = closing(s, text, i)) {
            s = State::bare;
            step = n;
        }
        for (std::size_t k = i; k < i + step && k < text.size(); ++k) line += text[k] == '\n';
        i += step;
    }
}

}  // namespace tape
