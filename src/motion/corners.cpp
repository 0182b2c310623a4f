// Fanuc's corner words after a G01: ",C" (a chamfer, C from the sharp corner along each move) and ",R" (a
// rounding of radius R, tangent to both moves) join it to the next move, a G01 in the plane. The corner
// lies between this block and the next, which a streaming interpreter has not read yet: the move is held
// until the next one comes, then drawn cut short, the corner, and the next move from the corner's end.
// Any other corner (an arc on either side, a move out of the plane, a corner longer than a move) is not
// drawn: the moves go to the sharp corner and the block says so. Where the next move ends is the same.
#include <cmath>
#include <cstdlib>
#include <utility>

#include "motion/machine.hpp"

namespace tape {

namespace {

double& axis(Point& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }

Point along(const Point& from, const Point& unit, double length) {
    return Point{from.x + unit.x * length, from.y + unit.y * length, from.z + unit.z * length};
}

// The unit direction from a to b and the distance; 0 when they coincide.
double direction(const Point& a, const Point& b, Point& unit) {
    double d = std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
    unit = d > 0 ? Point{(b.x - a.x) / d, (b.y - a.y) / d, (b.z - a.z) / d} : Point{};
    return d;
}

}  // namespace

void MotionMachine::corner_begin(const Block& b) {
    corner_word_ = nullptr;
    for (const auto& w : b.words)
        if (w.address == ',') corner_word_ = &w;
}

// A corner word whose block made no G01 to hold (another motion, a cycle's contour, lint): not drawn.
void MotionMachine::corner_end() {
    if (!corner_word_) return;
    corner_text_ = corner_word_->text;
    corner_word_ = nullptr;
    begin(MoveKind::not_simulated);
    corner_note(mv_, lathe_.open ? "in a lathe cycle's contour" : "this block's move is no G01");
}

void MotionMachine::corner_note(const Move& at, const std::string& why) {
    bool chamfer = corner_text_.find_first_of("Cc") != std::string::npos;
    auto block = at.block;
    Location where = at.where;  // at may be mv_ itself
    begin(MoveKind::not_simulated);
    mv_.block = block;
    mv_.where = where;
    mv_.note = corner_text_ + " (" + (chamfer ? "a chamfer" : "a rounding") + " of the corner to the next move) " +
               "is not drawn (" + why + "): the moves are drawn to the sharp corner";
    if (!opt_.findings_only) out_.move(mv_);
}

// The block's G01 is held; the next move draws it with the corner, or without it (said).
bool MotionMachine::corner_move() {
    if (corner_held_) {
        Move next = mv_;
        Move held = std::move(*corner_held_);
        corner_held_.reset();
        if (!corner_join(held, next)) {
            if (!opt_.findings_only) out_.move(held);
            corner_note(held, next.kind == MoveKind::linear ? "the corner does not fit the moves or the plane"
                                                            : "the next move is no G01");
        }
        mv_ = next;
    }
    if (!corner_word_ || mv_.kind != MoveKind::linear || mv_.depth != 0) return false;
    corner_held_ = mv_;
    corner_text_ = corner_word_->text;
    corner_word_ = nullptr;
    return true;
}

// Draws held cut short and its corner, and starts next at the corner's end; false when it cannot.
bool MotionMachine::corner_join(const Move& held, Move& next) {
    if (next.kind != MoveKind::linear || next.depth != 0) return false;
    int u = st.plane == Plane::xy ? 0 : st.plane == Plane::zx ? 2 : 1;
    int v = st.plane == Plane::xy ? 1 : st.plane == Plane::zx ? 0 : 2;
    int w = 3 - u - v;
    unsigned in_plane = (1u << u) | (1u << v);
    if ((held.known & in_plane) != in_plane || (next.known & in_plane) != in_plane) return false;
    Point a, b;
    double la = direction(held.start, held.end, a), lb = direction(next.start, next.end, b);
    if (la <= 0 || lb <= 0 || std::fabs(axis(a, w)) > 1e-9 || std::fabs(axis(b, w)) > 1e-9) return false;
    double cosine = a.x * b.x + a.y * b.y + a.z * b.z;
    if (cosine > 1 - 1e-12 || cosine < -1 + 1e-12) return false;  // straight on or straight back: no corner
    std::string text = corner_text_;
    char kind = text.size() > 1 ? static_cast<char>(text[1] & ~0x20) : 0;
    double value = std::strtod(text.c_str() + 2, nullptr);
    if (text.find('.') == std::string::npos && dialect_ == Dialect::fanuc) value *= st.inch ? 0.0001 : 0.001;
    value *= scale();
    double turn = std::acos(cosine);
    double cut = kind == 'R' ? value * std::tan(turn / 2) : value;  // from the sharp corner along each move
    constexpr double slack = 1e-9;                                  // a chamfer as long as its move takes all of it
    if (!(value > 0) || !std::isfinite(cut) || cut > la + slack || cut > lb + slack) return false;
    Move first = held, corner = held;
    first.end = corner.start = along(held.end, a, -cut);
    corner.end = along(held.end, b, cut);
    if (kind == 'R') {
        Point a_norm, n{b.x - cosine * a.x, b.y - cosine * a.y, b.z - cosine * a.z};  // towards the turn
        direction(Point{}, n, a_norm);
        corner.kind = MoveKind::arc;
        corner.centre = along(corner.start, a_norm, value);
        double cross = axis(a, u) * axis(b, v) - axis(a, v) * axis(b, u);  // seen from the plane's normal
        corner.clockwise = cross < 0;
        corner.radius = corner.end_radius = value;
        corner.turns = 0;
    }
    if (!opt_.findings_only) {
        if (la - cut > slack) out_.move(first);
        out_.move(corner);
    }
    next.start = corner.end;
    return true;
}

}  // namespace tape
