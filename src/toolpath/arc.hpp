// An arc's geometry in its plane, for the drawing and the comparison of toolpaths: the plane's axes
// (a, b) and its normal n are right-handed (a x b = n), so that counterclockwise seen from +n is the way
// the angle grows. G17: (x, y, z), G18: (z, x, y), G19: (y, z, x).
#pragma once

#include <cmath>
#include <numbers>

#include "tape/motion.hpp"

namespace tape::arcs {

struct InPlane {
    double a = 0, b = 0, n = 0;
};

inline InPlane to_plane(const Point& p, Plane plane) {
    switch (plane) {
        case Plane::zx:
            return {p.z, p.x, p.y};
        case Plane::yz:
            return {p.y, p.z, p.x};
        case Plane::xy:
            break;
    }
    return {p.x, p.y, p.z};
}

inline Point from_plane(const InPlane& q, Plane plane) {
    switch (plane) {
        case Plane::zx:
            return {q.b, q.n, q.a};
        case Plane::yz:
            return {q.n, q.a, q.b};
        case Plane::xy:
            break;
    }
    return {q.a, q.b, q.n};
}

/// An arc as start angle, signed sweep (positive counterclockwise) and radii at its ends.
struct Sweep {
    double start = 0, sweep = 0, r0 = 0, r1 = 0;
};

/// The arc from start to end about centre (centre's third coordinate ignored), turns whole extra turns.
inline Sweep sweep_of(const Point& start, const Point& end, const Point& centre, Plane plane, bool clockwise,
                      int turns) {
    constexpr double two_pi = 2 * std::numbers::pi;
    InPlane s = to_plane(start, plane), e = to_plane(end, plane), c = to_plane(centre, plane);
    Sweep out;
    out.start = std::atan2(s.b - c.b, s.a - c.a);
    double to = std::atan2(e.b - c.b, e.a - c.a);
    out.r0 = std::hypot(s.a - c.a, s.b - c.b);
    out.r1 = std::hypot(e.a - c.a, e.b - c.b);
    double d = clockwise ? out.start - to : to - out.start;
    d = std::fmod(d, two_pi);
    if (d < 0) d += two_pi;
    // An end on the start (within a nanometre of arc length) is no part of a turn.
    if (d * std::max(out.r0, 1e-9) < 1e-9 || (two_pi - d) * std::max(out.r0, 1e-9) < 1e-9) d = 0;
    d += two_pi * std::max(turns, 0);
    out.sweep = clockwise ? -d : d;
    return out;
}

/// The point at fraction t (0..1) of the arc, the radius and the third axis going evenly (a helix).
inline Point point_at(const Sweep& w, const Point& start, const Point& end, const Point& centre, Plane plane,
                      double t) {
    InPlane s = to_plane(start, plane), e = to_plane(end, plane), c = to_plane(centre, plane);
    double angle = w.start + w.sweep * t, r = w.r0 + (w.r1 - w.r0) * t;
    return from_plane({c.a + r * std::cos(angle), c.b + r * std::sin(angle), s.n + (e.n - s.n) * t}, plane);
}

}  // namespace tape::arcs
