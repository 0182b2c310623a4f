// Numbers of a block's words. Where a word has no decimal point, the control decides where its implied
// point stands, and each dialect's controls decide differently:
// - Fanuc: a length or angle without a point counts the least input increment (IS-B: 0.001 mm, 0.0001
//   inch), so X1000 is 1 mm and X1. is 1 mm; F, S, T, P are whole numbers (Fanuc Operator's Manual,
//   "Decimal point programming"; calculator-type input, parameter DPI No. 3401#0, is off by default).
// - LinuxCNC: every number is a plain decimal (X1 is 1 mm).
// - ГОСТ 20999-83 (and controls no dialect fits): §3.1.3 puts the implied point in the control's format,
//   so it is known from a format specification only; §3.1.4 says that in a program that writes points
//   a word without one is a whole number. Without either, a non-zero value cannot be read: it is
//   unscaled, and the interpreter says so rather than guess a scale.
// A format specification (MotionOptions::spec) decides over all of these.
#include "motion/words.hpp"

#include <cmath>
#include <string>

namespace tape::motion {
namespace {

bool is_length(char a) {
    switch (a) {
        case 'X':
        case 'Y':
        case 'Z':
        case 'U':
        case 'V':
        case 'W':
        case 'A':
        case 'B':
        case 'C':
        case 'I':
        case 'J':
        case 'K':
        case 'R':
        case 'Q':
            return true;
        default:
            return false;
    }
}

struct Parsed {
    double value = 0;
    bool ok = false;
    bool zero = true;
};

// Exact powers of ten: a value of at most 15 digits divided by one is the nearest double to it.
constexpr double powers_of_ten[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// Digits and point of the word's text (address, sign and blanks skipped). The loader has read the
// digits of most words already (Word::digits_value): those of 15 digits or fewer need no second look.
Parsed parse(const Word& w) {
    Parsed p;
    if (w.digit_count >= 1 && w.digit_count <= 15 && !w.macro) {
        int decimals = w.has_point() ? w.digit_count - w.point : 0;
        p.ok = true;
        p.zero = w.digits_value == 0;
        p.value = static_cast<double>(w.digits_value) / powers_of_ten[decimals] * (w.sign == '-' ? -1 : 1);
        return p;
    }
    double whole = 0, fraction = 0, scale = 1;
    int digits = 0;
    bool after = false;
    for (std::size_t i = 1; i < w.text.size(); ++i) {
        char c = w.text[i];
        if (c == '.') {
            after = true;
            continue;
        }
        if (c < '0' || c > '9') continue;
        p.ok = true;
        if (c != '0') p.zero = false;
        // A whole part longer than any control's word; digits far after the point are only precision.
        if (!p.zero && ++digits > 15 && !after) {
            p.ok = false;
            return p;
        }
        if (after)
            scale /= 10, fraction += (c - '0') * scale;
        else
            whole = whole * 10 + (c - '0');
    }
    p.value = (whole + fraction) * (w.sign == '-' ? -1 : 1);
    return p;
}

double spec_value(const Word& w, const WordFormat* f) {
    DecimalValue d = word_value(w, f);
    std::string s = (d.whole.empty() ? std::string("0") : d.whole) + "." + d.fraction;
    double v = std::strtod(s.c_str(), nullptr);
    return d.negative ? -v : v;
}

ValueState value_of(const Word& w, const NumberRules& r, double& out, bool& implied) {
    implied = false;
    if (w.macro) return ValueState::macro;
    Parsed p = parse(w);
    if (!p.ok) return ValueState::bad;
    out = p.value;
    if (w.has_point() || p.zero) return ValueState::ok;
    if (r.spec) {
        const WordFormat* f = r.spec->find(w.address);
        if (f && f->dimension) {
            out = spec_value(w, f);
            return ValueState::ok;
        }
    }
    if (!is_length(w.address)) return ValueState::ok;
    switch (r.dialect) {
        case Dialect::fanuc:
            out = p.value * (r.inch ? 0.0001 : 0.001);
            implied = true;
            return ValueState::ok;
        case Dialect::linuxcnc:
            return ValueState::ok;
        default:
            return r.program_points ? ValueState::ok : ValueState::unscaled;
    }
}

// G90.1 → 901, G01 → 10; -1 when the word is no plain code.
int code10(const Word& w) {
    if (w.macro) return -1;
    Parsed p = parse(w);
    if (!p.ok || w.sign || p.value > 9999) return -1;
    return static_cast<int>(std::lround(p.value * 10));
}

}  // namespace

bool BlockWords::has_g(int code10) const {
    for (int i = 0; i < g_count; ++i)
        if (g[i] == code10) return true;
    return false;
}

bool BlockWords::has_m(int code) const {
    for (int i = 0; i < m_count; ++i)
        if (m[i] == code) return true;
    return false;
}

bool block_has_points(const Block& block) {
    for (const auto& w : block.words)
        if (w.has_point()) return true;
    return false;
}

void read_words(const Block& block, const NumberRules& rules, BlockWords& out) {
    out.state.fill(ValueState::absent);
    out.g_count = out.m_count = 0;
    out.odd_code = nullptr;
    for (const auto& w : block.words) {
        if (w.address < 'A' || w.address > 'Z' || !w.known) continue;
        if (w.address == 'G' || w.address == 'M') {
            int c = code10(w);
            bool g = w.address == 'G';
            int& count = g ? out.g_count : out.m_count;
            if (c < 0 || count == BlockWords::max_codes || (!g && c % 10 != 0)) {
                out.odd_code = &w;
                continue;
            }
            (g ? out.g : out.m)[count++] = g ? c : c / 10;
            continue;
        }
        auto i = static_cast<std::size_t>(w.address - 'A');
        if (!(rules.letters >> i & 1)) continue;
        out.word[i] = &w;
        out.state[i] = value_of(w, rules, out.value[i], out.implied[i]);
    }
}

}  // namespace tape::motion
