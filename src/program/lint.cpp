// Lint: the rules of ГОСТ 20999-83 §1.4-§2.7 and of the dialects over loaded programs.
#include "tape/lint.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <tuple>
#include <utility>

#include "program/block_targets.hpp"
#include "program/lint_arcs.hpp"
#include "program/lint_travel.hpp"
#include "tape/code_tables.hpp"
#include "tape/functions.hpp"
#include "tape/machine_checks.hpp"
#include "tape/rules.hpp"

namespace tape {
namespace {

constexpr std::string_view dimension_order = "XYZUVWPQRABC";
constexpr std::string_view interpolation_order = "IJK";
constexpr std::string_view unsigned_addresses = "NGFSTMEO";

// A set of address letters as a table: these are asked of every word of every block.
class Letters {
public:
    constexpr explicit Letters(std::string_view a, std::string_view b = "") {
        for (char c : a) in_[static_cast<unsigned char>(c)] = true;
        for (char c : b) in_[static_cast<unsigned char>(c)] = true;
    }
    constexpr bool has(char c) const { return in_[static_cast<unsigned char>(c)]; }

private:
    std::array<bool, 256> in_{};
};
constexpr Letters dimension_letters(dimension_order, interpolation_order);
// Fanuc and LinuxCNC: P Q R are parameters (dwell, cycle depths, radius), not dimensions.
constexpr Letters axis_or_center_letters("XYZUVWABCIJK"), end_point_letters("XYZUVWABC");
constexpr Letters unsigned_letters(unsigned_addresses);

// Recommended order within a block (§2.2): G, X Y Z U V W P Q R A B C, I J K, F, S, T, M.
// Addresses whose place a controller's format decides (D E H L O N) have no rank: -1. A table, as
// every word of every block asks.
constexpr auto order_ranks = [] {
    std::array<std::int8_t, 256> rank{};
    rank.fill(-1);
    rank['G'] = 0;
    for (std::size_t p = 0; p < dimension_order.size(); ++p)
        rank[static_cast<unsigned char>(dimension_order[p])] = static_cast<std::int8_t>(10 + p);
    for (std::size_t p = 0; p < interpolation_order.size(); ++p)
        rank[static_cast<unsigned char>(interpolation_order[p])] = static_cast<std::int8_t>(30 + p);
    rank['F'] = 40;
    rank['S'] = 50;
    rank['T'] = 60;
    rank['M'] = 70;
    return rank;
}();
int order_rank(char a) { return order_ranks[static_cast<unsigned char>(a)]; }

bool is_dimension(char a) { return dimension_letters.has(a); }
bool is_axis_or_center(char a) { return axis_or_center_letters.has(a); }
bool is_end_point(char a) { return end_point_letters.has(a); }

using Add = const std::function<void(Finding)>&;

std::string unknown_code_reason(Dialect d, char letter) {
    switch (d) {
        case Dialect::gost:
            return letter == 'G' ? "is no G function of ГОСТ 20999-83: they have two digits, G00-G99 (table 4)"
                                 : "is no M function of ГОСТ 20999-83: they have two digits, M00-M99 (table 7), or "
                                   "three with a first 1 for after the machine's acknowledgement";
        case Dialect::fanuc:
            return letter == 'G'
                       ? "is no G code of Fanuc lathes, mills or the Haas controls that follow them"
                       : "is not in the Fanuc table: its M codes, the machine builder's, have at most three digits";
        case Dialect::linuxcnc:
            return letter == 'G' ? "is no LinuxCNC G code (G-code reference)"
                                 : "is no LinuxCNC M code (M-code reference; M100-M199 are the user's)";
        default:
            return "is not known";
    }
}

void add(Add out, std::string_view rule, const Location& where, std::uint64_t block, std::string message) {
    out(program_finding(rule, where, block, std::move(message)));
}

bool has_g(const Block& b, std::initializer_list<long long> codes) {
    for (const auto& w : b.words)
        if (w.address == 'G')
            if (auto g = w.integer(); g && std::find(codes.begin(), codes.end(), *g) != codes.end()) return true;
    return false;
}

// A G or M code written with a point that the dialect's table has (Fanuc's G54.1, G12.1, LinuxCNC's
// G33.1): the §9 notation cannot write such a code, and whether the control has it is the code table's
// question (unknown-code), not a point where the format has none.
bool dotted_code(const Word& w, Dialect dialect, std::optional<Dialect> close) {
    if ((w.address != 'G' && w.address != 'M') || !w.has_point()) return false;
    std::string value = code_value(std::string_view(w.text).substr(1));
    return !value.empty() && (code_known(dialect, w.address, value) || (close && code_known(*close, w.address, value)));
}

// The words of block b against format s, in the dialect read. note: with a machine, what its format mode
// adds to a word's finding ("G10 in effect: long dimensions").
struct SpecContext {
    bool points = false;  // the program writes explicit points somewhere
    Dialect dialect = Dialect::gost;
    std::optional<Dialect> close{};
    const MachineFormat* note = nullptr;
};
void spec_checks(Add out, const FormatSpec& s, const Block& b, const SpecContext& c) {
    if (b.main && !s.main_block)
        add(out, "spec-main", b.where, b.ordinal, "the controller format has no ':' main blocks");
    if (b.skip && !s.block_skip)
        add(out, "spec-skip", b.where, b.ordinal, "the controller format has no '/' block skip");
    auto check = [&](const Word& w) {
        if (w.macro || !w.known) return;  // a macro value has no digits to count; a flagged word was reported
        for (auto& [rule, message] : check_word(w, s, c.points)) {
            if (rule == "spec-point" && dotted_code(w, c.dialect, c.close)) continue;
            add(out, rule, w.where, b.ordinal, c.note && rule == "spec-digits" ? message + c.note->note(w) : message);
        }
    };
    if (b.number) check(*b.number);
    for (const auto& w : b.words) check(w);
}

// A G or M code outside the dialect's table (tape/code_tables.hpp); a macro value is not a code yet,
// and the letters of a macro call (G65, G66) are its arguments (M0.070 is #13): not asked of its block. A program uses
// few codes, again and again: each word as written is looked up once (unknown: whether it is outside the tables).
void code_checks(Add out, const Block& b, Dialect dialect, std::optional<Dialect> close,
                 lint_detail::CodeVerdicts& verdicts) {
    using V = lint_detail::CodeVerdicts;
    auto outside = [&](const Word& w) {
        std::string value = code_value(std::string_view(w.text).substr(1));
        return !value.empty() && !code_known(dialect, w.address, value) &&
               !(close && code_known(*close, w.address, value));
    };
    for (const auto& w : b.words) {
        if ((w.address != 'G' && w.address != 'M') || !w.known || w.macro || w.sign) continue;
        bool unknown;
        if (auto code = w.integer(); code && *code < 1000) {
            std::uint8_t& v = verdicts.plain[static_cast<std::size_t>(*code) + (w.address == 'M' ? 1000 : 0)];
            if (v == V::unasked) v = outside(w) ? V::unknown : V::known;
            unknown = v == V::unknown;
        } else {
            auto [at, first] = verdicts.written.try_emplace(w.text, false);
            if (first) at->second = outside(w);
            unknown = at->second;
        }
        if (unknown)
            add(out, "unknown-code", w.where, b.ordinal, w.text + " " + unknown_code_reason(dialect, w.address));
    }
}

// A letter's slot, 1..26 for either case; 0 for anything else.
unsigned letter_slot(char c) {
    unsigned folded = static_cast<unsigned char>(c) | 32u;
    return folded >= 'a' && folded <= 'z' ? folded & 31u : 0;
}

// The first word of a block in each of 32 slots (a letter's, either case: c & 31), kept as its index:
// an index is read only where the slot's bit is set, as zeroing the arrays for every block was a tenth
// of linting a long program.
class FirstWords {
public:
    const Word* at(const Block& b, unsigned slot) const {
        return slots_ >> slot & 1 ? &b.words[index_[slot]] : nullptr;
    }
    void set(const Block& b, unsigned slot, const Word& w) {
        index_[slot] = static_cast<std::uint32_t>(&w - b.words.data());
        slots_ |= 1u << slot;
    }

private:
    std::array<std::uint32_t, 32> index_;
    std::uint32_t slots_ = 0;
};

// With two dialects close, a word is held to what both readings ask: the looser of the two.
void word_checks(Add out, const Block& b, Dialect dialect, std::optional<Dialect> close, bool macro_call) {
    const DialectRules& rules = dialect_rules(dialect);
    bool gost_dimensions = dialect == Dialect::gost && !close;
    bool lathe_cycles = dialect == Dialect::fanuc || close == Dialect::fanuc;
    FirstWords seen, group;  // by address, by G group
    int max_rank = -1;
    const Word* max_word = nullptr;
    const Word* previous = nullptr;
    // A misread or unknown word says nothing about the order of the others: no cascade from it.
    bool order = rules.ordered_words &&
                 std::all_of(b.words.begin(), b.words.end(), [](const Word& w) { return w.known && !w.macro; });
    // Macro calls pass arguments by letter, and Fanuc's argument list II repeats I J K.
    bool dimensions = !macro_call;
    for (const auto& w : b.words) {
        if (!w.known) continue;
        unsigned a = letter_slot(w.address);
        bool dimension = gost_dimensions ? is_dimension(w.address) : is_axis_or_center(w.address);
        if (dimension && dimensions && a) {
            if (const Word* first = seen.at(b, a))
                add(out, "repeated-dimension", w.where, b.ordinal,
                    w.text + " repeats " + first->text +
                        ": a dimension or interpolation word may stand once in a block (§2.4)");
            else
                seen.set(b, a, w);
        }
        auto code = w.address == 'G' ? w.integer() : std::nullopt;
        if (code)
            if (const NcFunction* f = find_nc_function('G', *code); f && f->group) {
                unsigned g = letter_slot(f->group);
                // On a Fanuc lathe G90, G92 and G94 are turning cycles, not of the groups of table 4.
                bool lathe_cycle = lathe_cycles && (*code == 90 || *code == 92 || *code == 94);
                const Word* first = group.at(b, g);
                if (!lathe_cycle && first)
                    add(out, "g-group", w.where, b.ordinal,
                        w.text + " and " + first->text + " are both of group " + f->group + " (§2.5, table 4)");
                else if (!lathe_cycle)
                    group.set(b, g, w);
            }
        if (w.sign && unsigned_letters.has(w.address))
            add(out, "sign-not-allowed", w.where, b.ordinal,
                w.text + ": " + w.address + " words have no sign (§3.1.1, §3.3)");
        int rank = order_rank(w.address);
        // A feed that follows the dimension word of its own axis may stand there (§2.2).
        bool axis_feed_before = previous && previous->address == 'F' && max_word == previous;
        if (order && rank >= 0 && rank < max_rank && !(axis_feed_before && is_dimension(w.address))) {
            add(out, "word-order", w.where, b.ordinal,
                w.text + " stands after " + max_word->text +
                    "; recommended order G, X Y Z U V W P Q R A B C, I J K, F, S, T, M (§2.2)");
            order = false;  // once a block: the rest follow from the first
        }
        if (rank > max_rank) {
            max_rank = rank;
            max_word = &w;
        }
        previous = &w;
    }
}

}  // namespace

bool uses_explicit_points(const Program& program) {
    for (const auto& b : program.blocks)
        for (const auto& w : b.words)
            if (w.has_point()) return true;
    return false;
}

LintVisitor::LintVisitor(const LintOptions& options)
    : options_(options),
      sink_([this](Finding f) { keep(std::move(f)); }),
      targets_(std::make_unique<lint_detail::BlockTargets>()),
      machine_format_(options.machine ? std::make_unique<MachineFormat>(*options.machine) : nullptr) {}
LintVisitor::~LintVisitor() = default;

void LintVisitor::dialect(const DialectChoice& choice) {
    dialect_ = choice.dialect;
    close_ = choice.close;
    unknown_codes_.clear();
    // Two close readings may place a number's point differently (Fanuc's X1000 is 1 mm, LinuxCNC's
    // 1000 mm): arcs are checked only in a reading that stands alone.
    arcs_.reset();
    if (!close_ && options_.arcs)
        arcs_ = std::make_unique<lint_detail::ArcChecks>(dialect_, options_, [this](Finding f) {
            if (!quiet_) keep(std::move(f));
        });
    travel_.reset();
    if (!close_ && options_.machine && lint_detail::TravelChecks::applies(*options_.machine))
        travel_ = std::make_unique<lint_detail::TravelChecks>(*options_.machine, dialect_, [this](Finding f) {
            if (!quiet_) keep(std::move(f));
        });
}

void LintVisitor::program_start(const Program& header) {
    close_program();
    ++programs_;
    any_program_ = in_program_ = true;
    program_points_ = false;
    program_start_ = header.start;
    program_blocks_ = 0;
    last_number_.reset();
    after_end_at_.reset();
    motion_ = -1;
    feed_given_ = no_feed_said_ = subprogram_ = false;
    no_feed_.reset();
    open_.clear();
    if (arcs_) arcs_->start(header);
    if (travel_) travel_->start(header);
}

void LintVisitor::block(const Block& b) {
    quiet_ = b.damaged;  // the bad frame is the block's one finding; its modal state still counts
    ++program_blocks_;
    for (const auto& w : b.words) program_points_ |= w.has_point();
    if (auto n = b.number ? b.number->integer() : std::nullopt) {
        long long number = *n;  // set as a number: an optional copied whole stalls the CPU here
        if (last_number_ && number <= *last_number_)
            add(sink_, "block-number-order", b.number->where, b.ordinal,
                "block number " + b.number->text + " does not increase (the block before is " +
                    std::to_string(*last_number_) + ")");
        last_number_ = number;
    }
    if (dialect_ == Dialect::fanuc) targets_->block(b);
    static constexpr int m99[] = {99};
    if (b.ends && dialect_ == Dialect::fanuc) subprogram_ = holds_end_code(b, m99);
    bool macro_call = has_g(b, {65, 66});
    word_checks(sink_, b, dialect_, close_, macro_call);
    if (arcs_) arcs_->next(b);
    if (travel_) travel_->next(b);
    if (!macro_call) code_checks(sink_, b, dialect_, close_, unknown_codes_);
    motion_checks(b);
    flow_checks(b);
    if (options_.spec || options_.machine) held_.push_back(b);
    quiet_ = false;
}

// Feed moves need a feed, arcs a centre. G codes that take axis words for something else (reference
// returns, offsets, coordinate settings, cycles) leave the block unchecked.
void LintVisitor::motion_checks(const Block& b) {
    bool feed_here = false, end_point = false, center = false, radius = false, other_g = false;
    for (const auto& w : b.words) {
        if (!w.known) continue;
        feed_here |= w.address == 'F';
        end_point |= is_end_point(w.address);
        center |= w.address == 'I' || w.address == 'J' || w.address == 'K';
        radius |= w.address == 'R';
        if (w.address != 'G') continue;
        auto g = w.integer();
        if (!g) {
            other_g = true;  // G33.1, G38.2, G5.1, a macro value: not followed
            continue;
        }
        if (*g >= 0 && *g <= 3)
            motion_ = static_cast<int>(*g);
        else if ((*g >= 70 && *g <= 89) || *g == 33 || *g == 34 || *g == 35 ||
                 ((dialect_ == Dialect::fanuc || close_ == Dialect::fanuc) && (*g == 90 || *g == 92 || *g == 94) &&
                  !has_g(b, {0, 1, 2, 3})))
            motion_ = -1, other_g = true;  // cycles and threading: their own words
        else if (!(*g == 17 || *g == 18 || *g == 19 || *g == 20 || *g == 21 || (*g >= 40 && *g <= 44) || *g == 49 ||
                   (*g >= 53 && *g <= 59) || *g == 61 || *g == 64 || *g == 90 || *g == 91 || *g == 94 || *g == 95 ||
                   *g == 96 || *g == 97 || *g == 98 || *g == 99))
            other_g = true;
    }
    feed_given_ |= feed_here;
    if (other_g || !end_point || motion_ < 1) return;
    // One cause: the program gives no feed before its first feed move. A subroutine (LinuxCNC's o-sub,
    // a Fanuc program that ends with M99) moves at its caller's feed: said at the program's end, if at all.
    bool in_sub = std::any_of(open_.begin(), open_.end(), [](const Open& o) { return o.keyword == "sub"; });
    if (!feed_given_ && !no_feed_said_ && !in_sub) {
        no_feed_said_ = true;
        if (!quiet_)
            no_feed_ = program_finding(
                "no-feed", b.where, b.ordinal,
                "G0" + std::to_string(motion_) + " moves at a feed, but no F has been given in this program yet");
    }
    bool radius_allowed = dialect_ != Dialect::gost || (close_ && *close_ != Dialect::gost);
    if ((motion_ == 2 || motion_ == 3) && !center && !(radius_allowed && radius))
        add(sink_, "arc-center", b.where, b.ordinal,
            "G0" + std::to_string(motion_) + " with an end point but no " +
                (radius_allowed ? "I, J, K or R" : "I, J or K (§3.2)") + ": the arc is not defined");
}

// Loops and o-word blocks are closed in the order they were opened; GOTOs are kept for the end.
void LintVisitor::flow_checks(const Block& b) {
    using K = Statement::Kind;
    for (const auto& s : b.statements) {
        if (s.kind == K::while_do || s.kind == K::loop_do) {
            if (s.number) open_.push_back({std::to_string(*s.number), "DO", s.where, b.ordinal});
        } else if (s.kind == K::loop_end) {
            if (!s.number) continue;
            std::string n = std::to_string(*s.number);
            if (!close_to(n, "DO")) add(sink_, "control-flow", s.where, b.ordinal, "END " + n + " closes no DO " + n);
        } else if (s.kind == K::o_word) {
            const std::string& k = s.keyword;
            std::string_view closes = k == "endsub"      ? "sub"
                                      : k == "endif"     ? "if"
                                      : k == "endwhile"  ? "while"
                                      : k == "endrepeat" ? "repeat"
                                                         : "";
            bool do_while =
                k == "while" && !open_.empty() && open_.back().label == s.label && open_.back().keyword == "do";
            if (k == "sub" || k == "if" || k == "repeat" || k == "do" || (k == "while" && !do_while)) {
                open_.push_back({s.label, k, s.where, b.ordinal});
            } else if (do_while) {
                open_.pop_back();
            } else if (!closes.empty() || k == "else" || k == "elseif") {
                std::string_view wanted = closes.empty() ? "if" : closes;
                if (!closes.empty()
                        ? close_to(s.label, wanted)
                        : !open_.empty() && open_.back().label == s.label && open_.back().keyword == wanted) {
                } else {
                    add(sink_, "control-flow", s.where, b.ordinal,
                        "o" + s.label + " " + k + " has no open o" + s.label + " " + std::string(wanted));
                }
            }
        }
    }
}

// Closes the innermost open label/keyword; what was opened inside it and never closed is said once
// each, so that one missing END or endif is one finding, not one for every block around it.
bool LintVisitor::close_to(const std::string& label, std::string_view keyword) {
    auto it = std::find_if(open_.rbegin(), open_.rend(),
                           [&](const Open& o) { return o.label == label && o.keyword == keyword; });
    if (it == open_.rend()) return false;
    std::size_t keep = static_cast<std::size_t>(open_.rend() - it) - 1;
    for (std::size_t i = keep + 1; i < open_.size(); ++i) report_unclosed(open_[i]);
    open_.resize(keep);
    return true;
}

void LintVisitor::report_unclosed(const Open& o) {
    add(sink_, "control-flow", o.where, o.block,
        (o.keyword == "DO" ? "DO " + o.label + " is never closed with END " + o.label
                           : "o" + o.label + " " + o.keyword + " is never closed"));
}

void LintVisitor::after_end(std::string_view text, const Location& where) {
    if (!after_end_at_ && text.find_first_not_of(" \t\r\n") != std::string_view::npos) after_end_at_ = where;
}

void LintVisitor::finding(const Finding& f) { keep(f); }

// A rule the dialect does not have (nor, when two were close, the other) is not checked; the rest are
// counted, and of each rule the first max_per_rule by position are listed, whatever order they came in.
void LintVisitor::keep(Finding f) {
    if (const Rule* r = find_rule(f.id()); r && (!rule_applies(*r, dialect_) || (close_ && !rule_applies(*r, *close_))))
        return;
    if (quiet_ && !is_bad_frame(f.code)) return;
    if (options_.strict && f.code == Errc::blank_frame) f.severity = Severity::error;
    ++counts_[static_cast<int>(f.severity)];
    ++by_rule_[f.id()];
    std::vector<Kept>& list = kept_[f.id()];
    Kept k{std::move(f), arrived_++};
    if (!options_.max_per_rule || list.size() < options_.max_per_rule) {
        list.push_back(std::move(k));
        std::push_heap(list.begin(), list.end());
        return;
    }
    ++unlisted_[k.finding.id()];
    if (!(k < list.front())) return;
    std::pop_heap(list.begin(), list.end());  // the last by position makes room
    list.back() = std::move(k);
    std::push_heap(list.begin(), list.end());
}

// On a tape the frame orders: a bad frame's byte is in the image, a finding's in the decoded text.
bool LintVisitor::Kept::operator<(const Kept& o) const {
    auto key = [](const Kept& k) {
        return std::tuple(k.finding.where.frame.value_or(0), k.finding.where.byte.value_or(0), k.arrived);
    };
    return key(*this) < key(o);
}

void LintVisitor::end(const Location& where) {
    (void)where;
    close_program();
    if (!any_program_)
        add(sink_, "no-program", Location{.offset = 0, .line = 1, .column = 1}, 0,
            "no '%' program start on the tape: all of it is label, which a controller skips (§1.4)");
}

void LintVisitor::close_program() {
    if (!in_program_) return;
    in_program_ = false;
    if (program_blocks_ == 0) add(sink_, "program-start", program_start_, 0, "'%' is not followed by a block (§1.4)");
    if (no_feed_ && !subprogram_) keep(*no_feed_);
    no_feed_.reset();
    if (after_end_at_)
        add(sink_, "after-end", *after_end_at_, 0, "text after M02/M30 is not part of the program (§1.9)");
    for (const auto& o : open_) report_unclosed(o);
    open_.clear();
    targets_->close(sink_);
    if (options_.machine)
        machine_program_checks();
    else
        for (const auto& b : held_) spec_checks(sink_, *options_.spec, b, {program_points_, dialect_, close_});
    held_.clear();
}

// The machine's word format, mode by mode, and its own checks (a profile without a format has only these).
void LintVisitor::machine_program_checks() {
    const MachineProfile& m = *options_.machine;
    machine_format_->program_start();
    for (const auto& b : held_) {
        const FormatSpec& s = machine_format_->block(b);
        if (!m.format.words.empty())
            spec_checks(sink_, s, b, {program_points_, dialect_, close_, machine_format_.get()});
        machine_checks(m, b, sink_);
    }
}

std::vector<Finding> LintVisitor::findings() const {
    std::vector<Kept> all;
    for (const auto& [rule, list] : kept_) all.insert(all.end(), list.begin(), list.end());
    std::sort(all.begin(), all.end());
    std::vector<Finding> sorted;
    sorted.reserve(all.size());
    for (auto& k : all) sorted.push_back(std::move(k.finding));
    return sorted;
}

std::vector<Finding> lint(const LoadedTape& tape, const LintOptions& options) {
    // The tape loaded whole is given to the streaming checks as the loader would give it.
    LintVisitor v(options);
    v.dialect(DialectChoice{tape.dialect, {}});
    for (const auto& f : tape.findings) v.finding(f);
    for (const auto& p : tape.programs) {
        v.program_start(p);
        for (const auto& b : p.blocks) v.block(b);
        if (p.after_end_at) v.after_end(p.after_end, *p.after_end_at);
    }
    v.end(tape.locate(tape.text.size()));
    return v.findings();
}

}  // namespace tape
