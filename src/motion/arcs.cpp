// G02/G03: the arc's centre from I/J/K (from the start, or absolute after LinuxCNC's G90.1) or from R
// (negative: the long way), checked as the control checks it, and the move with its helix and turns.
// The plane's axes (u, v) are ordered so that u × v points along the normal: XY → Z, ZX → Y, YZ → X.
// So counter-clockwise in (u, v) is counter-clockwise seen from the normal's positive end, which is
// how ГОСТ 20999-83 table 4 and every control define G03 — in G18 too, seen from +Y, where viewers
// that draw X across and Z up turn every arc the wrong way (CAMotics#96, UGS#853).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "motion/machine.hpp"

namespace tape {

using namespace motion;

namespace {

struct Axes {
    int u, v, w;
    char cu, cv;  // the centre words of u and v
};

double& at(Point& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }
double at(const Point& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }

// The seeds' controller (manual excerpt §4.3) names the centre by the plane's first and second axes
// with I and J in every plane: in Z-X, I is along Z and J along X. ISO 6983 and the other dialects use
// the letter of the axis (K for Z, I for X). A ГОСТ block that writes K (G18) or I (G19) is read the ISO
// way, as neither is a word of the other reading.
Axes plane_axes(Plane p, Dialect d, const BlockWords& w) {
    bool first_second = d == Dialect::gost;
    switch (p) {
        case Plane::zx:
            if (first_second && !w.has('K')) return {2, 0, 1, 'I', 'J'};
            return {2, 0, 1, 'K', 'I'};
        case Plane::yz:
            if (first_second && w.has('I') && !w.has('K')) return {1, 2, 0, 'I', 'J'};
            return {1, 2, 0, 'J', 'K'};
        default:
            return {0, 1, 2, 'I', 'J'};
    }
}

std::string mm(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4f", v);
    return b;
}

}  // namespace

// Whether the block gives the arc a centre the interpreter can read (cu, cv: its centre words); where not,
// the block is named as not simulated and the tool is taken to its end point, as far as that is known.
bool MotionMachine::arc_defined(bool by_r, char cu, char cv, const Point& end, unsigned end_known) {
    for (char c : {by_r ? 'R' : cu, by_r ? 'R' : cv}) {
        if (!w_.has(c) || w_.ok(c)) continue;
        const Word& word = *w_.word_of(c);
        std::string why = w_.at(c) == ValueState::macro ? " is a macro value, known only when the program runs"
                          : w_.at(c) == ValueState::unscaled
                              ? " has no decimal point and the program has written none so far (ГОСТ 20999-83 §3.1.3)"
                              : " holds no value a control reads";
        not_simulated("the arc's " + word.text + why + ": not simulated", 0);
        mv_.end = end;
        pos = end;
        known = end_known;
        return false;
    }
    if (!by_r && !w_.has(cu) && !w_.has(cv)) {
        // No centre and no radius (lint's arc-center): the control stops; nothing to draw.
        not_simulated("G0" + std::to_string(group01_) + " with no centre (" + cu + ", " + cv +
                          ") and no R: the control stops here",
                      0);
        pos = end;
        known = end_known;
        return false;
    }
    return true;
}

void MotionMachine::arc(const Point& end, unsigned end_known) {
    Axes ax = plane_axes(st.plane, dialect_, w_);
    bool cw = group01_ == 2;
    bool by_r = w_.has('R') && !(w_.has(ax.cu) || w_.has(ax.cv)) ? true : w_.has('R') && dialect_ != Dialect::linuxcnc;
    if (!arc_defined(by_r, ax.cu, ax.cv, end, end_known)) return;
    begin(MoveKind::arc);
    mv_.end = end;
    mv_.end_known = end_known;
    mv_.clockwise = cw;
    unsigned plane_bits = (1u << ax.u) | (1u << ax.v);
    double s = scale();
    double su = at(pos, ax.u), sv = at(pos, ax.v), eu = at(end, ax.u), ev = at(end, ax.v);
    bool ends_known = (known & plane_bits) == plane_bits && (end_known & plane_bits) == plane_bits;
    double cu = 0, cv = 0;
    if (by_r) {
        double r = w_.get('R') * s;
        if (!ends_known || !std::isfinite(r)) {
            mv_.radius = mv_.end_radius = std::fabs(r);
            emit();
            pos = end, known = end_known;
            return;
        }
        double half = std::hypot(eu - su, ev - sv) / 2;
        if (half < 1e-9) {
            full_circle_by_r(r);
            return;
        }
        centre_by_r(r, half, su, sv, eu, ev, ax.v == 0, cw, plane_bits, cu, cv);
    } else {
        double iu = w_.ok(ax.cu) ? w_.get(ax.cu) * s : 0, iv = w_.ok(ax.cv) ? w_.get(ax.cv) * s : 0;
        bool incremental = st.arc_incremental;
        if (incremental && (known & plane_bits) != plane_bits) {
            emit();  // centre and start unknown: the arc cannot be placed
            pos = end, known = end_known;
            return;
        }
        cu = incremental ? su + iu : iu;
        cv = incremental ? sv + iv : iv;
    }
    at(mv_.centre, ax.u) = cu;
    at(mv_.centre, ax.v) = cv;
    at(mv_.centre, ax.w) = at(pos, ax.w);
    mv_.radius = std::hypot(su - cu, sv - cv);
    mv_.end_radius = std::hypot(eu - cu, ev - cv);
    bool closed = std::hypot(eu - su, ev - sv) < 1e-9;
    int p = w_.ok('P') && dialect_ == Dialect::linuxcnc ? static_cast<int>(std::clamp(w_.get('P'), 1.0, 1e6)) : 1;
    mv_.turns = p - 1 + (closed && !by_r ? 1 : 0);
    note_iso_centre(by_r, ax.cu);
    if (ends_known && !by_r && checkable_arc(plane_bits, ax.cu, ax.cv)) check_arc(ax.u, ax.v);
    emit();
    pos = end;
    known = end_known;
}

// G02/G03 by R ending where it starts: every circle through the point has that radius.
void MotionMachine::full_circle_by_r(double r) {
    finding("arc-full-circle-r", "G0" + std::to_string(group01_) + " by R" + mm(r) +
                                     " ends where it starts: a full circle by R has no one centre (the control "
                                     "alarms); give it by I, J, K");
    begin(MoveKind::not_simulated);
    mv_.note = "a full circle by R: its centre is not known";
    emit();
}

// A ГОСТ Z-X arc centred by I alone (cu_word 'I'): the centre of the ISO 6983 reading, I along X, kept
// for the arc check beside the seeds' reading in mv_.centre.
void MotionMachine::note_iso_centre(bool by_r, char cu_word) {
    iso_centre_.reset();
    if (dialect_ != Dialect::gost || st.plane != Plane::zx || by_r || !st.arc_incremental || cu_word != 'I' ||
        w_.has('J') || !w_.ok('I'))
        return;
    iso_centre_ = mv_.centre;
    iso_centre_->z = pos.z;
    iso_centre_->x = pos.x + w_.get('I') * scale();
}

// The centre of an R arc from start (su, sv) to end (eu, ev), half the chord apart: on the right of the
// chord for a clockwise arc of up to a half turn, the other side for a negative R. An R shorter than half
// the chord is a finding, and the arc is drawn as the half circle.
void MotionMachine::centre_by_r(double r, double half, double su, double sv, double eu, double ev, bool v_is_x, bool cw,
                                unsigned plane_bits, double& cu, double& cv) {
    double ar = std::fabs(r);
    // X may be a lathe's diameter (lint, not knowing the machine): the chord with X halved.
    double half_d = v_is_x ? std::hypot(eu - su, (ev - sv) / 2) / 2 : half;
    bool short_either = !(opt_.lathe_unknown && st.plane == Plane::zx && half_d - ar <= opt_.arc_tolerance_mm);
    if (half - ar > opt_.arc_tolerance_mm && short_either && checkable_arc(plane_bits, 'R', 'R'))
        finding("arc-radius-short", "R" + mm(r) + " is shorter than half the chord (" + mm(half) +
                                        " mm): no arc of that radius reaches the end point (the control alarms)");
    if (half > ar) ar = half;
    double h = std::sqrt(std::max(0.0, ar * ar - half * half));
    // Right of the chord for a clockwise arc of up to a half turn; R < 0 takes the other side.
    double side = (cw == (r > 0)) ? -1 : 1;
    double tu = (eu - su) / (2 * half), tv = (ev - sv) / (2 * half);
    cu = (su + eu) / 2 - tv * h * side;
    cv = (sv + ev) / 2 + tu * h * side;
}

}  // namespace tape
