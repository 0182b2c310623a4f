// A block's end point and its straight moves: X, Y, Z absolute or incremental (a Fanuc lathe's U and W
// always incremental, X a diameter in diameter mode), in mm; the one-block codes that take axis words
// for their own purpose (G04, G28, G53, G92, G52, G10).
#include <cmath>
#include <string>

#include "motion/machine.hpp"

namespace tape {

using namespace motion;

namespace {

double& at(Point& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }

std::string why_unread(const Word& w, ValueState s) {
    if (s == ValueState::macro) return w.text + " is a macro value, known only when the program runs";
    if (s == ValueState::unscaled)
        return w.text +
               " has no decimal point and the program has written none so far: where its implied point stands is "
               "in the control's format (ГОСТ 20999-83 §3.1.3); give the format with --spec";
    return w.text + " holds no value a control reads";
}

}  // namespace

// The end point of the block's axis words; false (said as not simulated) when one cannot be read.
bool MotionMachine::target(Point& end, unsigned& end_known, unsigned& named) {
    end = pos;
    end_known = known;
    named = 0;
    scaled_start_ = scaled_;
    std::string unread;
    unsigned lost = 0;
    // X Y Z, then a Fanuc lathe's incremental U and W: in the order of axes, absolute first.
    static constexpr char letters[6] = {'X', 'U', 'Y', 0, 'Z', 'W'};
    for (int i = 0; i < 3; ++i) {
        unsigned bit = 1u << i;
        for (int k = 0; k < (fanuc_lathe_ ? 2 : 1); ++k) {
            char letter = letters[2 * i + k];
            if (!letter || !w_.has(letter)) continue;
            named |= bit;
            if (!w_.ok(letter)) {
                if (!unread.empty()) unread += "; ";
                unread += why_unread(*w_.word_of(letter), w_.at(letter));
                lost |= bit;
                continue;
            }
            double v = w_.get(letter) * scale();
            if (i == 0 && st.diameter) v /= 2;
            bool incremental = k == 1 || (st.incremental && !fanuc_lathe_);
            if (incremental)
                at(end, i) += v;  // unknown stays unknown
            else
                at(end, i) = v, end_known |= bit, scaled_ &= ~bit;
            if (w_.scaled(letter)) scaled_ |= bit;
        }
    }
    if (unread.empty()) return true;
    begin(MoveKind::not_simulated);
    end_known &= ~lost;
    mv_.end = end;
    mv_.end_known = end_known;
    mv_.note = unread + ": not simulated";
    emit();
    pos = end;
    known = end_known;
    return false;
}

void MotionMachine::straight(MoveKind kind, const Point& end, unsigned end_known) {
    if (opt_.findings_only) {
        pos = end;
        known = end_known;
        return;
    }
    begin(kind);
    mv_.end = end;
    mv_.end_known = end_known;
    emit();
    pos = end;
    known = end_known;
}

// The block's motion: a one-block code, a cycle in force, or the motion mode in force.
void MotionMachine::motion_block() {
    if (once_ >= 0 && once_kind_ == GKind::dwell) {
        begin(MoveKind::dwell);
        // Fanuc: P in milliseconds, X/U in seconds (X1000 without a point is 1 s, the least increment);
        // LinuxCNC: P in seconds; ГОСТ: the time as the control's format gives it, here in seconds.
        char from = w_.ok('P') ? 'P' : w_.ok('X') ? 'X' : w_.ok('U') ? 'U' : w_.ok('F') ? 'F' : 0;
        double s = from ? w_.get(from) : 0;
        if (from == 'P' && dialect_ == Dialect::fanuc) s /= 1000;
        mv_.seconds = std::isfinite(s) && s > 0 ? s : 0;
        emit();
        return;
    }
    if (once_ >= 0 && once_kind_ == GKind::repetitive) return repetitive_cycle();  // U, W, P, Q: the cycle's own
    Point end;
    unsigned end_known, named;
    if (once_ >= 0 && once_kind_ == GKind::data_setting) {
        // G10 L2/L20 write a work offset's values: if it is the one in force, the tool's place moves.
        double l = w_.ok('L') ? w_.get('L') : 0;
        if (l == 2 || l == 20) known = 0;
        return;
    }
    if (!target(end, end_known, named)) return;
    if (once_ >= 0) return coordinates(once_kind_, end, end_known, named);
    if (!transform_.empty() && named) {
        not_simulated(transform_ + " (a coordinate transformation) is in force: where this move goes is not simulated",
                      named);
        return;
    }
    if (lathe_cycle_ >= 0 && named) return lathe_cycle(lathe_cycle_, end, end_known, named);
    if (cycle_ >= 0 && (named || w_.has('R') || w_.has('Z'))) return drill_cycle(end, end_known, named);
    if (!named) return;
    switch (group01_) {
        case 0:
            return straight(MoveKind::rapid, end, end_known);
        case 2:
        case 3:
            return arc(end, end_known);
        case -1:
            not_simulated("axis words with no motion mode (G00, G01, ...) in force: the control stops here", named);
            return;
        default:
            return straight(MoveKind::linear, end, end_known);
    }
}

// G92/G50, G52, G92.1-3, G28/G30, G53: their axis words say something else than where to go.
void MotionMachine::coordinates(GKind kind, const Point& end, unsigned end_known, unsigned named) {
    Point given = pos;
    for (int i = 0; i < 3; ++i) {
        char a = "XYZ"[i];
        if (w_.ok(a)) at(given, i) = w_.get(a) * scale() / (i == 0 && st.diameter ? 2 : 1);
    }
    switch (kind) {
        case GKind::set_coords:  // the tool is now at the values given: its place stays known
            pos = given;
            known |= named;
            return;
        case GKind::local_coords:  // G52: a shift from the work offset's zero; G52 X0 removes it
            for (int i = 0; i < 3; ++i)
                if (named & (1u << i)) at(pos, i) -= at(given, i) - at(local_, i), at(local_, i) = at(given, i);
            return;
        case GKind::reset_coords:
            known = 0;  // the shift G92 made is the control's: where the tool stands is not followed
            return;
        default:
            reference(kind, end, end_known, named);
            return;
    }
}

// G28/G30: through the point given to a place the control keeps; G53: to machine coordinates. The
// moves are drawn; where they end is not in the program's coordinates.
void MotionMachine::reference(GKind kind, const Point& end, unsigned end_known, unsigned named) {
    if (kind == GKind::reference) {
        if (named) straight(MoveKind::rapid, end, end_known);
        unsigned home = named ? named : all_axes;  // LinuxCNC's G28 alone sends every axis home
        straight(MoveKind::rapid, pos, known & ~home);
        return;
    }
    straight(group01_ == 1 ? MoveKind::linear : MoveKind::rapid, end, end_known & ~named);
}

}  // namespace tape
