// Programs compared by geometry (tape/motion_diff.hpp).
#include "tape/motion_diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "toolpath/arc.hpp"

namespace tape {
namespace {

bool near(const Point& p, const Point& q, unsigned known, double tol) {
    return (!(known & axis_x) || std::abs(p.x - q.x) <= tol) && (!(known & axis_y) || std::abs(p.y - q.y) <= tol) &&
           (!(known & axis_z) || std::abs(p.z - q.z) <= tol);
}

double distance(const Point& p, const Point& q) { return std::hypot(p.x - q.x, p.y - q.y, p.z - q.z); }

// How far e is from the line through s and f, and whether it lies between them going s -> e -> f.
bool on_the_way(const Point& s, const Point& e, const Point& f, double tol) {
    double ux = e.x - s.x, uy = e.y - s.y, uz = e.z - s.z, vx = f.x - e.x, vy = f.y - e.y, vz = f.z - e.z;
    if (ux * vx + uy * vy + uz * vz <= 0) return false;
    double wx = f.x - s.x, wy = f.y - s.y, wz = f.z - s.z, len = std::hypot(wx, wy, wz);
    double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
    return len > 0 && std::hypot(cx, cy, cz) / len <= tol;
}

// The rise of the plane's normal axis per radian: a helix continues only at the same pitch.
double rise(const PathPiece& p) {
    double dn = arcs::to_plane(p.end, p.plane).n - arcs::to_plane(p.start, p.plane).n;
    return p.sweep == 0 ? 0 : dn / p.sweep;
}

}  // namespace

void MotionPieces::note_block(const Block& block) {
    source_block_ = block.ordinal;
    source_ = block.source;
}

bool MotionPieces::merge(const Move& m) {
    if (pieces_.empty()) return false;
    PathPiece& last = pieces_.back();
    if (last.kind != m.kind || last.known != m.known || distance(last.end, m.start) > 1e-9) return false;
    if (m.kind != MoveKind::arc) {
        if (!on_the_way(last.start, last.end, m.end, tolerance_ / 4)) return false;
        last.end = m.end;
        ++last.moves;
        return true;
    }
    arcs::Sweep w = arcs::sweep_of(m.start, m.end, m.centre, m.state.plane, m.clockwise, m.turns);
    arcs::InPlane c0 = arcs::to_plane(last.centre, last.plane), c1 = arcs::to_plane(m.centre, m.state.plane);
    PathPiece next{.kind = m.kind, .start = m.start, .end = m.end, .plane = m.state.plane, .sweep = w.sweep};
    bool same_circle = m.state.plane == last.plane && (w.sweep > 0) == (last.sweep > 0) &&
                       std::hypot(c0.a - c1.a, c0.b - c1.b) <= tolerance_ / 4 &&
                       std::abs(w.r0 - last.radius) <= tolerance_ / 4 &&
                       std::abs(rise(next) - rise(last)) * std::abs(last.sweep + w.sweep) <= tolerance_ / 4;
    if (!same_circle) return false;
    last.end = m.end;
    last.sweep += w.sweep;
    ++last.moves;
    return true;
}

void MotionPieces::move(const Move& m) {
    bool motion = m.kind == MoveKind::rapid || m.kind == MoveKind::linear || m.kind == MoveKind::arc;
    if (!motion && m.kind != MoveKind::not_simulated) return;
    if (m.kind != MoveKind::arc && m.kind != MoveKind::not_simulated && distance(m.start, m.end) < 1e-9) return;
    if (motion && merge(m)) return;
    PathPiece p{.kind = m.kind,
                .start = m.start,
                .end = m.end,
                .centre = m.centre,
                .known = m.known,
                .plane = m.state.plane,
                .where = m.where,
                .block = m.block};
    if (m.kind == MoveKind::arc) {
        arcs::Sweep w = arcs::sweep_of(m.start, m.end, m.centre, m.state.plane, m.clockwise, m.turns);
        p.sweep = w.sweep;
        p.radius = w.r0;
        if (w.sweep == 0) return;  // an arc of no length
    }
    p.text = m.kind == MoveKind::not_simulated ? m.note : m.block == source_block_ ? source_ : std::string();
    pieces_.push_back(std::move(p));
}

MotionDifference compare_motion(const std::vector<PathPiece>& a, const std::vector<PathPiece>& b, double tol) {
    MotionDifference d;
    for (std::size_t i = 0;; ++i) {
        const PathPiece* p = i < a.size() ? &a[i] : nullptr;
        const PathPiece* q = i < b.size() ? &b[i] : nullptr;
        if (!p && !q) return d;
        d.index = i;
        if (p) d.first = *p;
        if (q) d.second = *q;
        d.same = false;
        if (!p || !q) {
            d.what = std::string(p ? "the second" : "the first") + " program ends here; the other goes on";
        } else if (p->kind == MoveKind::not_simulated || q->kind == MoveKind::not_simulated) {
            d.cannot_tell = true;
            d.what = "a move not simulated: the toolpaths cannot be compared past it";
        } else if (p->kind != q->kind) {
            d.what = "not the same kind of move";
        } else if (p->known != q->known) {
            d.what = "the tool's place is known on other axes";
        } else if (!near(p->start, q->start, p->known, tol)) {
            d.what = "they start at different places";
        } else if (!near(p->end, q->end, p->known, tol)) {
            d.what = "they end at different places";
        } else if (p->kind == MoveKind::arc && (p->plane != q->plane || !near(p->centre, q->centre, p->known, tol) ||
                                                std::abs(p->sweep - q->sweep) * std::max(p->radius, q->radius) > tol)) {
            d.what = "not the same arc (plane, centre, direction or turns)";
        } else {
            d.first.reset();
            d.second.reset();
            d.same = true;
            continue;
        }
        return d;
    }
}

std::string piece_text(const PathPiece& p) {
    char buf[256];
    auto point = [](const Point& q, unsigned known) {
        std::string s;
        char v[48];
        for (auto [bit, letter, value] : {std::tuple{axis_x, 'X', q.x}, {axis_y, 'Y', q.y}, {axis_z, 'Z', q.z}}) {
            std::snprintf(v, sizeof v, known & bit ? "%s%c%.4f" : "%s%c?", s.empty() ? "" : " ", letter, value);
            s += v;
        }
        return s;
    };
    std::string moves = p.moves > 1 ? ", " + std::to_string(p.moves) + " moves" : "";
    switch (p.kind) {
        case MoveKind::not_simulated:
            return "not simulated: " + p.text;
        case MoveKind::arc: {
            static const char* planes[] = {"XY", "ZX", "YZ"};
            std::snprintf(buf, sizeof buf, "arc %s %s, %.3f degrees, radius %.4f, about ",
                          planes[static_cast<int>(p.plane)], p.sweep < 0 ? "clockwise" : "counterclockwise",
                          std::abs(p.sweep) * 180 / std::numbers::pi, p.radius);
            return buf + point(p.centre, p.known) + ", from " + point(p.start, p.known) + " to " +
                   point(p.end, p.known) + moves;
        }
        default:
            return std::string(p.kind == MoveKind::rapid ? "rapid" : "feed") + " from " + point(p.start, p.known) +
                   " to " + point(p.end, p.known) + moves;
    }
}

}  // namespace tape
