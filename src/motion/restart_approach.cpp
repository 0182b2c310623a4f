// The approach of a restart: the interpreter runs the blocks before the restart block; where it leaves
// the tool is where the block must start. Whatever makes that place unknown refuses the restart.
#include "motion/restart_approach.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "motion/machine.hpp"
#include "tape/error.hpp"
#include "tape/motion.hpp"

namespace tape {
namespace {

constexpr double same_mm = 1e-9;

[[noreturn]] void refuse(const Location& where, const std::string& why) {
    throw Error(Errc::usage, where.position(), "line " + std::to_string(where.line) + ": " + why);
}

// The moves before the restart block: the first one not simulated, and the highest place reached by
// rapid in each work offset (Z on a mill, X on a lathe): the safe place to retract to.
class Before : public MotionVisitor {
public:
    explicit Before(bool lathe) : lathe_(lathe) {}
    void move(const Move& m) override {
        if (m.kind == MoveKind::not_simulated && !unsimulated) unsimulated = m;
        if (m.kind != MoveKind::rapid) return;
        unsigned axis = lathe_ ? axis_x : axis_z;
        if (!(m.end_known & axis)) return;
        double v = lathe_ ? m.end.x : m.end.z;
        auto [it, fresh] = highest.emplace(m.state.work_offset, v);
        if (!fresh) it->second = std::max(it->second, v);
    }
    std::optional<Move> unsimulated;
    std::map<int, double> highest;

private:
    bool lathe_;
};

std::string axes_named(unsigned axes) {
    std::string out;
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i)) out += std::string(out.empty() ? "" : ", ") + "XYZ"[i];
    return out;
}

bool dimension(char a) { return std::string_view("XYZUWIJKR").find(a) != std::string_view::npos; }

// The most decimals the program writes its dimensions with (at least a micron, or 0.1 mil in inches):
// the approach's values are written as finely, and no finer than a control takes.
int decimals(const Program& p, std::size_t upto, bool inch) {
    int most = inch ? 4 : 3;
    for (std::size_t i = 0; i <= upto && i < p.blocks.size(); ++i)
        for (const auto& w : p.blocks[i].words)
            if (dimension(w.address) && w.has_point() && !w.macro)
                most = std::max(most, static_cast<int>(w.digits().size()) - w.point);
    return std::min(most, 6);
}

// "50.", "-5.", "10.25": a value with its point, as Fanuc needs it and every control reads it.
std::string number(double v, int places) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", places, v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s == "-.") s = "0.";
    if (s == "-0.") s = "0.";
    return s;
}

// A value without a point is worth what the control's least increment makes it (X1000: 1 mm or 1 m):
// where the tool stands is then not known from the text alone, except on LinuxCNC (always units).
void check_points(const ApproachInput& in) {
    if (in.dialect == Dialect::linuxcnc) return;
    for (std::size_t i = 0; i < in.index; ++i)
        for (const auto& w : in.program->blocks[i].words) {
            if (std::string_view("XYZUW").find(w.address) == std::string_view::npos || w.has_point() || w.macro)
                continue;
            auto d = w.digits();
            if (d.find_first_not_of('0') != std::string::npos)
                refuse(w.where, w.text +
                                    " has no decimal point: what it is worth depends on the control's least "
                                    "increment, so where the tool stands is not known from the text");
        }
}

bool writes_y(const Program& p, std::size_t upto) {
    for (std::size_t i = 0; i <= upto && i < p.blocks.size(); ++i)
        for (const auto& w : p.blocks[i].words)
            if (w.address == 'Y' || w.address == 'V') return true;
    return false;
}

// What the approach cannot do without: the tool's place on every axis it moves, and a height.
void check_known(const ApproachInput& in, const Interpreter& run, const Before& before, const Block& target) {
    const std::string& n = target.number_text();
    if (before.unsimulated)
        refuse(before.unsimulated->where,
               before.unsimulated->note + ": where the tool stands at " + n + " is not known");
    if (!in.lathe && run.state().plane == Plane::zx && !writes_y(*in.program, in.index))
        refuse(target.where,
               "the ZX plane (G18) is in force and no Y is written: a lathe program? A lathe's "
               "approach goes X first: say it is a lathe");
    unsigned needed = in.lathe ? axis_x | axis_z : all_axes;
    if ((run.known() & needed) != needed)
        refuse(target.where, "where the tool stands in " + axes_named(needed & ~run.known()) + " at " + n +
                                 " is not known: no block before it sets it absolutely since the tool's place was "
                                 "last lost (power on, a reference return, a work offset changed or set)");
    if (!before.highest.contains(run.state().work_offset))
        refuse(target.where, std::string("no rapid move before ") + n + " reaches a known " + (in.lathe ? "X" : "Z") +
                                 ": no safe place to retract to is known");
}

