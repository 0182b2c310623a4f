// The dialect table and the choice of a dialect from a program's text.
#include "tape/dialect.hpp"

#include <array>
#include <cctype>
#include <cstdint>
#include <initializer_list>
#include <utility>

namespace tape {
namespace {

// Columns: needs_percent lowercase semicolon_ends_block semicolon_comment macro_b o_words
// o_program_number main_blocks skip_levels closing_percent ordered_words increasing_numbers corner_words.
constexpr std::array<DialectRules, 3> table = {{
    {Dialect::gost, true, false, false, false, false, false, false, true, false, false, true, true, false,
     "2 30 102 130", "ГОСТ 20999-83 (ISO 6983)"},
    {Dialect::fanuc, false, false, true, false, true, false, true, false, true, true, false, false, true, "2 30 99",
     "Fanuc Series 0i/16i/18i/21i/30i operator's manual: program format, Custom Macro B"},
    {Dialect::linuxcnc, false, true, false, true, false, true, false, false, false, true, false, false, false, "2 30",
     "LinuxCNC G-code reference (RS274NGC): overview, O codes, parameters"},
}};

bool starts_word(std::string_view s, std::size_t i, std::string_view word) {
    if (s.size() - i < word.size()) return false;
    for (std::size_t k = 0; k < word.size(); ++k)
        if (std::toupper(static_cast<unsigned char>(s[i + k])) != word[k]) return false;
    return true;
}

// Evidence found in one line outside comments.
struct Evidence {
    std::uint64_t o_numbers = 0, macro = 0, lowercase = 0, o_words = 0, named = 0, semicolon_comment = 0,
                  semicolon_end = 0, main_blocks = 0, percent_number = 0, percent_lines = 0, lines = 0,
                  linuxcnc_codes = 0, fanuc_codes = 0, names_linuxcnc = 0, names_fanuc = 0;
};

bool mentions(std::string_view line, std::string_view name) {
    for (std::size_t i = 0; i + name.size() <= line.size(); ++i)
        if (starts_word(line, i, name)) return true;
    return false;
}

void scan_line(std::string_view line, Evidence& e) {
    std::size_t i = line.find_first_not_of(" \t\r");
    if (i == std::string_view::npos) return;
    ++e.lines;
    // CAM posts name their controller in the header: "(POST LINUXCNC.CPS ...)", "(FANUC 0I-MF)".
    e.names_linuxcnc += mentions(line, "LINUXCNC");
    e.names_fanuc += mentions(line, "FANUC");
    if (line[i] == '%') {
        ++e.percent_lines;
        std::size_t j = line.find_first_not_of(" \t\r%", i);
        if (j != std::string_view::npos && std::isdigit(static_cast<unsigned char>(line[j]))) ++e.percent_number;
        return;
    }
    if (line[i] == '/') i = line.find_first_not_of(" \t\r/0123456789", i);
    if (i == std::string_view::npos) return;
    if (line[i] == ':') ++e.main_blocks;
    if (line[i] == 'O' && i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1]))) ++e.o_numbers;
    int depth = 0;
    bool lower = false;
    for (std::size_t k = i; k < line.size(); ++k) {
        char c = line[k];
        if (c == '(') ++depth;
        if (c == ')' && depth) --depth;
        if (depth || c == '(' || c == ')') continue;
        if (c == ';') {
            if (line.find_first_not_of(" \t\r", k + 1) == std::string_view::npos)
                ++e.semicolon_end;
            else
                ++e.semicolon_comment;
            break;
        }
        if (c == '#' && k + 1 < line.size() && line[k + 1] == '<') ++e.named;
        if ((c == 'o' || c == 'O') && k + 1 < line.size() && line[k + 1] == '<') ++e.o_words;
        if (c == 'o' && (k == i || line[k - 1] == ' ') && k + 1 < line.size() &&
            std::isdigit(static_cast<unsigned char>(line[k + 1])))
            ++e.o_words;
        lower |= c >= 'a' && c <= 'z';
        // Codes only one family has: LinuxCNC's G64 P, G91.1, G33.1, G38.n; Fanuc's M98 subprogram call.
        if (starts_word(line, k, "G91.1") || starts_word(line, k, "G90.1") || starts_word(line, k, "G33.1") ||
            starts_word(line, k, "G38.") || starts_word(line, k, "G64 P") || starts_word(line, k, "G64P"))
            ++e.linuxcnc_codes;
        if (starts_word(line, k, "M98")) ++e.fanuc_codes;
        if (c == '[') ++e.macro;  // a [ ] expression: Custom Macro B (LinuxCNC's come with lowercase, o-words)
        if (starts_word(line, k, "WHILE") || starts_word(line, k, "GOTO") || starts_word(line, k, "IF[") ||
            starts_word(line, k, "IF [") || starts_word(line, k, "G65") || starts_word(line, k, "M99") ||
            (c == '#' && k + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[k + 1]))))
            ++e.macro;
    }
    e.lowercase += lower;
}

