// A tape's own rules, learned from its undamaged blocks (tape_rules.hpp).
#include "tape_rules.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "tape/code_tables.hpp"
#include "tape/lint.hpp"
#include "tape/machine.hpp"

namespace tape::detail {
namespace {

// The word's digits start with a zero that is no value of its own ("01", "0040000", not "0" or "0.5"):
// the tape punches its words to a fixed width.
bool zero_padded(const Word& w) {
    std::string d = w.digits();
    int before = w.has_point() ? w.point : static_cast<int>(d.size());
    return before > 1 && d.front() == '0';
}

// The value of a plain word as a number: digits with the point where it is written (without one, the
// digits as a whole number: the implied point is the same for every such word of a block).
std::optional<double> number_of(const Word& w) {
    if (w.macro || !w.known) return std::nullopt;
    std::string d;
    for (char c : w.text)
        if ((c >= '0' && c <= '9') || c == '.') d += c;
    if (d.empty() || d == ".") return std::nullopt;
    double v = std::strtod(d.c_str(), nullptr);
    return w.sign == '-' ? -v : v;
}

int axis_of(char address) { return address == 'X' ? 0 : address == 'Y' ? 1 : address == 'Z' ? 2 : -1; }

// G codes whose axis words are no end point: dwell, data setting, reference returns, coordinate
// setting and shifts, macro calls.
bool axes_mean_other(int g) {
    return g == 4 || g == 10 || g == 27 || g == 28 || g == 29 || g == 30 || g == 50 || g == 52 || g == 53 || g == 65 ||
           g == 92;
}

std::uint32_t key3(unsigned char a, unsigned char b, unsigned char c) {
    return static_cast<std::uint32_t>(a) << 16 | static_cast<std::uint32_t>(b) << 8 | c;
}

}  // namespace

std::optional<WordShape> shape_of(const Word& w) {
    if (w.macro || !w.known) return std::nullopt;
    WordShape s;
    s.sign = w.sign;
    bool point = false, any = false;
    for (char c : w.text) {
        if (c == '.') {
            if (point) return std::nullopt;
            point = true, s.after = 0;
        } else if (c >= '0' && c <= '9') {
            any = true;
            ++(point ? s.after : s.before);
        }
    }
    if (!any) return std::nullopt;
    return s;
}

void advance(MotionState& state, const Block& block) {
    bool other = false, macro = false;
    for (const auto& w : block.words) {
        macro |= w.macro;
        if (w.address != 'G') continue;
        auto g = w.integer();
        if (!g) continue;
        if (*g == 90) state.absolute = true;
        if (*g == 91) state.absolute = false;
        if (*g >= 17 && *g <= 19) state.plane = static_cast<int>(*g);
        if (*g >= 0 && *g <= 3) state.motion = static_cast<int>(*g);
        other |= axes_mean_other(static_cast<int>(*g));
    }
    if (!block.statements.empty()) macro = true;
    for (const auto& w : block.words) {
        int axis = axis_of(w.address);
        if (axis < 0) continue;
        auto v = number_of(w);
        auto& at = state.at[static_cast<std::size_t>(axis)];
        if (other || macro || !v)
            at.reset();
        else if (state.absolute)
            at = *v;
        else if (at)
            at = *at + *v;
        state.pointed[static_cast<std::size_t>(axis)] = w.has_point();
    }
}

TapeRules::TapeRules(const std::set<std::uint64_t>& damaged_lines, const std::set<std::uint64_t>& numbers_damaged,
                     const FormatSpec* spec, const MachineProfile* machine)
    : damaged_lines_(damaged_lines),
      numbers_damaged_(numbers_damaged),
      // The machine's format is not lint's here: a tape that breaks it in places (the course text's
      // OCR) would count as one whose grammar does not fit, and no repair would be judged by grammar.
      lint_(std::make_unique<LintVisitor>(LintOptions{spec})),
      spec_(spec),
      machine_(machine) {
    if (machine) format_.emplace(*machine);
}

const FormatSpec* TapeRules::block_spec(std::uint64_t line, const Block& b) const {
    if (!machine_) return spec_;
    if (machine_->format.words.empty()) return nullptr;
    auto at = format_before_.find(line);
    MachineFormat f = at != format_before_.end() ? at->second : MachineFormat(*machine_);
    return &f.block(b);  // the profile's format or one of its modes: it outlives f
}

TapeRules::~TapeRules() = default;

// How an undamaged word keeps the machine's format: its digit count by address, the rules of notation
// across the tape.
std::optional<bool> machine_lists_code(const MachineProfile& p, const Word& w) {
    std::string d = w.digits();
    if (w.macro || !w.known || w.sign || w.has_point() || d.empty()) return std::nullopt;
    if (d.size() > 4) return false;  // no code has that many digits (and std::stoi takes it whole)
    const WordFormat* f = p.format.find(w.address);
    bool prefixed = p.prefixed.find(w.address) != std::string::npos && f && !f->dimension &&
                    static_cast<int>(d.size()) == f->before && d.size() >= 2;
    if (prefixed && d[0] != '0' && d[0] != '1') return false;
    return p.find_code(w.address, std::stoi(prefixed ? d.substr(1) : d)) != nullptr;
}

void TapeRules::learn_machine_format(const Word& w, const FormatSpec& spec) {
    if (w.address == 'G' || w.address == 'M')
        if (auto listed = machine_lists_code(*machine_, w)) (*listed ? ++machine_codes_ : foreign_codes_ = true);
    ++checked_words_;
    bool digits_kept = true;
    for (const auto& [rule, message] : check_word(w, spec, points_)) {
        if (rule == "spec-digits")
            digits_kept = false;
        else
            broken_rules_.emplace(rule);
    }
    if (digits_kept)
        ++fitting_[w.address];
    else
        untrusted_.insert(w.address);
}

bool TapeRules::machine_rule_trusted(char address, std::string_view rule) const {
    if (rule == "spec-digits") return machine_format_trusted(address);
    if (rule == "spec-tab" && tabs_) return false;
    return checked_words_ >= enough_words && !broken_rules_.count(rule);
}

void TapeRules::program_start(const Program& header) {
    lint_->program_start(header);
    state_ = MotionState{};
    if (format_) format_->program_start();
}

void TapeRules::block(const Block& b) {
    lint_->block(b);
    ++blocks_;
    bool damaged = b.damaged || damaged_lines_.count(b.where.line) > 0;
    if (damaged) before_.emplace(b.where.line, state_);
    if (format_) {
        if (damaged) format_before_.emplace(b.where.line, *format_);
        const FormatSpec& spec = format_->block(b);  // a damaged block's codes as read, as advance() takes them
        if (!damaged && !machine_->format.words.empty())
            for (const auto& w : b.words)
                if (w.known && !w.macro) learn_machine_format(w, spec);
    }
    if (!damaged)
        if (auto closes = arc_agrees(state_, b)) ++arcs_checked_, arcs_open_ += !*closes;
    advance(state_, b);
    if (damaged) state_.at = {};
    learn_block(b, damaged);
    points_ |= std::any_of(b.words.begin(), b.words.end(), [](const Word& w) { return w.has_point(); });
}

void TapeRules::finish(std::string_view text) {
    std::vector<std::string_view> lines;
    for (std::size_t from = 0; from <= text.size();) {
        std::size_t to = std::min(text.find('\n', from), text.size());
        lines.push_back(text.substr(from, to - from));
        from = to + 1;
    }
    std::set<std::uint64_t> with_errors;
    for (const auto& f : lint_->findings()) {
        std::uint64_t line = f.where.line.value_or(0);
        if (line == 0 || line > lines.size() || damaged_lines_.count(line) || f.severity != Severity::error) continue;
        excused_.insert(finding_key(f, lines[line - 1]));
        with_errors.insert(line);
    }
    for (std::size_t l = 0; l < lines.size(); ++l)
        if (!damaged_lines_.count(l + 1)) learn_digit_spacing(lines[l]);
    error_lines_ = with_errors.size();
    lint_.reset();
    learn_step();
}

// Digits side by side, and digits with only spaces between them, outside ( ) comments; and tabs.
void TapeRules::learn_digit_spacing(std::string_view line) {
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    bool comment = false, last_digit = false, spaced = false;
    for (char c : line) {
        tabs_ |= c == '\t';
        comment = c == '(' || (comment && c != ')');
        if (comment || c == ')') {
            last_digit = false;
        } else if (c == ' ') {
            spaced = true;
            continue;
        } else {
            if (digit(c) && last_digit) ++(spaced ? split_digits_ : digit_pairs_);
            last_digit = digit(c);
        }
        spaced = false;
    }
}

void TapeRules::learn_block(const Block& b, bool damaged) {
    bool number_damaged = b.damaged || numbers_damaged_.count(b.where.line) > 0;
    numbers_.emplace_back(b.where.line, number_damaged                      ? damaged_number
                                        : !b.number || !b.number->integer() ? no_number
                                                                            : *b.number->integer());
    if (damaged) return;
    ++undamaged_blocks_;
    if (b.number) ++addresses_[b.number->address];
    for (const auto& w : b.words) {
        ++addresses_[w.address];
        unreadable_[w.address] += !w.known;
        bool lower = !w.text.empty() && std::islower(static_cast<unsigned char>(w.text.front()));
        ++(lower ? lower_words_ : upper_words_);
    }
    if (b.number)  // block numbers keep a format too (N001, :005): under 'N'
        if (auto s = shape_of(*b.number)) ++shapes_['N'][*s], ++words_['N'], padded_['N'] += zero_padded(*b.number);
    for (const auto& w : b.words) {
        if (auto s = shape_of(w)) {
            ++shapes_[w.address][*s];
            ++words_[w.address];
            padded_[w.address] += zero_padded(w);
        }
        if (w.address == 'G' || w.address == 'M')
            codes_.insert(std::string(1, w.address) + code_value(w.text.substr(1)));
        if (w.address == 'F' || w.address == 'S' || w.address == 'T')
            if (auto v = number_of(w)) {
                auto [it, fresh] = ranges_.try_emplace(w.address, *v, *v);
                it->second.first = std::min(it->second.first, *v), it->second.second = std::max(it->second.second, *v);
                ++range_words_[w.address];
            }
    }
}

void CharModel::learn(std::span<const Frame> frames) {
    Frame a = blank_frame, b = blank_frame;
    for (Frame c : frames) {
        if (c == blank_frame) continue;
        ++trigrams_[key3(a, b, c)];
        ++bigrams_[key3(0, a, b)];
        ++bigrams_[key3(1, b, c)];  // b then c, for the chance of c after b alone
        ++unigrams_[c], ++total_;
        a = b, b = c;
    }
}

double CharModel::chance(Frame a, Frame b, Frame c) const {
    auto count = [](const std::unordered_map<std::uint32_t, std::uint32_t>& m, std::uint32_t k) {
        auto it = m.find(k);
        return it == m.end() ? 0.0 : static_cast<double>(it->second);
    };
    const double ab = count(bigrams_, key3(0, a, b)), b_any = static_cast<double>(unigrams_[b]);
    const double p3 = ab > 0 ? count(trigrams_, key3(a, b, c)) / ab : 0;
    const double p2 = b_any > 0 ? count(bigrams_, key3(1, b, c)) / b_any : 0;
    const double p1 = (static_cast<double>(unigrams_[c]) + 0.5) / (static_cast<double>(total_) + 128);
    return 0.6 * p3 + 0.3 * p2 + 0.1 * p1;
}

double CharModel::score(Frame before2, Frame before1, Frame f, Frame after) const {
    return std::log(chance(before2, before1, f)) + std::log(chance(before1, f, after));
}

bool TapeRules::format_broken(char address, const WordShape& shape) const {
    auto n = words_.find(address);
    if (n == words_.end() || n->second < enough_words) return false;
    std::size_t pointed = 0, signed_ = 0, plus = 0;
    std::set<int> decimals, widths;
    for (const auto& [s, count] : shapes_.at(address)) {
        pointed += s.after >= 0 ? count : 0;
        signed_ += s.sign ? count : 0;
        plus += s.sign == '+' ? count : 0;
        if (s.after >= 0) decimals.insert(s.after);
        widths.insert(s.before + std::max(s.after, 0));
    }
    bool point = shape.after >= 0;
    if ((pointed == 0 && point) || (pointed == n->second && !point)) return true;  // point style
    if (more_digits_than_ever(address, shape)) return true;
    if (point && pointed >= enough_words && decimals.size() == 1 && *decimals.begin() != shape.after) return true;
    // A fixed width shows in zeros punched before the digits (N001, X+0040000): words of one width alone
    // (M3, M5, M8, then M30) are no format.
    auto padded = padded_.find(address);
    if (widths.size() == 1 && padded != padded_.end() && padded->second > 0 &&
        *widths.begin() != shape.before + std::max(shape.after, 0))
        return true;
    if ((plus == 0 && shape.sign == '+') || (signed_ == n->second && !shape.sign)) return true;  // sign style
    return false;
}

// By Good and Turing's estimate, the chance that a word's letter is one the tape has not shown yet is
// the share of words whose letter is seen once: a letter the damage hid (its only word damaged) is as
// likely as that. Only where that chance is under one in a thousand (with one more letter seen once
// than counted, for the one a damaged block may hold) is an unseen letter ruled out.
bool TapeRules::address_unused(char address) const {
    if (addresses_.count(address)) return false;
    std::size_t words = 0, once = 1;
    for (const auto& [letter, n] : addresses_) words += n, once += n == 1;
    return words >= 1000 * once;
}

bool TapeRules::form_broken(const Word& w) const {
    if (w.known || w.macro) return false;
    auto n = words_.find(w.address);
    auto bad = unreadable_.find(w.address);
    return n != words_.end() && n->second >= enough_words && (bad == unreadable_.end() || bad->second == 0);
}

bool TapeRules::case_broken(const Word& w) const {
    if (w.text.empty() || !std::isalpha(static_cast<unsigned char>(w.text.front()))) return false;
    bool lower = std::islower(static_cast<unsigned char>(w.text.front()));
    return (lower ? upper_words_ : lower_words_) >= enough_words && (lower ? lower_words_ : upper_words_) == 0;
}

// More digits before the point (or in all, without one) than any word of the address of that style has
// on a tape that writes it often, many words with the most: "X-1338.958" where X never has more than
// three, and many have three.
bool TapeRules::more_digits_than_ever(char address, const WordShape& shape) const {
    constexpr std::size_t many_words = 100, many_at_most = 10;
    // Codes and numbers are no quantities: M30 after many M3, N10000 after N9990.
    if (address == 'G' || address == 'M' || address == 'N' || address == 'O' || address == ':') return false;
    bool point = shape.after >= 0;
    int most = -1;
    std::size_t words = 0, at_most = 0;
    for (const auto& [s, count] : shapes_.at(address)) {
        if ((s.after >= 0) != point) continue;
        words += count;
        if (s.before > most) most = s.before, at_most = 0;
        if (s.before == most) at_most += count;
    }
    return words >= many_words && at_most >= many_at_most && shape.before > most;
}

bool TapeRules::code_used(char letter, std::string_view value) const {
    return codes_.count(std::string(1, letter) + std::string(value)) > 0;
}

// The step most consecutive numbered blocks keep, if nearly all keep it.
void TapeRules::learn_step() {
    std::map<long long, std::size_t> steps;
    std::size_t pairs = 0;
    for (std::size_t i = 1; i < numbers_.size(); ++i)
        if (numbers_[i - 1].second >= 0 && numbers_[i].second >= 0)
            ++steps[numbers_[i].second - numbers_[i - 1].second], ++pairs;
    if (pairs < 4) return;
    auto step = std::max_element(steps.begin(), steps.end(), [](auto& x, auto& y) { return x.second < y.second; });
    if (step->first > 0 && step->second * 10 >= pairs * 9) step_ = step->first;
}

std::optional<long long> TapeRules::expected_number(std::uint64_t line) const {
    auto it = std::lower_bound(numbers_.begin(), numbers_.end(), std::make_pair(line, no_number));
    if (it == numbers_.end() || it->first != line) return std::nullopt;
    auto at = static_cast<std::size_t>(it - numbers_.begin());
    if (step_ != 0 && at > 0 && at + 1 < numbers_.size()) {
        long long before = numbers_[at - 1].second, after = numbers_[at + 1].second;
        if (before >= 0 && after >= 0 && after - before == 2 * step_) return before + step_;
    }
    return local_sequence(at);
}

// Two numbered blocks on each side of block `at` (within a few blocks, damaged ones counted as places,
// none crossed that has no number) that keep one step, the same N repeated included: the number `at`
// must have. A block numbered out of step, or a skip in the numbers, breaks the step across it.
std::optional<long long> TapeRules::local_sequence(std::size_t at) const {
    constexpr long long reach = 6;
    std::vector<std::pair<long long, long long>> known;  // (place from at, N)
    for (int dir : {-1, 1}) {
        int found = 0;
        for (long long d = 1; d <= reach && found < 2; ++d) {
            long long i = static_cast<long long>(at) + dir * d;
            if (i < 0 || i >= static_cast<long long>(numbers_.size())) break;
            long long n = numbers_[static_cast<std::size_t>(i)].second;
            if (n == no_number) break;
            if (n >= 0) known.emplace_back(dir * d, n), ++found;
        }
        if (found < 2) return std::nullopt;
    }
    std::sort(known.begin(), known.end());
    auto [p0, n0] = known.front();
    auto [p1, n1] = known.back();
    if ((n1 - n0) % (p1 - p0) != 0) return std::nullopt;
    long long step = (n1 - n0) / (p1 - p0);
    if (step < 0) return std::nullopt;
    for (auto [p, n] : known)
        if (n != n0 + step * (p - p0)) return std::nullopt;
    return n0 - step * p0;
}

bool TapeRules::value_out_of_range(char address, double value) const {
    constexpr std::size_t enough = 5;
    constexpr double far = 10;
    auto r = ranges_.find(address);
    if (r == ranges_.end() || range_words_.at(address) < enough) return false;
    return value > r->second.second * far || (r->second.first > 0 && value * far < r->second.first);
}

const MotionState* TapeRules::state_before(std::uint64_t line) const {
    auto it = before_.find(line);
    return it == before_.end() ? nullptr : &it->second;
}

std::string finding_key(const Finding& f, std::string_view line_text) {
    std::string key(f.id());
    std::size_t col = static_cast<std::size_t>(f.where.column.value_or(1));
    if (col == 0 || col > line_text.size()) return key;
    std::string_view at = line_text.substr(col - 1);
    if (f.id() == "unknown-code") return key + ":" + std::string(at.substr(0, at.find_first_of(" \t(;")));
    return key + ":" + std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(at.front()))));
}

bool looks_like_nc_program(std::string_view text) {
    std::size_t letters = 0, addresses = 0;
    bool comment = false, semicolon = false, name = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '\n') comment = semicolon = name = false;
        if (c == '(') comment = true;
        if (c == ')') comment = false;
        if (c == ';') semicolon = true;
        if (c == '<') name = true;
        if (c == '>') name = false;
        if (comment || semicolon || name || !std::isalpha(static_cast<unsigned char>(c))) continue;
        ++letters;
        std::size_t j = i + 1;
        while (j < text.size() && (text[j] == ' ' || text[j] == '+' || text[j] == '-')) ++j;
        if (j < text.size() &&
            (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.' || text[j] == '#' || text[j] == '['))
            ++addresses;
    }
    constexpr std::size_t few = 20;
    return letters < few || addresses * 10 >= letters * 6;
}

}  // namespace tape::detail
