#include "macro.hpp"

#include <algorithm>
#include <array>

#include "chars.hpp"

namespace tape::macro {
namespace {

constexpr std::array<std::string_view, 16> fanuc_functions = {"SIN",  "COS", "TAN", "ASIN", "ACOS",  "ATAN",
                                                              "SQRT", "ABS", "BIN", "BCD",  "ROUND", "FIX",
                                                              "FUP",  "LN",  "EXP", "ADP"};
constexpr std::array<std::string_view, 14> linuxcnc_functions = {
    "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX", "FUP", "LN", "EXP", "EXISTS"};
constexpr std::array<std::string_view, 10> operators = {"EQ", "NE", "GT", "GE", "LT", "LE", "AND", "OR", "XOR", "MOD"};

using chars::is_blank, chars::is_digit, chars::is_letter;

bool is_function(std::string_view name, bool linuxcnc) {
    if (linuxcnc)
        return std::find(linuxcnc_functions.begin(), linuxcnc_functions.end(), name) != linuxcnc_functions.end();
    return std::find(fanuc_functions.begin(), fanuc_functions.end(), name) != fanuc_functions.end();
}
bool is_operator(std::string_view name) {
    return std::find(operators.begin(), operators.end(), name) != operators.end();
}

std::size_t skip_blanks(std::string_view s, std::size_t i) {
    while (i < s.size() && is_blank(s[i])) ++i;
    return i;
}

}  // namespace

std::string name_at(std::string_view s, std::size_t i) {
    std::string name;
    for (; i < s.size() && is_letter(s[i]); ++i) name += chars::upper(s[i]);
    return name;
}

std::size_t group_length(std::string_view s, std::size_t i) {
    int depth = 0;
    for (std::size_t k = i; k < s.size(); ++k) {
        if (s[k] == '[') ++depth;
        if (s[k] == ']' && --depth == 0) return k + 1 - i;
    }
    return std::string_view::npos;
}

std::size_t reference_length(std::string_view s, std::size_t i, bool named) {
    if (i >= s.size() || s[i] != '#') return 0;
    std::size_t j = skip_blanks(s, i + 1);
    if (j < s.size() && s[j] == '[') {
        std::size_t n = group_length(s, j);
        return n == std::string_view::npos ? s.size() - i : j + n - i;
    }
    if (named && j < s.size() && s[j] == '<') {
        auto close = s.find('>', j);
        return close == std::string_view::npos ? 0 : close + 1 - i;
    }
    std::size_t k = j;
    while (k < s.size() && is_digit(s[k])) ++k;
    return k == j ? 0 : k - i;
}

std::size_t value_length(std::string_view s, std::size_t i, bool linuxcnc) {
    std::size_t j = skip_blanks(s, i);
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) j = skip_blanks(s, j + 1);
    if (j >= s.size()) return 0;
    if (s[j] == '#') {
        std::size_t n = reference_length(s, j, linuxcnc);
        return n ? j + n - i : 0;
    }
    if (s[j] == '[') {
        std::size_t n = group_length(s, j);
        return n == std::string_view::npos ? s.size() - i : j + n - i;
    }
    if (linuxcnc && is_letter(s[j])) {
        std::string name = name_at(s, j);
        std::size_t k = skip_blanks(s, j + name.size());
        if (!is_function(name, true) || k >= s.size() || s[k] != '[') return 0;
        std::size_t n = group_length(s, k);
        return n == std::string_view::npos ? s.size() - i : k + n - i;
    }
    std::size_t k = j;
    while (k < s.size() && (is_digit(s[k]) || s[k] == '.')) ++k;
    return k == j ? 0 : k - i;
}

std::optional<std::string> check_expression(std::string_view e, bool linuxcnc) {
    int depth = 0;
    for (std::size_t i = 0; i < e.size();) {
        char c = e[i];
        if (is_blank(c)) {
            ++i;
            continue;
        }
        if (c == '[') {
            ++depth;
            ++i;
        } else if (c == ']') {
            if (--depth < 0) return "']' closes no '['";
            ++i;
        } else if (is_digit(c) || c == '.') {
            while (i < e.size() && (is_digit(e[i]) || e[i] == '.')) ++i;
        } else if (c == '#') {
            std::size_t n = reference_length(e, i, linuxcnc);
            if (n == 0) return "'#' is not followed by a variable number";
            if (e[skip_blanks(e, i + 1)] == '[')
                if (auto inner = check_expression(e.substr(i + 1, n - 1), linuxcnc)) return inner;
            i += n;
        } else if (is_letter(c)) {
            std::string name = name_at(e, i);
            std::size_t after = skip_blanks(e, i + name.size());
            if (is_function(name, linuxcnc)) {
                if (after >= e.size() || e[after] != '[') return "the function " + name + " is not followed by '['";
            } else if (is_operator(name)) {
            } else {
                return "'" + std::string(e.substr(i, name.size())) + "' is no function or operator";
            }
            i += name.size();
        } else if (c == '+' || c == '-' || c == '*' || c == '/' || c == ',') {
            if (c == '*' && i + 1 < e.size() && e[i + 1] == '*') ++i;
            ++i;
        } else {
            return "'" + std::string(1, c) + "' has no place in an expression";
        }
    }
    if (depth > 0) return "'[' is not closed with ']'";
    return std::nullopt;
}

}  // namespace tape::macro
