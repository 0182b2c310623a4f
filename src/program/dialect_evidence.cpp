// The clues of a program's text, line by line, outside comments (tape/dialect.hpp's guess_dialect).
#include "program/dialect_evidence.hpp"

#include <algorithm>
#include <initializer_list>
#include <string>

#include "program/chars.hpp"

namespace tape::detection {
namespace {

using chars::is_blank, chars::is_digit, chars::is_letter, chars::is_lower, chars::is_upper, chars::upper;

constexpr std::array<ClueInfo, clue_count> clues = {{
    {Side::fanuc, 4, "O program number(s)"},
    {Side::fanuc, 2, "macro statement(s), expression(s) or variable(s)"},
    {Side::fanuc, 1, "';' end(s) of block"},
    {Side::fanuc, 2, "M98/M97 subprogram call(s)"},
    {Side::fanuc, 2, "',C'/',R' corner word(s)"},
    {Side::fanuc, 4, "line(s) naming Fanuc or Haas"},
    {Side::linuxcnc, 1, "line(s) with lowercase words"},
    {Side::linuxcnc, 4, "o-word(s)"},
    {Side::linuxcnc, 4, "named parameter(s)"},
    {Side::linuxcnc, 1, "';' comment(s)"},
    {Side::linuxcnc, 2, "LinuxCNC-only G code(s)"},
    {Side::linuxcnc, 2, "polar word(s) (^, @)"},
    {Side::linuxcnc, 2, "(debug,) (msg,) (print,) comment(s)"},
    {Side::linuxcnc, 2, "GRBL console line(s) ($, ?)"},
    {Side::linuxcnc, 4, "line(s) naming LinuxCNC"},
    {Side::gost, 4, "':' main block(s)"},
    {Side::gost, 4, "'%' with a program number"},
    {Side::gost, 1, "line(s) with '+' signed dimensions"},
    {Side::foreign, 4, "assignment(s) to a letter or name (NAME=, R1=, N1=)"},
    {Side::foreign, 4, "program header(s) of another control (%PM, %MPF, %_N_, $NAME%)"},
    {Side::foreign, 4, "statement(s) of another control (DEF, CALL, RTS, GOTOF, MSG(, N labels)"},
    {Side::foreign, 4, "parameter word(s) P<n>.<value> (P123.22.5)"},
}};

bool starts_word(std::string_view s, std::size_t i, std::string_view word) {
    if (s.size() - i < word.size()) return false;
    for (std::size_t k = 0; k < word.size(); ++k)
        if (upper(s[i + k]) != word[k]) return false;
    return true;
}

// word at i, upper case as written, with no letter or digit right before it.
bool word_at(std::string_view s, std::size_t i, std::string_view word) {
    if (i > 0 && (is_letter(s[i - 1]) || is_digit(s[i - 1]) || s[i - 1] == '.')) return false;
    return s.compare(i, word.size(), word) == 0;
}

// The controls a line names (CAM posts name theirs in the header), in one pass over it: every line of
// the sample is asked.
struct Named {
    bool linuxcnc = false, fanuc = false;
};
Named names_in(std::string_view line) {
    Named n;
    for (std::size_t i = 0; i < line.size(); ++i) switch (upper(line[i])) {
            case 'L':
                n.linuxcnc |= starts_word(line, i, "LINUXCNC");
                break;
            case 'F':
                n.fanuc |= starts_word(line, i, "FANUC");
                break;
            case 'H':
                n.fanuc |= starts_word(line, i, "HAAS");
                break;
            default:
                break;
        }
    return n;
}

std::size_t skip(std::string_view s, std::size_t i) {
    while (i < s.size() && is_blank(s[i])) ++i;
    return i;
}

bool o_keyword_at(std::string_view s, std::size_t i) {
    for (std::string_view k : {"SUB", "ENDSUB", "CALL", "RETURN", "IF", "ELSEIF", "ELSE", "ENDIF", "WHILE", "ENDWHILE",
                               "DO", "REPEAT", "ENDREPEAT", "BREAK", "CONTINUE"})
        if (starts_word(s, i, k) && (i + k.size() == s.size() || !is_letter(s[i + k.size()]))) return true;
    return false;
}

// An o-word at i ('o' or 'O'): o<name>, or digits and a keyword ("O100 if"); Fanuc's O1234 is none.
bool o_word_at(std::string_view s, std::size_t i) {
    if (i + 1 >= s.size() || (s[i] != 'o' && s[i] != 'O')) return false;
    if (s[i + 1] == '<') return true;
    std::size_t k = i + 1;
    while (k < s.size() && is_digit(s[k])) ++k;
    if (k == i + 1) return false;
    if (s[i] == 'o') return true;
    return o_keyword_at(s, skip(s, k));
}

// What stands before an '=' at eq: a letter address or name being given a value (foreign), as
// opposed to Fanuc's #100= or LinuxCNC's #<name> =.
bool assigns_to_name(std::string_view s, std::size_t eq) {
    std::size_t k = eq;
    while (k > 0 && is_blank(s[k - 1])) --k;
    if (k > 0 && s[k - 1] == ']') {  // Okuma's VGRIN[1]=: the name before the index
        int depth = 0;
        while (k > 0) {
            char c = s[--k];
            if (c == ']') ++depth;
            if (c == '[' && --depth == 0) break;
        }
    }
    std::size_t end = k;
    while (k > 0 && (is_letter(s[k - 1]) || is_digit(s[k - 1]) || s[k - 1] == '_')) --k;
    if (k == end || !is_letter(s[k])) return false;
    return k == 0 || (s[k - 1] != '#' && s[k - 1] != '<');
}

// H&K's parameter words: P, digits, a point, then digits and a second point, or a sign.
bool parameter_word_at(std::string_view s, std::size_t i) {
    if (s[i] != 'P' || (i > 0 && is_letter(s[i - 1]))) return false;
    std::size_t k = i + 1;
    while (k < s.size() && is_digit(s[k])) ++k;
    if (k == i + 1 || k >= s.size() || s[k] != '.') return false;
    ++k;
    if (k < s.size() && (s[k] == '-' || s[k] == '+')) return true;
    while (k < s.size() && is_digit(s[k])) ++k;
    return k < s.size() && s[k] == '.';
}

// A statement of a control no dialect here reads, at the line's start.
bool foreign_statement(std::string_view s, std::size_t i) {
    for (std::string_view k : {"DEF ", "CALL ", "RTS", "GOTOF", "GOTOB", "PROC ", "MSG("})
        if (s.compare(i, k.size(), k) == 0) return true;
    // Okuma's named labels before a block's words (NM59 M59, NHME G30 P8), and GOTO to them.
    if (s[i] == 'N' && i + 1 < s.size() && is_upper(s[i + 1])) {
        std::size_t k = i + 1;
        while (k < s.size() && (is_upper(s[k]) || is_digit(s[k]))) ++k;
        std::size_t w = skip(s, k);
        if (w > k && w + 1 < s.size() && is_upper(s[w]) && (is_digit(s[w + 1]) || s[w + 1] == '=')) return true;
    }
    return s.compare(i, 6, "GOTO N") == 0 && i + 6 < s.size() && is_upper(s[i + 6]);
}

// Fanuc's ",C1." chamfer or ",R2." corner after the ',' at i, blanks allowed between (", R 15.").
bool corner_word_at(std::string_view s, std::size_t i) {
    std::size_t k = skip(s, i + 1);
    if (k >= s.size() || (s[k] != 'C' && s[k] != 'R')) return false;
    k = skip(s, k + 1);
    return k < s.size() && (is_digit(s[k]) || s[k] == '.');
}

// M2, M02, M30 or M99 (any case) at i: a program's end.
bool end_code_at(std::string_view s, std::size_t i) {
    if (upper(s[i]) != 'M' || (i > 0 && (is_letter(s[i - 1]) || is_digit(s[i - 1])))) return false;
    std::size_t k = skip(s, i + 1), digits = k;
    while (digits < s.size() && is_digit(s[digits])) ++digits;
    if (digits == k || digits - k > 3 || (digits < s.size() && s[digits] == '.')) return false;
    int code = std::stoi(std::string(s.substr(k, digits - k)));
    return code == 2 || code == 30 || code == 99;
}

constexpr std::string_view linuxcnc_codes[] = {"G64 P", "G64P",  "G90.1", "G91.1", "G33.1", "G38.",
                                               "G43.2", "G59.1", "G59.2", "G59.3", "G5.2",  "G5.3"};

}  // namespace

const ClueInfo& clue_info(Clue c) { return clues[static_cast<std::size_t>(c)]; }

void Evidence::add(Clue c, std::uint64_t number, std::uint64_t n) {
    auto k = static_cast<std::size_t>(c);
    auto& count = in_leader_ ? leader_count_ : count_;
    auto& first = in_leader_ ? leader_first_line_ : first_line_;
    if (!count[k]) first[k] = number;
    count[k] += n;
}

void Evidence::scan(std::string_view text) {
    std::uint64_t number = 0;
    for (std::size_t b = 0; b < text.size();) {
        auto nl = text.find('\n', b);
        std::size_t end = nl == std::string_view::npos ? text.size() : nl;
        line(text.substr(b, end - b), ++number);
        b = end + 1;
    }
    if (in_leader_) leader_ends(false);
}

// The text before the first '%' ends: its clues count when it is the program (no '%' came, or it ended
// a program the '%' closes); as label they are dropped, and the text starts with its '%'.
void Evidence::leader_ends(bool percent) {
    in_leader_ = false;
    if (percent && !leader_ends_program_) {
        starts_with_percent_ = true;
        return;
    }
    starts_with_percent_ = false;
    for (std::size_t k = 0; k < clue_count; ++k)
        if (leader_count_[k]) {
            first_line_[k] = count_[k] ? std::min(first_line_[k], leader_first_line_[k]) : leader_first_line_[k];
            count_[k] += leader_count_[k];
        }
}

void Evidence::line(std::string_view s, std::uint64_t number) {
    std::size_t i = skip(s, 0);
    if (i >= s.size()) return;
    if (in_leader_ && s[i] == '%') leader_ends(true);
    // CAM posts name their controller in the header: "(POST LINUXCNC.CPS ...)", "(FANUC 0I-MF)".
    Named named = names_in(s);
    if (named.linuxcnc) add(Clue::names_linuxcnc, number);
    if (named.fanuc) add(Clue::names_fanuc, number);
    if (s[i] == '%') {
        std::size_t j = skip(s, std::min(s.find_first_not_of('%', i), s.size()));
        if (j < s.size() && s[j] == 'O' && j + 1 < s.size() && is_digit(s[j + 1]))
            add(Clue::o_number, number);
        else if (j < s.size() && is_digit(s[j]))
            add(Clue::percent_number, number);
        else if (j < s.size() && (is_letter(s[j]) || s[j] == '_'))
            add(Clue::header, number);
        return;
    }
    std::string_view trimmed = s.substr(0, s.find_last_not_of(" \t\r") + 1);
    if (s[i] == '$') {  // Okuma's "$NAME.MIN%" file header, or a GRBL console line ("$I", "$$")
        add(trimmed.back() == '%' ? Clue::header : Clue::console_command, number);
        return;
    }
    if (trimmed.size() == i + 1 && (s[i] == '?' || s[i] == '~' || s[i] == '!')) {  // GRBL's real-time commands
        add(Clue::console_command, number);
        return;
    }
    if (s[i] == '/') i = skip(s, std::min(s.find_first_not_of("/0123456789", i), s.size()));
    if (i >= s.size()) return;
    if (s[i] == ':' && i + 1 < s.size() && is_digit(s[i + 1])) {
        std::size_t k = skip(s, std::min(s.find_first_not_of("0123456789", i + 1), s.size()));
        add(k >= s.size() || s[k] == '(' || s[k] == ';' ? Clue::o_number : Clue::main_block, number);
    }
    if (s[i] == 'O' && i + 1 < s.size() && is_digit(s[i + 1]) && !o_word_at(s, i)) add(Clue::o_number, number);
    if (foreign_statement(s, i)) add(Clue::keyword_line, number);
    words(s, i, number);
}

// The words of a line: the clues that stand among them, outside comments.
void Evidence::words(std::string_view s, std::size_t i, std::uint64_t number) {
    bool o_word_line = o_word_at(s, i);  // its [ ] are LinuxCNC's arguments and conditions
    bool lower = false, signed_dimension = false, assignment = false;
    int depth = 0;
    for (std::size_t k = i; k < s.size(); ++k) {
        char c = s[k];
        if (c == '(') {
            for (std::string_view command : {"DEBUG,", "MSG,", "PRINT,", "ABORT,", "LOG,", "LOGOPEN,", "PROBEOPEN "})
                if (depth == 0 && starts_word(s, k + 1, command)) add(Clue::comment_command, number);
            ++depth;
        }
        if (c == ')' && depth) --depth;
        if (depth || c == '(' || c == ')') continue;
        if (c == ';') {
            add(skip(s, k + 1) >= s.size() ? Clue::semicolon_end : Clue::semicolon_comment, number);
            break;
        }
        if (c == '#' && k + 1 < s.size() && s[k + 1] == '<') add(Clue::named_parameter, number);
        if ((c == 'o' || c == 'O') && (k == i || is_blank(s[k - 1])) && o_word_at(s, k)) add(Clue::o_word, number);
        lower |= is_lower(c);
        if (c == 'G')  // each code's first letter
            for (std::string_view code : linuxcnc_codes)
                if (word_at(s, k, code)) add(Clue::linuxcnc_code, number);
        if (c == 'M' && (word_at(s, k, "M98") || word_at(s, k, "M97"))) add(Clue::subprogram_call, number);
        if (c == ',' && corner_word_at(s, k)) add(Clue::corner_word, number);
        if ((c == '^' || c == '@') && k + 1 < s.size() && (is_digit(s[k + 1]) || s[k + 1] == '.' || s[k + 1] == '-'))
            add(Clue::polar_word, number);
        if (!o_word_line &&
            (c == '[' || (c == 'W' && word_at(s, k, "WHILE")) || (c == 'G' && word_at(s, k, "GOTO")) ||
             (c == 'I' && word_at(s, k, "IF")) || (c == 'G' && word_at(s, k, "G65")) ||
             (c == 'M' && word_at(s, k, "M99")) || (c == '#' && k + 1 < s.size() && is_digit(s[k + 1]))))
            add(Clue::macro, number);
        if (c == '+' && k > i &&
            std::string_view("XYZUVWIJKABC").find(upper(s[s.find_last_not_of(" \t", k - 1)])) != std::string_view::npos)
            signed_dimension = true;
        if (c == '=' && assigns_to_name(s, k)) assignment = true;
        if (parameter_word_at(s, k)) add(Clue::parameter_word, number);
        if (in_leader_ && end_code_at(s, k)) leader_ends_program_ = true;
    }
    if (lower) add(Clue::lowercase, number);
    if (signed_dimension) add(Clue::signed_dimension, number);
    if (assignment) add(Clue::assignment, number);
}

std::uint64_t Evidence::support(Dialect d) const {
    Side side = d == Dialect::fanuc ? Side::fanuc : d == Dialect::linuxcnc ? Side::linuxcnc : Side::gost;
    std::uint64_t sum = 0;
    for (std::size_t k = 0; k < clue_count; ++k)
        if (clues[k].side == side) sum += clues[k].weight * count_[k];
    return sum;
}

std::uint64_t Evidence::foreign() const {
    std::uint64_t sum = 0;
    for (std::size_t k = 0; k < clue_count; ++k)
        if (clues[k].side == Side::foreign) sum += count_[k];
    return sum;
}

std::string Evidence::describe(Side side) const {
    std::string out;
    for (std::size_t k = 0; k < clue_count; ++k)
        if (clues[k].side == side && count_[k])
            out += (out.empty() ? "" : ", ") + std::to_string(count_[k]) + " " + std::string(clues[k].what) +
                   " (line " + std::to_string(first_line_[k]) + ")";
    return out;
}

}  // namespace tape::detection