// A coordinate transformation (G68 rotation, G51 scaling, G16 polar) in force at the block: the modal
// blocks do not send it again, and the interpreter does not follow the moves under it.
void check_transform(const ApproachInput& in, const Block& target) {
    std::optional<Word> in_force;
    for (std::size_t i = 0; i < in.index; ++i)
        for (const auto& w : in.program->blocks[i].words) {
            if (w.address != 'G' || w.macro) continue;
            double code = std::strtod(w.text.c_str() + 1, nullptr);
            auto kind = motion::classify(static_cast<int>(std::lround(code * 10)), in.dialect, in.lathe);
            if (kind == motion::GKind::transform) in_force = w;
            if (kind == motion::GKind::transform_off) in_force.reset();
        }
    if (in_force)
        refuse(target.where, "a coordinate transformation (" + in_force->text + " at line " +
                                 std::to_string(in_force->where.line) + ") is in force: it is not rebuilt");
}

// A lathe cycle's contour (G70-G73 P-Q) is where its blocks stand: a restart inside it, or before a
// cycle whose contour lies before the block, leaves the control without it.
void check_contours(const ApproachInput& in, const Interpreter& run, const Block& target) {
    if (auto open = run.open_cycle(); !open.empty())
        refuse(target.where, target.number_text() + " is in the contour of " + open +
                                 ": a restart inside a lathe cycle's contour is not rebuilt");
    if (!in.lathe || in.dialect != Dialect::fanuc) return;
    std::set<long long> before;
    for (std::size_t i = 0; i < in.index; ++i)
        if (const auto& n = in.program->blocks[i].number; n && n->integer()) before.insert(*n->integer());
    for (std::size_t i = in.index; i < in.program->blocks.size(); ++i) {
        const Block& b = in.program->blocks[i];
        bool cycle = false;
        for (const auto& w : b.words) {
            if (w.address == 'G' && !w.macro) {
                int code = static_cast<int>(std::lround(std::strtod(w.text.c_str() + 1, nullptr) * 10));
                cycle |= code != 760 && motion::classify(code, in.dialect, true) == motion::GKind::repetitive;
            }
            if (cycle && w.address == 'P' && w.integer() && before.contains(*w.integer()))
                refuse(b.where, w.text + " of this cycle names a block before " + target.number_text() +
                                    ": the restarted program does not hold its contour");
        }
    }
}

// A corner word (",C", ",R") on the block before: the block starts at the corner's end, not at the sharp
// corner the approach would go to.
void check_corner(const ApproachInput& in, const Block& target) {
    if (in.index == 0) return;
    for (const auto& w : in.program->blocks[in.index - 1].words)
        if (w.address == ',')
            refuse(target.where, "the block before " + target.number_text() + " ends in a corner (" + w.text +
                                     "): " + target.number_text() + " starts where the corner ends, not rebuilt");
}

}  // namespace

std::vector<std::string> restart_approach(const ApproachInput& in) {
    const Program& p = *in.program;
    const Block& target = p.blocks[in.index];
    check_points(in);
    MotionOptions options = motion_options(in.dialect);
    options.lathe = in.lathe;
    Before before(in.lathe);
    Interpreter run(before, options);
    run.dialect(DialectChoice{in.dialect, {}, {}});
    run.program_start(p);
    for (std::size_t i = 0; i < in.index; ++i) run.block(p.blocks[i]);
    check_known(in, run, before, target);
    check_transform(in, target);
    check_contours(in, run, target);
    check_corner(in, target);

    const ModalState st = run.state();
    const Point at = run.position();
    double safe = std::max(before.highest.at(st.work_offset), in.lathe ? at.x : at.z);
    double scale = st.inch ? 25.4 : 1.0;
    int places = decimals(p, in.index, st.inch);
    auto value = [&](double mm, bool x_on_lathe = false) {
        return number(mm * (x_on_lathe && st.diameter ? 2 : 1) / scale, places);
    };
    // Absolute first: a Fanuc lathe has no G90 (it is a turning cycle there): X and Z are absolute.
    std::string first = in.lathe && in.dialect == Dialect::fanuc ? "" : "G90 ";
    if (in.dialect == Dialect::linuxcnc && !st.arc_incremental) first += "G90.1 ";  // not in the modal blocks
    if (in.dialect == Dialect::linuxcnc && in.lathe) first += st.diameter ? "G7 " : "G8 ";
    double depth = in.lathe ? at.x : at.z;
    std::vector<std::string> out;
    if (in.lathe) {
        out.push_back(first + "G00 X" + value(safe, true));
        out.push_back("G00 Z" + value(at.z));
    } else {
        out.push_back(first + "G00 Z" + value(safe));
        out.push_back("G00 X" + value(at.x) + " Y" + value(at.y));
    }
    if (depth < safe - same_mm) {
        const std::string& n = target.number_text();
        if (in.inverse_time)
            refuse(target.where, "inverse-time feed (G93) is in force at " + n + ": no feed to go down at is known");
        if (in.feed.empty())
            refuse(target.where, "no feed (F) is programmed before " + n + ": none to go down at is known");
        out.push_back(in.lathe ? "G01 X" + value(at.x, true) + " " + in.feed : "G01 Z" + value(at.z) + " " + in.feed);
    }
    return out;
}

}  // namespace tape
