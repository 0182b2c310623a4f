// Macro statements as the loader reads them: Fanuc Custom Macro B (IF, GOTO, WHILE/DO/END, the
// output statements, #n = value) and LinuxCNC o-words. Each statement is one; its problems one finding.
#include <array>
#include <utility>

#include "program/loader/loader.hpp"
#include "program/macro.hpp"

namespace tape {

using namespace loading;

namespace {
constexpr std::array<std::string_view, 15> o_keywords = {"SUB",    "ENDSUB", "CALL",      "RETURN", "IF",
                                                         "ELSEIF", "ELSE",   "ENDIF",     "WHILE",  "ENDWHILE",
                                                         "DO",     "REPEAT", "ENDREPEAT", "BREAK",  "CONTINUE"};
}  // namespace

void Loader::macro_problem(std::size_t i, std::string message) {
    find("macro-syntax", i, blk_.ordinal, std::move(message));
}

Statement& Loader::add_statement(Statement::Kind kind, std::size_t from, std::size_t to) {
    Statement& s = blk_.statements.emplace_back();
    s.kind = kind;
    s.text.assign(trim_right(text_.substr(from, to - from)));
    s.where = at(from);
    return s;
}

// The digits at i (blanks before them skipped), moving i past them; nullopt when none stand there.
std::optional<long long> Loader::number_after(std::size_t& i, std::size_t end) const {
    i = skip_blanks(i, end);
    std::size_t j = i;
    long long v = 0;
    while (j < end && is_digit(text_[j]) && j - i < 18) v = v * 10 + (text_[j++] - '0');
    if (j == i) return std::nullopt;
    i = j;
    return v;
}

// Fanuc Custom Macro B: IF [..] GOTO n | IF [..] THEN ..., GOTO n, WHILE [..] DO m, DO m, END m, and
// the output statements. Each statement is one; its problems are one finding.
std::size_t Loader::macro_statement(std::size_t i, std::size_t e, const std::string& keyword) {
    using K = Statement::Kind;
    MacroScan m{i, i + keyword.size(), statement_end(i, e)};
    if (keyword == "IF") {
        if (!if_statement(m)) return m.end;
    } else if (keyword == "GOTO") {
        goto_target(m, add_statement(K::go_to, i, m.end));
    } else if (keyword == "WHILE") {
        Statement& s = add_statement(K::while_do, i, m.end);
        if (!macro_condition(m, "WHILE")) return m.end;
        if (macro::name_at(text_, m.at) != "DO") {
            macro_problem(i, "WHILE [...] must be followed by DO m");
            return m.end;
        }
        m.at += 2;
        loop_number(m, s, "DO");
    } else if (keyword == "DO" || keyword == "END") {
        loop_number(m, add_statement(keyword == "DO" ? K::loop_do : K::loop_end, i, m.end), keyword.c_str());
    } else {  // POPEN PCLOS DPRNT BPRNT
        add_statement(K::output, i, m.end);
        std::size_t k = skip_blanks(m.at, m.end);
        if ((keyword == "DPRNT" || keyword == "BPRNT") &&
            (k >= m.end || text_[k] != '[' || macro::group_length(text_.substr(0, m.end), k) == std::string_view::npos))
            macro_problem(i, keyword + " needs its output in [ ]");
        return m.end;
    }
    if (std::size_t rest = skip_blanks(m.at, m.end); rest < m.end)
        macro_problem(rest, "'" + std::string(trim_right(text_.substr(rest, m.end - rest))) + "' after " + keyword +
                                " has no meaning");
    return m.end;
}

// IF [..] GOTO n, or IF [..] THEN #n = value (the assignment is part of the IF). False when nothing
// after the statement is to be looked at.
bool Loader::if_statement(MacroScan& m) {
    using K = Statement::Kind;
    Statement& s = add_statement(K::if_goto, m.start, m.end);
    if (!macro_condition(m, "IF")) return false;
    std::string next = macro::name_at(text_, m.at);
    if (next == "GOTO") {
        m.at += 4;
        goto_target(m, s);
        return true;
    }
    if (next != "THEN") {
        macro_problem(m.start, "IF [...] must be followed by GOTO n or THEN");
        return false;
    }
    s.kind = K::if_then;
    m.at = skip_blanks(m.at + 4, m.end);
    if (m.at >= m.end || text_[m.at] != '#') {
        macro_problem(m.at, "IF [...] THEN needs an assignment after THEN");
        return false;
    }
    std::size_t statements = blk_.statements.size();
    assignment(m.at, m.end);
    blk_.statements.resize(statements);
    return false;
}

// The condition in [ ] after IF or WHILE, checked; m.at moves past it. False when it is missing or wrong.
bool Loader::macro_condition(MacroScan& m, const char* what) {
    std::size_t k = skip_blanks(m.at, m.end);
    if (k >= m.end || text_[k] != '[') {
        macro_problem(m.start, std::string(what) + " needs its condition in [ ]");
        return false;
    }
    std::size_t n = macro::group_length(text_.substr(0, m.end), k);
    if (n == std::string_view::npos) {
        macro_problem(k, "'[' is not closed with ']'");
        return false;
    }
    if (auto problem = macro::check_expression(text_.substr(k, n), false)) {
        macro_problem(k, std::string(what) + " [" + std::string(text_.substr(k + 1, n - 2)) + "]: " + *problem);
        return false;
    }
    m.at = skip_blanks(k + n, m.end);
    return true;
}

// DO m / END m: the loop number, 1 to 3.
void Loader::loop_number(MacroScan& m, Statement& s, const char* what) {
    s.number = number_after(m.at, m.end);
    if (!s.number || *s.number < 1 || *s.number > 3)
        macro_problem(m.start, std::string(what) + " needs a loop number 1, 2 or 3");
}

// GOTO's target: a block number, or a macro value computed when the program runs.
void Loader::goto_target(MacroScan& m, Statement& s) {
    std::size_t before = m.at;
    s.number = number_after(m.at, m.end);
    if (s.number) return;
    std::size_t n = macro::value_length(text_.substr(0, m.end), m.at, false);
    if (n == 0) macro_problem(before, "GOTO needs the number of the block to go to");
    m.at += n;
}

// "#100 = expression": Fanuc takes the rest of the block; LinuxCNC one value, then more of the block.
std::size_t Loader::assignment(std::size_t i, std::size_t e) {
    std::size_t end = statement_end(i, e);
    std::size_t n = macro::reference_length(text_.substr(0, end), i, linuxcnc_);
    std::size_t eq = skip_blanks(i + (n ? n : 1), end);
    if (n == 0 || eq >= end || text_[eq] != '=') {
        Statement& s = add_statement(Statement::Kind::assignment, i, end);
        macro_problem(i, "'" + s.text + "': a variable is given a value with '#n = value'");
        return end;
    }
    if (auto problem = macro::check_expression(text_.substr(i, n), linuxcnc_)) macro_problem(i, *problem);
    std::size_t value = skip_blanks(eq + 1, end), value_end = end;
    if (linuxcnc_) {
        std::size_t len = macro::value_length(text_.substr(0, end), value, true);
        value_end = len ? value + len : value;
    }
    add_statement(Statement::Kind::assignment, i, value_end);
    std::string_view rhs = trim_right(text_.substr(value, value_end - value));
    if (rhs.empty())
        macro_problem(i, "the assignment to " + std::string(text_.substr(i, n)) + " has no value");
    else if (auto problem = macro::check_expression(rhs, linuxcnc_))
        macro_problem(value, "the value of " + std::string(text_.substr(i, n)) + ": " + *problem);
    return value_end;
}

// LinuxCNC o-words: "o100 sub", "o<probe> call [1] [2]", "o101 if [#1 GT 0]", ...
std::size_t Loader::o_word(std::size_t i, std::size_t e) {
    std::size_t end = statement_end(i, e), k = i + 1;
    Statement& s = add_statement(Statement::Kind::o_word, i, end);
    if (text_[k] == '<') {
        auto close = text_.find('>', k);
        if (close == std::string_view::npos || close >= end) {
            macro_problem(i, "the o-word name '<' is not closed with '>'");
            return end;
        }
        k = close + 1;
    } else {
        while (k < end && is_digit(text_[k])) ++k;
    }
    s.label.clear();
    for (char c : text_.substr(i + 1, k - i - 1)) s.label += is_upper(c) ? static_cast<char>(c - 'A' + 'a') : c;
    k = skip_blanks(k, end);
    std::string keyword = macro::name_at(text_, k);
    if (!listed(keyword, o_keywords)) {
        macro_problem(k, keyword.empty() ? "the o-word " + s.text + " has no keyword (sub, call, if, while, ...)"
                                         : "'" + keyword + "' is no o-word keyword");
        return end;
    }
    for (char c : keyword) s.keyword += static_cast<char>(c - 'A' + 'a');
    k = skip_blanks(k + keyword.size(), end);
    bool needs_condition = keyword == "IF" || keyword == "ELSEIF" || keyword == "WHILE" || keyword == "REPEAT";
    if (needs_condition && (k >= end || text_[k] != '['))
        macro_problem(i, "o" + s.label + " " + s.keyword + " needs its condition in [ ]");
    while (k < end) {  // arguments and conditions: [ ] groups
        if (text_[k] != '[') {
            macro_problem(k, "'" + std::string(trim_right(text_.substr(k, end - k))) + "' after o" + s.label + " " +
                                 s.keyword + " has no meaning");
            break;
        }
        std::size_t n = macro::group_length(text_.substr(0, end), k);
        if (n == std::string_view::npos) {
            macro_problem(k, "'[' is not closed with ']'");
            break;
        }
        if (auto problem = macro::check_expression(text_.substr(k, n), true)) {
            macro_problem(k, *problem);
            break;
        }
        k = skip_blanks(k + n, end);
    }
    return end;
}

}  // namespace tape
