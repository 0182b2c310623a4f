// Figures of a program (tape/motion_stats.hpp).
#include "tape/motion_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "toolpath/arc.hpp"

namespace tape {
namespace {

// The least and most of the axes known.
void extend(ToolFigures& t, const Point& p, unsigned known) {
    for (auto [bit, value, lo, hi] :
         {std::tuple{axis_x, p.x, &t.min.x, &t.max.x}, std::tuple{axis_y, p.y, &t.min.y, &t.max.y},
          std::tuple{axis_z, p.z, &t.min.z, &t.max.z}}) {
        if (!(known & bit)) continue;
        if (!(t.axes & bit)) *lo = *hi = value;
        *lo = std::min(*lo, value);
        *hi = std::max(*hi, value);
        t.axes |= bit;
    }
    t.any = t.axes != 0;
}

// An arc reaches past its ends where it crosses the plane's axes: those quarter points count too.
void extend_arc(ToolFigures& t, const Move& m) {
    arcs::Sweep w = arcs::sweep_of(m.start, m.end, m.centre, m.state.plane, m.clockwise, m.turns);
    double quarter = std::numbers::pi / 2, lo = std::min(w.start, w.start + w.sweep),
           hi = std::max(w.start, w.start + w.sweep);
    for (double k = std::ceil(lo / quarter); k * quarter <= hi && k - std::ceil(lo / quarter) < 4; ++k)
        extend(t, arcs::point_at(w, m.start, m.end, m.centre, m.state.plane, (k * quarter - w.start) / w.sweep),
               m.known);
}

// The feed in mm/min of a move, 0 when not known (per revolution without a speed; constant surface
// speed where the tool is on the axis).
double feed_mm_per_min(const Move& m) {
    const ModalState& s = m.state;
    if (!s.feed_per_rev) return s.feed;
    double rpm = s.speed;
    if (s.constant_surface) {
        double radius = (std::abs(m.start.x) + std::abs(m.end.x)) / 2;  // a lathe's x is a radius
        rpm = radius > 0.5 ? s.speed * 1000 / (2 * std::numbers::pi * radius) : 0;
    }
    return s.feed * rpm;
}

void add_move(ToolFigures& t, const Move& m, double rapid_rate) {
    ++t.moves;
    double length = m.length();
    if (m.kind == MoveKind::rapid) {
        t.rapid_mm += length;
        if (rapid_rate > 0) t.rapid_min += length / rapid_rate;
    } else {
        t.cutting_mm += length;
        if (double feed = feed_mm_per_min(m); feed > 0)
            t.cutting_min += length / feed;
        else if (length > 0)
            ++t.untimed;
    }
    extend(t, m.start, m.known);
    extend(t, m.end, m.known);
    if (m.kind == MoveKind::arc) extend_arc(t, m);
}

}  // namespace

ToolFigures& MotionStats::of(int tool) {
    for (auto& t : f_.tools)
        if (t.tool == tool) return t;
    f_.tools.push_back(ToolFigures{.tool = tool});
    return f_.tools.back();
}

void MotionStats::move(const Move& m) {
    switch (m.kind) {
        case MoveKind::not_simulated:
            ++f_.not_simulated;
            return;
        case MoveKind::dwell:
            of(m.state.tool).dwell_min += m.seconds / 60;
            f_.total.dwell_min += m.seconds / 60;
            return;
        case MoveKind::rapid:
        case MoveKind::linear:
        case MoveKind::arc:
            break;
        default:
            return;
    }
    // From a place not known the length is not known either: the program's first move (no axis known),
    // or a move after an axis was lost (a block not simulated). An axis never set (a lathe's Y) never
    // moved: the move is measured without it.
    unsigned known = m.known & all_axes, ever = ever_known_;
    ever_known_ |= known;
    if (known == 0 || (known | (all_axes & ~ever)) != all_axes) {
        ++f_.unknown;
        return;
    }
    add_move(of(m.state.tool), m, rapid_);
    f_.total.tool = -1;
    add_move(f_.total, m, rapid_);
}

}  // namespace tape