// "3 O program number(s), 12 macro statement(s)": only the evidence that was found.
std::string evidence(std::initializer_list<std::pair<std::uint64_t, std::string_view>> items) {
    std::string out;
    for (const auto& [n, what] : items)
        if (n) out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + std::string(what);
    return out;
}

}  // namespace

std::string_view dialect_name(Dialect d) {
    switch (d) {
        case Dialect::gost:
            return "gost";
        case Dialect::fanuc:
            return "fanuc";
        case Dialect::linuxcnc:
            return "linuxcnc";
        case Dialect::automatic:
            return "auto";
    }
    return "?";
}

std::optional<Dialect> parse_dialect(std::string_view name) {
    for (Dialect d : {Dialect::gost, Dialect::fanuc, Dialect::linuxcnc, Dialect::automatic})
        if (dialect_name(d) == name) return d;
    return std::nullopt;
}

const DialectRules& dialect_rules(Dialect d) {
    for (const auto& row : table)
        if (row.dialect == d) return row;
    return table[0];
}

DialectChoice guess_dialect(std::string_view text) {
    Evidence e;
    for (std::size_t b = 0; b < text.size();) {
        auto nl = text.find('\n', b);
        std::size_t end = nl == std::string_view::npos ? text.size() : nl;
        scan_line(text.substr(b, end - b), e);
        b = end + 1;
    }
    std::uint64_t linuxcnc =
        e.lowercase + e.o_words * 4 + e.named * 4 + e.semicolon_comment + e.linuxcnc_codes * 2 + e.names_linuxcnc * 4;
    std::uint64_t fanuc = e.o_numbers * 4 + e.macro * 2 + e.semicolon_end + e.fanuc_codes * 2 + e.names_fanuc * 4;
    std::uint64_t gost = e.main_blocks * 4 + e.percent_number * 4;
    if (fanuc > linuxcnc && fanuc > gost)
        return {Dialect::fanuc, evidence({{e.o_numbers, "O program number(s)"},
                                          {e.macro, "macro statement(s), expression(s) or call(s)"},
                                          {e.semicolon_end, "';' end(s) of block"},
                                          {e.fanuc_codes, "M98 call(s)"},
                                          {e.names_fanuc, "line(s) naming Fanuc"}})};
    if (linuxcnc > gost && linuxcnc > 0)
        return {Dialect::linuxcnc, evidence({{e.lowercase, "line(s) with lowercase words"},
                                             {e.o_words, "o-word(s)"},
                                             {e.named, "named parameter(s)"},
                                             {e.semicolon_comment, "';' comment(s)"},
                                             {e.linuxcnc_codes, "LinuxCNC-only G code(s)"},
                                             {e.names_linuxcnc, "line(s) naming LinuxCNC"}})};
    if (gost > 0)
        return {Dialect::gost,
                evidence({{e.main_blocks, "':' main block(s)"}, {e.percent_number, "'%' with a program number"}})};
    if (e.percent_lines == 0 && e.lines > 0)
        return {Dialect::linuxcnc, "no '%' anywhere, so no ГОСТ tape program; nothing else decides"};
    return {Dialect::gost, "nothing in the text needs another dialect"};
}

}  // namespace tape
