// G and M codes: which each is for the interpreter (per dialect; a lathe reads some Fanuc codes as its
// own), and the modal state and events they make.
#include <array>
#include <initializer_list>
#include <string>

#include "motion/machine.hpp"

namespace tape {

using namespace motion;

namespace motion {

namespace {

GKind fanuc_lathe(int c) {
    switch (c) {
        case 900:
        case 920:
        case 940:
            return GKind::lathe_cycle;  // turning, thread, facing (G-code system A)
        case 500:
            return GKind::set_coords;
        case 980:
        case 990:
            return GKind::feed_mode;
        case 700:
        case 710:
        case 720:
        case 730:
        case 760:
            return GKind::repetitive;  // finishing, roughing contours, thread in passes
        case 740:
        case 750:
            return GKind::not_drawn;  // peck drilling and grooving in passes
        case 910:
        case 930:
        case 950:
            return GKind::unknown;
        default:
            return GKind::ignore;  // not lathe-specific: the common table answers
    }
}

// The G codes every dialect reads alike (×10: G38.2 is 382), by what they do. Exact stop, compensation,
// path modes and a macro call cancelled (ignore) change nothing the interpreter draws.
struct CommonCodes {
    GKind kind;
    std::initializer_list<int> codes;
};
constexpr CommonCodes common_codes[] = {
    {GKind::motion, {0, 10, 20, 30}},
    {GKind::dwell, {40}},
    {GKind::ignore, {90, 400, 410, 420, 430, 440, 490, 610, 640, 670}},
    {GKind::plane, {170, 180, 190}},
    {GKind::reference, {280, 300}},
    {GKind::machine, {530}},
    {GKind::work_offset, {540, 550, 560, 570, 580, 590}},
    {GKind::cycle_cancel, {800}},
    {GKind::cycle, {810, 820, 830, 840, 850, 860, 880, 890}},
    {GKind::distance, {900, 910}},
    {GKind::set_coords, {920}},
    {GKind::feed_mode, {930, 940, 950}},
    {GKind::speed_mode, {960, 970}},
    {GKind::cycle_return, {980, 990}},
    {GKind::data_setting, {100}},
    {GKind::not_drawn, {50, 51, 52, 60, 310, 381, 382, 383, 384, 385, 650, 660, 661, 120, 130, 870}},
    {GKind::transform, {160, 680, 510, 511}},
    {GKind::transform_off, {150, 690, 501}},
};

// common_codes as a table by code: one look-up a G word, on lint's path too.
constexpr std::array<GKind, 1000> common_table() {
    std::array<GKind, 1000> t{};
    t.fill(GKind::unknown);
    for (const auto& row : common_codes)
        for (int c : row.codes) t[static_cast<std::size_t>(c)] = row.kind;
    return t;
}
constexpr std::array<GKind, 1000> common_kinds = common_table();

GKind common(int c) { return c >= 0 && c < 1000 ? common_kinds[static_cast<std::size_t>(c)] : GKind::unknown; }

}  // namespace

GKind classify(int c, Dialect d, bool lathe) {
    if (lathe && d == Dialect::fanuc) {
        GKind k = fanuc_lathe(c);
        if (k != GKind::ignore) return k;
    }
    switch (d) {
        case Dialect::gost:
            if (c == 700 || c == 710) return GKind::units;
            if (c == 330 || c == 340 || c == 350) return GKind::motion;  // threads: a straight feed move
            if (c == 80) return GKind::ignore;                           // G08/G09: acceleration, deceleration
            if (c == 200 || c == 210 || c == 520) return GKind::unknown;
            break;
        case Dialect::fanuc:
            if (c == 200 || c == 210) return GKind::units;
            if (c == 320 || c == 330) return GKind::motion;
            if (c == 520) return GKind::local_coords;
            if (c == 541) return GKind::work_offset;
            if (c == 730 || c == 740 || c == 760) return GKind::cycle;  // peck, counter tapping, fine boring
            if (c == 500) return GKind::transform_off;                  // scaling off
            break;
        case Dialect::linuxcnc:
            if (c == 200 || c == 210) return GKind::units;
            if (c == 330) return GKind::motion;
            if (c == 70 || c == 80) return GKind::diameter;
            if (c == 901 || c == 911) return GKind::arc_distance;
            if (c == 921 || c == 922 || c == 923) return GKind::reset_coords;
            if (c == 520) return GKind::local_coords;
            if (c == 591 || c == 592 || c == 593) return GKind::work_offset;
            if (c == 730) return GKind::cycle;
            if (c == 611 || c == 431 || c == 491 || c == 411 || c == 421) return GKind::ignore;
            if (c == 331 || c == 760 || c == 700 || c == 710 || c == 720 || c == 51 || c == 52 || c == 21 || c == 31)
                return GKind::not_drawn;
            break;
        default:
            if (c == 200 || c == 210) return GKind::units;
            if (c == 330) return GKind::motion;
            break;
    }
    return common(c);
}

std::string g_name(int code10) {
    std::string s = "G" + std::string(code10 < 100 ? "0" : "") + std::to_string(code10 / 10);
    if (code10 % 10) s += "." + std::to_string(code10 % 10);
    return s;
}

}  // namespace motion

// The block's G codes into the modal state. False when one is not simulated: said, and the block's
// motion is left out (its modal codes still count).
bool MotionMachine::g_codes() {
    once_ = -1;
    std::string unknown;
    for (int i = 0; i < w_.g_count; ++i) {
        int c = w_.g[i];
        GKind k = classify(c, dialect_, opt_.lathe);
        if (k == GKind::unknown || k == GKind::not_drawn) {
            if (!unknown.empty()) unknown += ", ";
            unknown += g_name(c);
            continue;
        }
        apply_g(c, k);
    }
    if (unknown.empty()) return true;
    unsigned lost = 0;
    for (char a : {'X', 'U'})
        if (w_.has(a)) lost |= axis_x;
    if (w_.has('Y') || w_.has('V')) lost |= axis_y;
    if (w_.has('Z') || w_.has('W')) lost |= axis_z;
    values();
    events_before();
    not_simulated(unknown + (unknown.find(',') == std::string::npos ? " is" : " are") +
                      " not simulated: the interpreter does not draw what it does" +
                      (lost ? ", and the tool's place on the axes this block names is unknown after it" : ""),
                  lost);
    events_after();
    return false;
}

// The plain modal state a G code sets (plane, units, distance modes, work offset, feed and speed modes,
// the cycles' return level); false for the codes that move or start something.
bool MotionMachine::set_mode(int c, GKind k) {
    switch (k) {
        case GKind::plane:
            plane_set_ = true;
            st.plane = c == 170 ? Plane::xy : c == 180 ? Plane::zx : Plane::yz;
            return true;
        case GKind::units:
            st.inch = c == 200 || c == 700;
            return true;
        case GKind::distance:
            st.incremental = c == 910;
            return true;
        case GKind::arc_distance:
            st.arc_incremental = c == 911;
            return true;
        case GKind::diameter:
            st.diameter = c == 70;
            return true;
        case GKind::work_offset:
            if (c / 10 != st.work_offset) known = 0;  // the other offset's values are the control's
            st.work_offset = c / 10;
            return true;
        case GKind::feed_mode:
            st.feed_per_rev = c == 950 || (fanuc_lathe_ && c == 990);
            return true;
        case GKind::speed_mode:
            st.constant_surface = c == 960;
            return true;
        case GKind::cycle_return:
            st.retract_to_r = c == 990;
            return true;
        default:
            return false;
    }
}

void MotionMachine::apply_g(int c, GKind k) {
    if (set_mode(c, k)) return;
    switch (k) {
        case GKind::motion:
            group01_ = c / 10;
            cycle_ = lathe_cycle_ = -1;
            return;
        case GKind::cycle:
            if (cycle_ < 0) {
                initial_z_ = pos.z;
                initial_known_ = (known & axis_z) != 0;
                cycle_r_ok_ = cycle_z_ok_ = false;
            }
            cycle_ = c / 10;
            return;
        case GKind::cycle_cancel:
            cycle_ = -1;
            if (dialect_ == Dialect::linuxcnc) group01_ = -1;  // G80 is LinuxCNC's motion mode "none"
            return;
        case GKind::transform:
            transform_ = g_name(c);
            return;
        case GKind::transform_off:
            transform_.clear();
            return;
        case GKind::lathe_cycle:
            lathe_cycle_ = c / 10;
            lathe_named_ = 0;
            group01_ = -1;
            return;
        case GKind::ignore:
            return;
        default:
            once_ = c;
            once_kind_ = k;
            return;
    }
}

// F, S and T.
void MotionMachine::values() {
    if (w_.ok('F')) st.feed = w_.get('F') * (st.inch && !st.feed_per_rev ? 25.4 : st.inch ? 25.4 : 1.0);
    if (w_.ok('S')) st.speed = w_.get('S');
    if (w_.ok('T') && w_.get('T') >= 0 && w_.get('T') < 1e9) {
        auto t = static_cast<int>(w_.get('T'));
        pending_tool_ = fanuc_lathe_ && t >= 100 ? t / 100 : t;
    }
}

void MotionMachine::events_before() {
    bool lathe_turret = opt_.lathe && w_.ok('T');
    if (w_.has_m(6) || lathe_turret) {
        st.tool = pending_tool_;
        event(MoveKind::tool_change, st.tool);
    }
    for (int i = 0; i < w_.m_count; ++i) {
        int m = w_.m[i];
        bool gost_both = dialect_ == Dialect::gost && (m == 13 || m == 14);  // ГОСТ table 7: spindle and coolant on
        if (m == 3 || m == 4 || gost_both) {
            st.spindle = m == 4 || m == 14 ? 4 : 3;
            event(MoveKind::spindle, st.spindle);
        }
        if (m == 7 || m == 8 || gost_both) {
            st.coolant = m == 7 ? 7 : 8;
            event(MoveKind::coolant, st.coolant);
        }
    }
}

void MotionMachine::events_after() {
    for (int i = 0; i < w_.m_count; ++i) {
        int m = w_.m[i];
        if (m == 5) st.spindle = 5, event(MoveKind::spindle, 5);
        if (m == 9) st.coolant = 9, event(MoveKind::coolant, 9);
        if (m == 0 || m == 1) event(MoveKind::stop, m);
        if (call_m(m)) continue;  // M97, M98, M99 in a subprogram (subprograms.cpp)
        if (m == 2 || m == 30 || (m == 99 && dialect_ == Dialect::fanuc)) event(MoveKind::program_end, m);
    }
}

}  // namespace tape
