// Canned cycles expanded into their moves (depth 1): drilling G73/G81-G89 in G17 with G98/G99 (Fanuc
// and LinuxCNC manuals: initial level, R level, bottom; G91 takes R from the initial level and Z from
// R), and a Fanuc lathe's single cycles G90 (turning), G92 (thread) and G94 (facing).
#include <algorithm>
#include <cmath>

#include "motion/machine.hpp"

namespace tape {

using namespace motion;

// One move of a cycle.
void MotionMachine::leg(MoveKind kind, const Point& to, unsigned to_known) {
    begin(kind);
    mv_.depth = 1;
    mv_.end = to;
    mv_.end_known = to_known;
    emit();
    pos = to;
    known = to_known;
}

// A cycle's word in mm: false (said) when the block gives it in a way that cannot be read.
bool MotionMachine::cycle_value(char letter, double& value) {
    if (!w_.has(letter)) return true;
    if (!w_.ok(letter)) {
        not_simulated("the cycle's " + w_.word_of(letter)->text + " cannot be read: the cycle is not simulated",
                      all_axes);
        return false;
    }
    value = w_.get(letter) * scale();
    return true;
}

void MotionMachine::drill_cycle(const Point& end, unsigned end_known, unsigned named) {
    if (st.plane != Plane::xy) {
        not_simulated("a canned cycle (G" + std::to_string(cycle_) + ") outside the XY plane is not simulated",
                      all_axes);
        return;
    }
    double r = cycle_r_, z = cycle_z_, q = cycle_q_;
    if (!cycle_value('R', r) || !cycle_value('Z', z) || !cycle_value('Q', q)) return;
    if (w_.has('R')) cycle_r_ = r, cycle_r_ok_ = true;
    if (w_.has('Z')) cycle_z_ = z, cycle_z_ok_ = true;
    if (w_.has('Q')) cycle_q_ = q;
    if (w_.ok('P')) cycle_p_ = w_.get('P');
    int repeat = 1;
    char count = w_.ok('K') ? 'K' : w_.ok('L') ? 'L' : 0;
    if (count) repeat = static_cast<int>(std::clamp(w_.get(count), 0.0, 1e6));
    if (!cycle_r_ok_ || !cycle_z_ok_) {
        not_simulated("a canned cycle without its R or Z level: the control stops here", all_axes);
        return;
    }
    // G91: R from the initial level, Z from R.
    bool inc = st.incremental;
    double r_level = inc ? initial_z_ + cycle_r_ : cycle_r_;
    double bottom = inc ? r_level + cycle_z_ : cycle_z_;
    bool z_known = inc ? initial_known_ : true;
    unsigned zbit = z_known ? unsigned(axis_z) : 0u;
    double pecks = peck_count(r_level, bottom);
    // A hole: over it, to R, each peck (G83: down, up to R, back), the bottom, a dwell, out, up.
    if (!expansion_allowed(std::max(repeat, 1) * (6 + 3 * pecks))) return;
    Point step{end.x - pos.x, end.y - pos.y, 0};
    for (int hole = 0; hole < repeat; ++hole) {
        Point at = pos;
        unsigned k = known;
        if (named & (axis_x | axis_y)) {
            if (hole == 0)
                at.x = end.x, at.y = end.y, k = (k & ~(axis_x | axis_y)) | (end_known & (axis_x | axis_y));
            else if (inc)
                at.x += step.x, at.y += step.y;
            leg(MoveKind::rapid, at, k);
        }
        drill_hole(at, r_level, bottom, zbit, static_cast<int>(pecks));
    }
}

// G73/G83's pecks above the bottom: one every Q from R down, the last one short of the bottom.
double MotionMachine::peck_count(double r_level, double bottom) const {
    double q_mm = std::fabs(cycle_q_);
    if ((cycle_ != 83 && cycle_ != 73) || !(q_mm > 0) || !(r_level - bottom > q_mm)) return 0;
    return std::ceil((r_level - bottom) / q_mm) - 1;
}

// The moves cycles expand into are bounded, by cycle and by program (hostile repeat counts and peck
// depths): past the bound a cycle is named, not drawn.
bool MotionMachine::expansion_allowed(double moves) {
    constexpr double max_per_cycle = 100'000, max_per_program = 10'000'000;
    if (moves <= max_per_cycle && expanded_ + moves <= max_per_program) {
        expanded_ += moves;
        return true;
    }
    not_simulated(moves > max_per_cycle
                      ? "a cycle of more than 100 000 moves (its repeats, pecks or passes) is not drawn"
                      : "more than 10 million moves drawn from this program's cycles: the cycle is not drawn",
                  all_axes);
    return false;
}

void MotionMachine::lathe_cycle(int code, Point end, unsigned end_known, unsigned named) {
    unsigned xz = axis_x | axis_z;
    // The cycle's X and Z are kept from block to block: "G92 X.. Z.. F..", then "X.." for the next pass.
    if (!(named & axis_x) && (lathe_named_ & axis_x))
        end.x = lathe_end_.x, end_known = (end_known & ~axis_x) | (lathe_end_known_ & axis_x);
    if (!(named & axis_z) && (lathe_named_ & axis_z))
        end.z = lathe_end_.z, end_known = (end_known & ~axis_z) | (lathe_end_known_ & axis_z);
    lathe_end_ = end;
    lathe_end_known_ = end_known;
    lathe_named_ |= named;
    if ((known & xz) != xz || (end_known & xz) != xz) {
        not_simulated("G" + std::to_string(code) + " from a place not known: the cycle is not simulated", xz);
        return;
    }
    double taper = 0;
    if (!cycle_value('R', taper)) return;
    Point s = pos, a = pos, b = end, c = pos;
    MoveKind cut = MoveKind::linear;
    if (code == 94) {  // facing: Z in, X across, Z out, X back
        a.z = end.z + taper;
        b = Point{end.x, pos.y, end.z};
        leg(MoveKind::rapid, a, known);
        leg(cut, b, known);
        c = Point{end.x, pos.y, s.z};
        leg(cut, c, known);
    } else {  // G90 turning, G92 thread: X in, Z along, X out, Z back
        a.x = end.x + taper;
        leg(MoveKind::rapid, a, known);
        leg(cut, Point{end.x, pos.y, end.z}, known);
        c = Point{s.x, pos.y, end.z};
        leg(code == 92 ? MoveKind::rapid : cut, c, known);
    }
    leg(MoveKind::rapid, s, known);
}

// One hole of a drilling cycle, the tool over it: down to R, pecks, the bottom, a dwell, back up.
void MotionMachine::drill_hole(Point at, double r_level, double bottom, unsigned zbit, int pecks) {
    at.z = r_level;
    leg(MoveKind::rapid, at, (known & ~axis_z) | zbit);
    double q_mm = std::fabs(cycle_q_);
    for (int n = 1; n <= pecks; ++n) {
        // Counted, not stepped: a step below the depth's rounding would never reach the bottom.
        double depth = r_level - n * q_mm;
        at.z = depth;
        leg(MoveKind::linear, at, known);
        if (cycle_ == 83) {
            at.z = r_level;
            leg(MoveKind::rapid, at, known);
            at.z = depth;
            leg(MoveKind::rapid, at, known);
        }
    }
    at.z = bottom;
    leg(MoveKind::linear, at, known);
    if (cycle_ == 82 || cycle_ == 89 || cycle_ == 88) {
        begin(MoveKind::dwell);
        mv_.depth = 1;
        double s = cycle_p_ / (dialect_ == Dialect::fanuc ? 1000 : 1);
        mv_.seconds = std::isfinite(s) && s > 0 ? s : 0;
        emit();
    }
    bool feed_out = cycle_ == 84 || cycle_ == 74 || cycle_ == 85 || cycle_ == 89;
    double top = st.retract_to_r ? r_level : initial_z_;
    unsigned top_known = st.retract_to_r ? zbit : (initial_known_ ? unsigned(axis_z) : 0u);
    if (feed_out) {
        at.z = r_level;
        leg(MoveKind::linear, at, (known & ~axis_z) | zbit);
    }
    if (!feed_out || top != r_level) {
        at.z = top;
        leg(MoveKind::rapid, at, (known & ~axis_z) | top_known);
    }
}

}  // namespace tape
