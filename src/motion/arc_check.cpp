// An arc's end on its circle, to the control's tolerance (MotionOptions): the radius to the start and
// the radius to the end may differ by so much. Worded as LinuxCNC words its error, with both radii.
#include <cmath>
#include <cstdio>
#include <string>

#include "motion/machine.hpp"

namespace tape {

namespace {

double at(const Point& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }

std::string fixed(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4f", v);
    return b;
}

std::string point(const Point& p, int u, int v) {
    return std::string("(") + "XYZ"[u] + fixed(at(p, u)) + "," + "XYZ"[v] + fixed(at(p, v)) + ")";
}

}  // namespace

// Whether the arc's words can be checked: not a lathe's arc read in the mill's plane (lint, not knowing
// the machine, with a plane the program never chose and Z or K words in XY); not Fanuc values with and
// without points mixed (X92 is 0.092 mm as shipped and 92 mm with calculator-type input, parameter DPI:
// the program's writer had one in mind that the tape does not say).
bool MotionMachine::checkable_arc(unsigned plane_bits, char cu, char cv) const {
    if (opt_.lathe_unknown && !plane_set_ && st.plane == Plane::xy && (w_.has('Z') || w_.has('K'))) return false;
    if (dialect_ != Dialect::fanuc) return true;
    bool positions_scaled = ((scaled_ | scaled_start_) & plane_bits) != 0;
    bool words_scaled = w_.scaled(cu) || w_.scaled(cv);
    bool words_pointed =
        (w_.ok(cu) && !w_.scaled(cu) && w_.get(cu) != 0) || (w_.ok(cv) && !w_.scaled(cv) && w_.get(cv) != 0);
    return !((positions_scaled && words_pointed) || (words_scaled && !positions_scaled));
}

bool MotionMachine::arc_off(double r1, double r2) const {
    double diff = std::fabs(r1 - r2), r = std::max(r1, r2);
    double slack = 1e-9 * (1 + r);  // what a double loses on the way: not the control's tolerance
    if (opt_.arc_tolerance_linuxcnc)
        return diff > 100 * opt_.arc_tolerance_mm + slack ||
               (diff > opt_.arc_tolerance_mm + slack && diff > opt_.arc_tolerance_relative * r + slack);
    return diff > opt_.arc_tolerance_mm + opt_.arc_tolerance_relative * r + slack;
}

void MotionMachine::check_arc(int u, int v) {
    double r1 = mv_.radius, r2 = mv_.end_radius;
    if (r1 < 1e-6 || r2 < 1e-6) {
        finding("arc-radius", "zero-radius arc: start=" + point(mv_.start, u, v) + " center=" +
                                  point(mv_.centre, u, v) + " end=" + point(mv_.end, u, v) + " (the control alarms)");
        return;
    }
    if (!arc_off(r1, r2)) return;
    // X may be a lathe's diameter: the same words with X halved, I still a radius.
    auto fits_as_diameter = [&](const Point& c) {
        double half_s = mv_.start.x / 2, half_e = mv_.end.x / 2, i = c.x - mv_.start.x;
        double rd1 = std::hypot(mv_.start.z - c.z, i), rd2 = std::hypot(mv_.end.z - c.z, half_e - (half_s + i));
        return !arc_off(rd1, rd2);
    };
    bool lathe_plane = opt_.lathe_unknown && st.plane == Plane::zx && v == 0;
    if (lathe_plane && fits_as_diameter(mv_.centre)) return;
    if (iso_centre_) {  // a ГОСТ arc whose I may be along X, as ISO 6983 has it
        const Point& c = *iso_centre_;
        if (!arc_off(std::hypot(mv_.start.z - c.z, mv_.start.x - c.x), std::hypot(mv_.end.z - c.z, mv_.end.x - c.x)))
            return;
        if (lathe_plane && fits_as_diameter(c)) return;
    }
    std::string tolerance = fixed(opt_.arc_tolerance_mm) + " mm";
    if (opt_.arc_tolerance_relative > 0)
        tolerance = opt_.arc_tolerance_linuxcnc
                        ? tolerance + " when that is over " + fixed(opt_.arc_tolerance_relative * 100) +
                              " % of the radius, and never " + fixed(100 * opt_.arc_tolerance_mm) + " mm"
                        : tolerance + " + " + fixed(opt_.arc_tolerance_relative * 100) + " % of the radius";
    finding("arc-radius", "radius to end of arc differs from radius to start: start=" + point(mv_.start, u, v) +
                              " center=" + point(mv_.centre, u, v) + " end=" + point(mv_.end, u, v) +
                              " r1=" + fixed(r1) + " r2=" + fixed(r2) + " difference=" + fixed(std::fabs(r1 - r2)) +
                              " mm (" + fixed(std::fabs(r1 - r2) / std::max(r1, r2) * 100) +
                              " %); the control allows " + tolerance);
}

}  // namespace tape
