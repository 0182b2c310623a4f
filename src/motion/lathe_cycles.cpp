// A Fanuc (and Haas) lathe's multiple repetitive cycles (Fanuc lathe G-code system A; Haas lathes read
// them alike):
// - G71/G72/G73 P(ns) Q(nf) U(Δu) W(Δw): roughing to the finishing contour of blocks N(ns)..N(nf). Both
//   Fanuc forms: two blocks (G71 U(Δd) R(e) first, whose words are the passes' depth and retract) and the
//   one block of the 0/6 controls and Haas (G71 P Q U W D F). The roughing passes are not drawn; the
//   contour is, where roughing leaves it (shifted by Δu/2 in X and Δw in Z), then the rapid return to the
//   start point. The contour blocks follow the cycle block: they are drawn as the cycle's moves (depth
//   1), not run a second time, and the modal state of the cycle is back in force after N(nf) (the
//   control goes on after nf; F, S and T in the contour count only for G70).
// - G70 P Q: the finishing pass along a contour drawn before (or following it), then back to the start.
// - G76: a thread in passes, two blocks (G76 P(m)(r)(a) Q(Δdmin) R(d), then G76 X Z R(i) P(k) Q(Δd)
//   F(L)) or one (G76 X Z I(i) K(k) D(Δd) F(L) A(a)). The passes go straight in X: the tool angle's
//   shift of each pass along Z and the end chamfer are not drawn.
// A P or Q that names no block where the contour should be is said at the cycle's block.
#include <algorithm>
#include <cmath>
#include <utility>

#include "motion/machine.hpp"

