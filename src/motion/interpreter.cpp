// The interpreter's public face (tape/motion.hpp): the loader's visitor driving MotionMachine, the
// one-pass helper, and what a move measures.
#include <cmath>
#include <numbers>

#include "motion/machine.hpp"

namespace tape {

Interpreter::Interpreter(MotionVisitor& out, const MotionOptions& options)
    : machine_(std::make_unique<MotionMachine>(out, options)) {}

Interpreter::~Interpreter() = default;

void Interpreter::dialect(const DialectChoice& choice) { machine_->dialect(choice.dialect); }
void Interpreter::program_start(const Program& header) { machine_->program_start(header); }
void Interpreter::block(const Block& block) { machine_->block(block); }
void Interpreter::end(const Location& where) {
    (void)where;
    machine_->end();
}
void Interpreter::subprograms(const SubprogramText* text) { machine_->subprograms(text); }

Point Interpreter::position() const { return machine_->pos; }
unsigned Interpreter::known() const { return machine_->known; }
const ModalState& Interpreter::state() const { return machine_->st; }
std::string Interpreter::open_cycle() const { return machine_->open_cycle(); }

void interpret_each(std::string_view text, std::span<const std::uint64_t> frame_of, MotionVisitor& out,
                    const MotionOptions& options) {
    SubprogramText subs(text, frame_of);
    Interpreter in(out, options);
    in.subprograms(&subs);
    LoadOptions lo;
    lo.dialect = options.dialect;
    load_each(text, frame_of, in, lo);
}

MotionOptions motion_options(Dialect dialect) {
    MotionOptions o;
    o.dialect = dialect;
    switch (dialect) {
        case Dialect::linuxcnc:  // CENTER_ARC_RADIUS_TOLERANCE_MM = 2 * 0.01 * sqrt(2), SPIRAL_RELATIVE_TOLERANCE
            o.arc_tolerance_mm = 2 * 0.01 * std::numbers::sqrt2;
            o.arc_tolerance_relative = 0.001;
            o.arc_tolerance_linuxcnc = true;
            break;
        case Dialect::fanuc:
            o.arc_tolerance_mm = 0.02;
            break;
        default:  // the seeds' controller: to a micron (alarm 7.56) unless machine constant 55 widens it
            o.arc_tolerance_mm = 0.001;
            break;
    }
    return o;
}

namespace {

double at(const Point& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }

}  // namespace

double Move::sweep() const {
    if (kind != MoveKind::arc || radius <= 0) return 0;
    int u = state.plane == Plane::xy ? 0 : state.plane == Plane::zx ? 2 : 1;
    int v = state.plane == Plane::xy ? 1 : state.plane == Plane::zx ? 0 : 2;
    double a0 = std::atan2(at(start, v) - at(centre, v), at(start, u) - at(centre, u));
    double a1 = std::atan2(at(end, v) - at(centre, v), at(end, u) - at(centre, u));
    double d = clockwise ? a0 - a1 : a1 - a0;
    constexpr double turn = 2 * std::numbers::pi;
    bool closed = std::hypot(at(end, u) - at(start, u), at(end, v) - at(start, v)) < 1e-9;
    if (closed)
        d = 0;
    else
        d = std::fmod(std::fmod(d, turn) + turn, turn);
    return d + turn * turns;
}

double Move::length() const {
    switch (kind) {
        case MoveKind::rapid:
        case MoveKind::linear:
            return std::hypot(end.x - start.x, end.y - start.y, end.z - start.z);
        case MoveKind::arc: {
            int w = state.plane == Plane::xy ? 2 : state.plane == Plane::zx ? 1 : 0;
            return std::hypot(sweep() * radius, at(end, w) - at(start, w));
        }
        default:
            return 0;
    }
}

}  // namespace tape
