// ГОСТ 20999-83 §9: after a dimension word's address two digits give the digits before and after
// the implied point, three digits when zeros may be left out (first 0: leading, last 0: trailing);
// '+' when the value is signed; after a dimensionless address one digit gives the number of digits,
// two digits starting with 0 when leading zeros may be left out; DS: explicit point accepted.
#include "tape/format_spec.hpp"

#include <algorithm>
#include <cctype>

#include "tape/error.hpp"

namespace tape {
namespace {

constexpr std::string_view dimension_addresses = "XYZUVWPQRABCIJK";
constexpr std::string_view feed_addresses = "FE";

bool is_dimension_address(char a) { return dimension_addresses.find(a) != std::string_view::npos; }

[[noreturn]] void spec_error(std::string_view spec, const std::string& why) {
    throw Error(Errc::usage, "format specification '" + std::string(spec) + "': " + why);
}

WordFormat word_format(char address, bool sign, const std::string& d, std::string_view spec) {
    WordFormat f;
    f.address = address;
    f.sign = sign;
    f.text = std::string(1, address) + (sign ? "+" : "") + d;
    auto digit = [&](std::size_t i) { return d[i] - '0'; };
    bool feed = feed_addresses.find(address) != std::string_view::npos;
    bool dimension_style =
        is_dimension_address(address) || sign || (feed && (d.size() == 3 || (d.size() == 2 && d[0] != '0')));
    if (dimension_style) {
        f.dimension = true;
        if (d.size() == 2) {
            f.before = digit(0);
            f.after = digit(1);
        } else if (d.size() == 3 && d[0] == '0') {
            f.omit_leading = true;
            f.before = digit(1);
            f.after = digit(2);
        } else if (d.size() == 3 && d[2] == '0') {
            f.omit_trailing = true;
            f.before = digit(0);
            f.after = digit(1);
        } else {
            spec_error(spec, f.text +
                                 ": a dimension word takes two digits (before and after the point), or three "
                                 "with a leading 0 (leading zeros omitted) or a trailing 0 (trailing zeros omitted)");
        }
        if (f.before + f.after == 0) spec_error(spec, f.text + " allows no digits");
    } else {
        if (d.size() == 1) {
            f.before = digit(0);
        } else if (d.size() == 2 && d[0] == '0') {
            f.omit_leading = true;
            f.before = digit(1);
        } else {
            spec_error(spec, f.text +
                                 ": a dimensionless word takes one digit (the number of digits), or two starting "
                                 "with 0 (leading zeros omitted)");
        }
        if (f.before == 0) spec_error(spec, f.text + " allows no digits");
    }
    return f;
}

std::string strip_leading_zeros(std::string s) {
    s.erase(0, std::min(s.find_first_not_of('0'), s.size()));
    return s;
}

std::string strip_trailing_zeros(std::string s) {
    auto last = s.find_last_not_of('0');
    s.erase(last == std::string::npos ? 0 : last + 1);
    return s;
}

}  // namespace

const WordFormat* FormatSpec::find(char address) const {
    if (address == ':') address = 'N';
    for (const auto& w : words)
        if (w.address == address) return &w;
    return nullptr;
}

FormatSpec parse_format_spec(std::string_view text) {
    FormatSpec spec;
    spec.text = std::string(text);
    std::string s;
    for (char c : text)
        if (!std::isspace(static_cast<unsigned char>(c))) s += c;
    if (s.empty()) throw Error(Errc::usage, "empty format specification");
    std::size_t i = 0;
    while (i < s.size()) {
        char c = s[i];
        if (c == '%')
            spec.program_start = true, ++i;
        else if (c == ':')
            spec.main_block = true, ++i;
        else if (c == '/')
            spec.block_skip = true, ++i;
        else if (c == '.')
            spec.tab = true, ++i;
        else if (c == '*') {
            if (++i != s.size()) spec_error(text, "'*' (end of block) must be last");
        } else if (c == 'D' && i + 1 < s.size() && s[i + 1] == 'S' &&
                   (i + 2 == s.size() || !std::isdigit(static_cast<unsigned char>(s[i + 2])))) {
            spec.explicit_point = true;
            i += 2;
        } else if (c >= 'A' && c <= 'Z') {
            std::size_t j = i + 1;
            bool sign = j < s.size() && s[j] == '+';
            if (sign) ++j;
            std::size_t k = j;
            while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
            if (k == j) spec_error(text, std::string("no digits after ") + c);
            if (spec.find(c)) spec_error(text, std::string(1, c) + " is given twice");
            spec.words.push_back(word_format(c, sign, s.substr(j, k - j), text));
            i = k;
        } else {
            spec_error(text, std::string("'") + c +
                                 "' is not part of the notation (% : / DS . * and words such as X+053, N03)");
        }
    }
    if (spec.words.empty()) spec_error(text, "no words");
    return spec;
}

DecimalValue word_value(const Word& w, const WordFormat* from) {
    DecimalValue v;
    v.negative = w.sign == '-';
    std::string whole = w.digits(), fraction;
    if (w.has_point()) {
        fraction = whole.substr(static_cast<std::size_t>(w.point));
        whole.resize(static_cast<std::size_t>(w.point));
    } else if (from && from->dimension) {
        std::size_t total = static_cast<std::size_t>(from->before + from->after);
        std::string d = whole;
        if (d.size() < total)
            d = from->omit_trailing ? d + std::string(total - d.size(), '0') : std::string(total - d.size(), '0') + d;
        std::size_t cut = d.size() - static_cast<std::size_t>(from->after);
        whole = d.substr(0, cut);
        fraction = d.substr(cut);
    }
    v.whole = strip_leading_zeros(whole);
    v.fraction = strip_trailing_zeros(fraction);
    if (v.whole.empty() && v.fraction.empty()) v.negative = false;
    return v;
}

std::vector<std::pair<std::string_view, std::string>> check_word(const Word& w, const FormatSpec& spec,
                                                                 bool program_has_points) {
    std::vector<std::pair<std::string_view, std::string>> problems;
    const WordFormat* f = spec.find(w.address);
    if (!f) {
        problems.emplace_back("spec-address", "the controller format has no address " +
                                                  std::string(1, w.address == ':' ? 'N' : w.address));
        return problems;
    }
    if (w.sign && !f->sign)
        problems.emplace_back("spec-sign", w.text + ": the format writes " + f->text + " without a sign");
    if (w.has_point()) {
        if (!spec.explicit_point)
            problems.emplace_back("spec-point", w.text + ": the format has no DS, so no explicit decimal point");
        else if (!f->dimension)
            problems.emplace_back("spec-point", w.text + ": " + f->text + " is a whole number");
        int before = w.point, after = static_cast<int>(w.digits().size()) - w.point;
        if (f->dimension && (before > f->before || after > f->after))
            problems.emplace_back("spec-digits", w.text + ": " + f->text + " allows " + std::to_string(f->before) +
                                                     " digits before the point and " + std::to_string(f->after) +
                                                     " after");
        return problems;
    }
    int n = static_cast<int>(w.digits().size());
    if (!f->dimension || (program_has_points && spec.explicit_point)) {
        // A whole number: dimensionless words, or dimension words of a program with explicit points (§3.1.4).
        int allowed = f->before;
        bool ok = f->omit_leading || f->dimension ? n <= allowed : n == allowed;
        if (!ok)
            problems.emplace_back("spec-digits", w.text + ": " + f->text + " takes " +
                                                     (f->omit_leading || f->dimension ? "at most " : "exactly ") +
                                                     std::to_string(allowed) + " digit(s)");
        return problems;
    }
    int total = f->before + f->after;
    bool ok = (f->omit_leading || f->omit_trailing) ? n <= total : n == total;
    if (!ok)
        problems.emplace_back("spec-digits", w.text + ": " + f->text + " takes " +
                                                 ((f->omit_leading || f->omit_trailing) ? "at most " : "exactly ") +
                                                 std::to_string(total) + " digits (" + std::to_string(f->before) +
                                                 " before the implied point, " + std::to_string(f->after) + " after)");
    return problems;
}

std::string format_word(const Word& w, const FormatSpec& spec, const FormatSpec* from, bool strip_zeros) {
    const WordFormat* f = spec.find(w.address);
    if (!f)
        throw Error(Errc::bad_text,
                    "the controller format has no address " + std::string(1, w.address == ':' ? 'N' : w.address));
    // A main block number is written with N's digits, but only a format with ':' has main blocks.
    if (w.address == ':' && !spec.main_block)
        throw Error(Errc::bad_text, w.text + ": the controller format has no ':' main blocks");
    DecimalValue v = word_value(w, from ? from->find(w.address) : nullptr);
    if (v.negative && !f->sign)
        throw Error(Errc::bad_text, w.text + ": negative, but the format writes " + f->text + " without a sign");
    std::string out(1, w.address);
    if (f->sign) out += v.negative ? '-' : '+';
    if (!f->dimension) {
        if (!v.fraction.empty()) throw Error(Errc::bad_text, w.text + ": " + f->text + " takes a whole number");
        if (static_cast<int>(v.whole.size()) > f->before)
            throw Error(Errc::bad_text,
                        w.text + ": " + f->text + " has room for " + std::to_string(f->before) + " digit(s)");
        std::string d = v.whole.empty() ? "0" : v.whole;
        if (!(strip_zeros && f->omit_leading))
            d = std::string(static_cast<std::size_t>(f->before) - v.whole.size(), '0') + v.whole;
        if (d.empty()) d = "0";
        return out + d;
    }
    if (static_cast<int>(v.whole.size()) > f->before)
        throw Error(Errc::bad_text, w.text + ": " + f->text + " has room for " + std::to_string(f->before) +
                                        " digit(s) before the point");
    if (static_cast<int>(v.fraction.size()) > f->after)
        throw Error(Errc::bad_text, w.text + ": " + f->text + " has room for " + std::to_string(f->after) +
                                        " digit(s) after the point");
    if (spec.explicit_point) {
        // A format without digits before the point (X+05) has no room for the usual "0.": the point
        // comes first, and zero is ".0" so that the word keeps a digit.
        if (v.whole.empty() && f->before == 0) return out + "." + (v.fraction.empty() ? "0" : v.fraction);
        return out + (v.whole.empty() ? "0" : v.whole) + "." + v.fraction;
    }
    std::string d = std::string(static_cast<std::size_t>(f->before) - v.whole.size(), '0') + v.whole + v.fraction +
                    std::string(static_cast<std::size_t>(f->after) - v.fraction.size(), '0');
    if (strip_zeros && f->omit_leading)
        d = strip_leading_zeros(d);
    else if (strip_zeros && f->omit_trailing)
        d = strip_trailing_zeros(d);
    if (d.empty()) d = "0";
    return out + d;
}

}  // namespace tape