namespace tape {

using namespace motion;

namespace motion {

std::vector<double> thread_depths(double height, double first, double min_cut, double allowance, int finish_passes,
                                  std::size_t max_passes) {
    std::vector<double> out;
    bool sane = std::isfinite(height) && std::isfinite(first) && height > 0 && first > 0 && allowance >= 0 &&
                allowance < height && min_cut >= 0 && finish_passes >= 0;
    double rough_to = height - allowance;
    // Decimal depths in binary: a pass that reaches the depth but for rounding reaches it (K4. D1. makes
    // 16 passes, not a 17th of 1e-16), and a count of passes of exactly max_passes is not over it.
    double slack = rough_to * 1e-9;
    double passes = (rough_to / first) * (rough_to / first);
    if (!sane || passes > static_cast<double>(max_passes) * (1 + 1e-9)) return out;
    double before = 0;
    for (int n = 1; before < rough_to; ++n) {
        double depth = std::max(first * std::sqrt(static_cast<double>(n)), before + min_cut);
        before = depth >= rough_to - slack ? rough_to : depth;
        out.push_back(before);
    }
    for (int i = 0; i < finish_passes; ++i) out.push_back(height);
    return out;
}

}  // namespace motion

namespace {

std::optional<long long> block_sequence(const Block& b) { return b.number ? b.number->integer() : std::nullopt; }

std::string cycle_name(int code, long long p, long long q) {
    return "G" + std::to_string(code) + " P" + std::to_string(p) + " Q" + std::to_string(q);
}

}  // namespace

// A block of G70-G73 or G76.
void MotionMachine::repetitive_cycle() {
    if (lathe_.open) {
        not_simulated(g_name(once_) + " inside the contour of " + lathe_.open->name + ": the control stops (alarm)",
                      all_axes);
        return;
    }
    if (once_ == 760) return thread_cycle();
    contour_cycle();
}

// A cycle's word in mm (increment: a P or D without a point counts the least input increment, as a
// length word does); false, said, when it cannot be read; value unchanged when absent.
bool MotionMachine::lathe_word(char letter, double& value, bool increment) {
    if (!w_.has(letter)) return true;
    if (!w_.ok(letter)) {
        not_simulated(g_name(once_) + "'s " + w_.word_of(letter)->text + " cannot be read: the cycle is not simulated",
                      all_axes);
        return false;
    }
    double v = w_.get(letter);
    if (increment && !w_.word_of(letter)->has_point() && !w_.scaled(letter)) v *= st.inch ? 0.0001 : 0.001;
    value = v * scale();
    return true;
}

void MotionMachine::contour_cycle() {
    int code = once_ / 10;
    if (!w_.has('P') && !w_.has('Q')) return;  // G71 U(Δd) R(e): the roughing passes' depth, not drawn
    // Plain numbers, not optionals: GCC 12 takes an optional read after its test for uninitialized.
    long long p = 0, q = 0;
    auto sequence = [this](char letter, long long& out) {
        const Word* w = w_.word_of(letter);
        auto v = w ? w->integer() : std::nullopt;
        if (v) out = *v;
        return v.has_value();
    };
    if (!sequence('P', p) || !sequence('Q', q)) {
        not_simulated(g_name(once_) +
                          ": the contour's first and last blocks (P and Q) are not both given as sequence numbers: "
                          "the cycle is not simulated",
                      all_axes);
        return;
    }
    if (code == 70)
        for (const auto& c : lathe_.done)
            if (c.p == p && c.q == q) return contour_replay(c);
    OpenContour o;
    o.code = code;
    o.p = p;
    o.q = q;
    o.start = o.at = pos;
    o.start_known = known;
    double du = 0, dw = 0;
    if (code != 70 && (!lathe_word('U', du, false) || !lathe_word('W', dw, false))) return;
    o.shift = Point{st.diameter ? du / 2 : du, 0, dw};
    o.state = st;
    o.group01 = group01_;
    o.block = block_->ordinal;
    o.where = block_->where;
    o.name = cycle_name(code, p, q);
    o.recorded.p = p;
    o.recorded.q = q;
    lathe_.open = std::move(o);
}

// G70 along a contour drawn before: its moves again, from where the tool stands, then back.
void MotionMachine::contour_replay(const Contour& c) {
    Point start = pos;
    unsigned start_known = known;
    if (opt_.findings_only) return;  // the tool ends where it started
    if (!expansion_allowed(static_cast<double>(c.moves.size()) + 1)) return;
    for (std::size_t i = 0; i < c.moves.size(); ++i) {
        mv_ = c.moves[i];
        if (i == 0) mv_.start = start, mv_.known = start_known;
        mv_.block = block_->ordinal;
        mv_.where = block_->where;
        mv_.last_frame.reset();
        mv_.depth = 1;
        mv_.state.tool = st.tool;
        pos = mv_.end;
        known = mv_.end_known;
        emit();
    }
    leg(MoveKind::rapid, start, start_known);
}

// Before a block while a cycle waits for its contour: the contour starts here, or is not where it
// should be (said at the cycle's block). A block of nothing but comments changes nothing.
bool MotionMachine::contour_before(const Block& b) {
    OpenContour& o = *lathe_.open;
    if (o.drawing) return true;
    auto n = block_sequence(b);
    if (n && *n == o.p) {
        o.drawing = true;
        return true;
    }
    if (!n && b.words.empty() && b.statements.empty() && !b.ends_program()) return false;
    contour_lost(false);
    return false;
}

// After a block of the contour: at N(nf) the return to the start point and the cycle's modal state.
void MotionMachine::contour_after(const Block& b) {
    if (!lathe_.open) return;  // a block of the contour stopped it (said there)
    auto n = block_sequence(b);
    bool last = n && *n == lathe_.open->q;
    if (!last && !b.ends_program()) return;
    st = lathe_.open->state;
    group01_ = lathe_.open->group01;
    if (!last) return contour_lost(true);
    OpenContour o = std::move(*lathe_.open);
    lathe_.open.reset();
    pos = o.at;
    leg(MoveKind::rapid, o.start, o.start_known);
    if (lathe_.done.size() == LatheCycles::max_contours ||
        lathe_.recorded_moves + o.recorded.moves.size() > LatheCycles::max_moves)
        return;  // a G70 of it is said as not simulated
    lathe_.recorded_moves += o.recorded.moves.size();
    lathe_.done.push_back(std::move(o.recorded));
}

// A move of a contour being drawn: kept for G70, shifted by a roughing cycle's allowance, at depth 1.
// Events (F, S, T and M codes count only for the finishing pass) are not drawn.
bool MotionMachine::contour_move() {
    OpenContour& o = *lathe_.open;
    if (mv_.kind != MoveKind::rapid && mv_.kind != MoveKind::linear && mv_.kind != MoveKind::arc)
        return mv_.kind != MoveKind::not_simulated && mv_.kind != MoveKind::program_end;
    mv_.depth = 1;
    if (!opt_.findings_only && lathe_.recorded_moves + o.recorded.moves.size() < LatheCycles::max_moves)
        o.recorded.moves.push_back(mv_);
    auto shifted = [&](Point p) { return Point{p.x + o.shift.x, p.y, p.z + o.shift.z}; };
    if (!o.first) mv_.start = shifted(mv_.start);
    mv_.end = shifted(mv_.end);
    mv_.centre = shifted(mv_.centre);
    mv_.state.feed = o.state.feed;
    mv_.state.tool = o.state.tool;
    o.first = false;
    o.at = mv_.end;
    if (!opt_.findings_only) out_.move(mv_);
    return true;
}

// A cycle whose contour cannot be drawn: said at the cycle's block, the tool at the start point (ended:
// the text ends, and with it the program).
void MotionMachine::contour_lost(bool ended) {
    OpenContour o = std::move(*lathe_.open);
    lathe_.open.reset();
    if (ended) block_ = nullptr;
    std::string first = "block N" + std::to_string(o.p) + ", the contour's first";
    std::string why = !ended      ? first + ", is not the block after it"
                      : o.drawing ? "the program ends before block N" + std::to_string(o.q) + ", the contour's last"
                                  : "the program ends before " + first;
    begin(MoveKind::not_simulated);
    mv_.block = o.block;
    mv_.where = o.where;
    mv_.note = o.name + ": " + why + ": the cycle's contour is not simulated";
    emit();
}

// G76: the first block of the two-block form keeps its values; the others cut the thread.
void MotionMachine::thread_cycle() {
    bool axes = w_.has('X') || w_.has('Z') || w_.has('U') || w_.has('W');
    if (!axes) {  // G76 P(m)(r)(a) Q(Δdmin) R(d)
        if (w_.ok('P') && w_.get('P') >= 0 && w_.get('P') < 1e7)
            lathe_.finish_passes = std::max(1, static_cast<int>(w_.get('P')) / 10000);
        if (lathe_word('Q', lathe_.min_cut, true)) lathe_word('R', lathe_.allowance, false);
        return;
    }
    Point end;
    unsigned end_known, named_axes;
    if (!target(end, end_known, named_axes)) return;
    bool one = w_.has('K') || w_.has('D');  // G76 X Z I K D F A (0/6 controls, Haas)
    double height = 0, first = 0, taper = 0;
    if (!lathe_word(one ? 'K' : 'P', height, true) || !lathe_word(one ? 'D' : 'Q', first, true) ||
        !lathe_word(one ? 'I' : 'R', taper, false))
        return;
    // The one-block form's finishing allowance and minimum cut are the control's settings, not on tape.
    auto depths = one ? thread_depths(height, first, 0, 0, 0)
                      : thread_depths(height, first, lathe_.min_cut, lathe_.allowance, lathe_.finish_passes);
    unsigned xz = axis_x | axis_z;
    if (depths.empty() || (known & xz) != xz || (end_known & xz) != xz) {
        not_simulated(depths.empty() ? "G76 without a thread height and first cut that make passes (more than 10000 "
                                       "or none): the cycle is not simulated"
                                     : "G76 from a place not known: the cycle is not simulated",
                      xz);
        return;
    }
    if (expansion_allowed(4.0 * static_cast<double>(depths.size())))
        thread_passes(end, end_known, depths, height, taper);
}

// Each pass as G92's: X in to the pass's depth, the thread along Z at the feed, X out, Z back. X given
// is the root at the thread's end; the crest lies height from it, on the start point's side.
void MotionMachine::thread_passes(const Point& end, unsigned end_known, const std::vector<double>& depths,
                                  double height, double taper) {
    Point start = pos;
    double side = start.x >= end.x ? 1.0 : -1.0;  // outside thread: the start point above the root
    for (double depth : depths) {
        double x_end = end.x + side * (height - depth);
        leg(MoveKind::rapid, Point{x_end + taper, start.y, start.z}, known);
        leg(MoveKind::linear, Point{x_end, start.y, end.z}, known & end_known);
        leg(MoveKind::rapid, Point{start.x, start.y, end.z}, known);
        leg(MoveKind::rapid, start, known);
    }
}

}  // namespace tape
