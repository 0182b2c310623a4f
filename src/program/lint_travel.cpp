#include "program/lint_travel.hpp"

#include <cstdio>

#include "tape/code_tables.hpp"

namespace tape::lint_detail {
namespace {

// The axis of the profile whose travel is checked for the interpreter's axis i (X, Y, Z), or nullptr.
const MachineAxis* travel_axis(const MachineProfile& m, int i) {
    const MachineAxis* a = m.find_axis("XYZ"[i]);
    return a && a->min_mm && a->max_mm && a->mm_per_pulse == 0 ? a : nullptr;
}

// A block that can move the program's zero or the tool's length against the machine: a work offset or a
// coordinate setting (G10, G50, G52-G59, G92 and their variants), a tool, length or radius compensation
// (G40-G49), the tool itself and its offset words (T, H, D, L, M06), or a macro statement (Fanuc's
// #5221 is G54's X). Wider than any one dialect needs: a reset only costs a finding, never makes one.
bool moves_the_frame(const Block& b) {
    if (!b.statements.empty()) return true;
    for (const auto& w : b.words) {
        if (!w.known) continue;
        if (w.address == 'T' || w.address == 'H' || w.address == 'D' || w.address == 'L') return true;
        auto v = w.integer();
        if (w.address == 'M' && v && *v % 100 == 6) return true;
        if (w.address != 'G') continue;
        std::string code = code_value(std::string_view(w.text).substr(1));  // "54.1": G54.1 is of G54's kind
        if (w.macro || code.empty()) return true;
        int whole = code[0] == '.' ? 0 : std::stoi(code.substr(0, code.find('.')));
        if (whole == 10 || whole == 50 || whole == 92 || (whole >= 40 && whole <= 59)) return true;
    }
    return false;
}

std::string mm(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.3f", v);
    return s;
}

}  // namespace

bool TravelChecks::applies(const MachineProfile& m) {
    for (int i = 0; i < 3; ++i)
        if (travel_axis(m, i)) return true;
    return false;
}

MotionOptions TravelChecks::options_for(const MachineProfile& m, Dialect dialect) {
    MotionOptions o = motion_options(m, dialect);
    // X read as a diameter where the profile only guesses: the smaller span, never a false one.
    auto d = m.sources.find("diameter_programming");
    if (o.lathe && (d == m.sources.end() || d->second.starts_with("guess"))) o.diameter = true;
    o.follow_subprograms = false;
    return o;
}

TravelChecks::TravelChecks(const MachineProfile& m, Dialect dialect, std::function<void(Finding)> sink)
    : m_(&m), sink_(std::move(sink)), options_(options_for(m, dialect)), in_(*this, options_) {
    for (int i = 0; i < 3; ++i) axes_[static_cast<std::size_t>(i)] = travel_axis(m, i);
    in_.dialect(DialectChoice{dialect, {}, {}});
}

void TravelChecks::start(const Program& header) {
    reset();
    ends_.clear();
    stopped_ = compensated_ = false;
    in_.program_start(header);
}

void TravelChecks::next(const Block& b) {
    // With the block-skip switch on, a '/' block does not run, and every point after it that the
    // interpreter reckons from it (incremental words) is another: not followed on.
    if (b.skip) stopped_ = true;
    if (moves_the_frame(b)) {
        reset();
        for (const auto& w : b.words)
            if (w.address == 'G' && w.known && !w.has_point())
                if (auto g = w.integer(); g && *g >= 40 && *g <= 42) compensated_ = *g != 40;
    }
    ends_.clear();
    in_.block(b);
    // An axis written as an absolute X, Y or Z is the program's own again from this block on.
    if (!in_.state().incremental)
        for (const auto& w : b.words)
            if (auto i = std::string_view("XYZ").find(w.address); i != std::string_view::npos && w.known && !w.macro)
                stale_[i] = false;
    if (!stopped_ && !compensated_)
        for (const auto& e : ends_) take(e);
}

void TravelChecks::move(const Move& mv) {
    if (mv.kind == MoveKind::not_simulated) stopped_ = true;
    if (mv.kind == MoveKind::rapid || mv.kind == MoveKind::linear || mv.kind == MoveKind::arc)
        ends_.push_back(End{mv.end, mv.known, mv.end_known, mv.block, mv.where});
}

void TravelChecks::take(const End& e) {
    for (std::size_t i = 0; i < 3; ++i) {
        unsigned bit = 1u << i;
        if (!(e.known & bit)) spans_[i] = {};  // from a place not known: perhaps another zero
        if (axes_[i] && !stale_[i] && (e.end_known & bit))
            note(static_cast<int>(i), i == 0 ? e.at.x : i == 1 ? e.at.y : e.at.z, e);
    }
}

// One more point of axis i; a finding when the points seen since the last reset are farther apart than
// the axis travels (then the span starts again at this point, so that each excursion is said once).
void TravelChecks::note(int i, double at, const End& e) {
    Span& s = spans_[static_cast<std::size_t>(i)];
    Seen here{at, e.block};
    if (!s.low || at < s.low->at) s.low = here;
    if (!s.high || at > s.high->at) s.high = here;
    const MachineAxis& a = *axes_[static_cast<std::size_t>(i)];
    double travel = *a.max_mm - *a.min_mm, apart = s.high->at - s.low->at;
    if (apart <= travel + 1e-6) return;
    const Seen& other = s.low->block == e.block ? *s.high : *s.low;
    std::string axis(1, a.name), radius = options_.lathe && i == 0 ? " (as a radius)" : "";
    sink_(program_finding("machine-travel", e.where, e.block,
                          axis + " goes to " + mm(at) + radius + " here and to " + mm(other.at) + " in block " +
                              std::to_string(other.block) + ", " + mm(apart) + " mm apart; " + m_->title + "'s " +
                              axis + " travels " + mm(travel) + " mm (" + mm(*a.min_mm) + " to " + mm(*a.max_mm) +
                              ", " + a.source + "): one of them is outside it, wherever the work offset puts zero"));
    s = Span{here, here};
}

}  // namespace tape::lint_detail
