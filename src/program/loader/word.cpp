// The loader's hot loop: one word, an address and its value (ГОСТ 20999-83 §3.1), or a macro value
// where the dialect has them.
#include <algorithm>
#include <array>
#include <cstring>

#include "program/loader/loader.hpp"
#include "program/macro.hpp"

namespace tape {

using namespace loading;

namespace {

// What a character can be inside a word, looked up once per character in the hot loop.
enum class CharClass : std::uint8_t { other, digit, point, sign, blank };
constexpr auto char_class = [] {
    std::array<CharClass, 256> t{};
    for (int c = '0'; c <= '9'; ++c) t[static_cast<std::size_t>(c)] = CharClass::digit;
    t['.'] = CharClass::point;
    t['+'] = t['-'] = CharClass::sign;
    t[' '] = t['\t'] = t['\r'] = t[0x11] = t[0x12] = t[0x13] = t[0x14] = CharClass::blank;
    return t;
}();

}  // namespace

// Address (or ':'), sign, digits and point, spaces allowed between; i at the address.
// Scans first, then copies whole runs: this is the loader's hot loop.
void Loader::word(std::size_t i, std::size_t e, std::size_t* next, std::uint64_t block_no, Word& w) {
    w.address = rules_->lowercase ? upper(text_[i]) : text_[i];
    locate(i, w.where);
    w.sign = 0;
    w.point = -1;
    w.macro = false;
    w.known = true;
    w.digit_count = -1;
    // A digit or point right after the letter is a plain number: most words, so macro_word is not asked.
    bool plain = i + 1 < e && (char_class[static_cast<unsigned char>(text_[i + 1])] == CharClass::digit ||
                               char_class[static_cast<unsigned char>(text_[i + 1])] == CharClass::point);
    if ((rules_->macro_b || rules_->o_words) && !plain && macro_word(i, e, next, w)) return;
    int points = 0, digits = 0;
    // Wraps past 18 digits, when digit_count says 19 and no one reads it.
    unsigned long long value = 0;
    std::size_t j = i + 1, end = j, first_blank = std::string_view::npos;
    const char* s = text_.data();
    for (; j < e; ++j) {
        unsigned digit = static_cast<unsigned char>(s[j]) - unsigned{'0'};
        if (digit < 10) {  // the common case first: one compare
            value = value * 10 + digit;
            ++digits;
            end = j + 1;
            continue;
        }
        CharClass k = char_class[static_cast<unsigned char>(s[j])];
        if (k == CharClass::point) {
            if (++points == 1) w.point = digits;
        } else if (k == CharClass::sign && !w.sign && digits == 0 && points == 0)
            w.sign = s[j];
        else if (k == CharClass::blank) {
            if (first_blank == std::string_view::npos) first_blank = j;
            continue;
        } else
            break;
        end = j + 1;
    }
    *next = j;
    w.digits_value = static_cast<long long>(value);
    w.digit_count = std::min(digits, 19);
    std::string_view span = text_.substr(i, end - i);
    if (first_blank >= end) {
        w.text.resize(span.size());  // within the reused capacity: no allocation, one copy
        std::memcpy(w.text.data(), span.data(), span.size());
    } else {
        w.text.clear();
        for (char c : span)
            if (!is_blank(c)) w.text += c;
    }
    if (is_lower(text_[i]) && !rules_->lowercase) return;  // flagged as a whole by the caller
    if (digits == 0) find("no-digits", i, block_no, "the word " + w.text + " has no digits (§3.1.1)");
    if (points > 1)
        find("two-points", i, block_no, "the word " + w.text + " has " + std::to_string(points) + " decimal points");
}

// A word whose value is a macro variable or expression ("X#1", "Z-[#2*2]", LinuxCNC's "F #<feed>"):
// kept as written, its expression checked. False when the value is a plain number.
bool Loader::macro_word(std::size_t i, std::size_t e, std::size_t* next, Word& w) {
    std::size_t v = skip_blanks(i + 1, e);
    if (v < e && (text_[v] == '+' || text_[v] == '-')) v = skip_blanks(v + 1, e);
    if (v >= e || !(text_[v] == '#' || text_[v] == '[' || (linuxcnc_ && is_letter(text_[v])))) return false;
    std::size_t n = macro::value_length(text_.substr(0, e), i + 1, linuxcnc_);
    if (!n) return false;
    w.macro = true;
    w.text.clear();
    for (char c : text_.substr(i, n + 1))
        if (!is_blank(c)) w.text += c;
    auto s = text_.substr(i + 1, n);
    auto sign = s.find_first_not_of(" \t\r");
    if (sign != std::string_view::npos && (s[sign] == '+' || s[sign] == '-')) w.sign = s[sign];
    if (auto problem =
            macro::check_expression(s.substr(sign == std::string_view::npos ? 0 : sign + (w.sign != 0)), linuxcnc_))
        macro_problem(i, "the value of " + w.text + ": " + *problem);
    *next = i + 1 + n;
    return true;
}

}  // namespace tape
