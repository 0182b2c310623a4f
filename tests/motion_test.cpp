// The interpreter (tape/motion.hpp): arcs in every plane as the controls turn them, worked by hand from
// the public backplot bug reports; R arcs both ways, full circles, helices; tolerances on both sides of
// each limit; lathes, units, incremental moves, canned cycles; the sample tapes.
#include "tape/motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "test_util.hpp"

namespace {

using tape::Dialect;
using tape::Move;
using tape::MoveKind;

constexpr double pi = std::numbers::pi;

struct Collect : tape::MotionVisitor {
    std::vector<Move> moves;
    std::vector<tape::Finding> findings;
    void move(const Move& m) override { moves.push_back(m); }
    void finding(const tape::Finding& f) override { findings.push_back(f); }
    std::vector<Move> of(MoveKind k) const {
        std::vector<Move> out;
        for (const auto& m : moves)
            if (m.kind == k) out.push_back(m);
        return out;
    }
    std::size_t count(MoveKind k) const { return of(k).size(); }
    std::size_t rule(std::string_view id) const {
        std::size_t n = 0;
        for (const auto& f : findings) n += f.rule == id;
        return n;
    }
};

Collect run(const std::string& text, tape::MotionOptions o) {
    Collect c;
    tape::interpret_each(text, {}, c, o);
    return c;
}

Collect run(const std::string& text, Dialect d = Dialect::linuxcnc) { return run(text, tape::motion_options(d)); }

void expect_point(const tape::Point& p, double x, double y, double z) {
    EXPECT_NEAR(p.x, x, 1e-9);
    EXPECT_NEAR(p.y, y, 1e-9);
    EXPECT_NEAR(p.z, z, 1e-9);
}

// G17, seen from +Z: from (10,0) clockwise to (0,-10) around the origin is a quarter turn.
TEST(MotionArcs, G17ClockwiseQuarter) {
    auto c = run("G17 G90 G0 X10 Y0 Z0\nG2 X0 Y-10 I-10 J0 F100\nM2\n");
    auto arcs = c.of(MoveKind::arc);
    ASSERT_EQ(arcs.size(), 1u);
    expect_point(arcs[0].centre, 0, 0, 0);
    EXPECT_TRUE(arcs[0].clockwise);
    EXPECT_NEAR(arcs[0].sweep(), pi / 2, 1e-9);
    EXPECT_NEAR(arcs[0].length(), 10 * pi / 2, 1e-9);
    EXPECT_TRUE(c.findings.empty());
}

// G18 (CAMotics#96, UGS#853/#1154, Candle#9): seen from +Y the screen has Z to the right and X up
// (Z × X = Y). From Z10 X0 to Z0 X10 around the origin, G03 turns a quarter (right to up,
// counter-clockwise) and G02 three quarters (right, down, left, up). A viewer that draws X across and Z up
// swaps the two.
TEST(MotionArcs, G18SeenFromPlusY) {
    auto cw = run("G18 G90 G0 X0 Y0 Z10\nG2 X10 Z0 I0 K-10 F100\nM2\n").of(MoveKind::arc);
    auto ccw = run("G18 G90 G0 X0 Y0 Z10\nG3 X10 Z0 I0 K-10 F100\nM2\n").of(MoveKind::arc);
    ASSERT_EQ(cw.size(), 1u);
    ASSERT_EQ(ccw.size(), 1u);
    expect_point(cw[0].centre, 0, 0, 0);
    EXPECT_NEAR(cw[0].sweep(), 3 * pi / 2, 1e-9);
    EXPECT_NEAR(ccw[0].sweep(), pi / 2, 1e-9);
    EXPECT_EQ(cw[0].state.plane, tape::Plane::zx);
}

// G19, seen from +X: Y to the right, Z up. From Y10 Z0 to Y0 Z10: G03 a quarter, G02 three quarters.
TEST(MotionArcs, G19SeenFromPlusX) {
    auto ccw = run("G19 G90 G0 X0 Y10 Z0\nG3 Y0 Z10 J-10 K0 F100\nM2\n").of(MoveKind::arc);
    auto cw = run("G19 G90 G0 X0 Y10 Z0\nG2 Y0 Z10 J-10 K0 F100\nM2\n").of(MoveKind::arc);
    ASSERT_EQ(ccw.size(), 1u);
    expect_point(ccw[0].centre, 0, 0, 0);
    EXPECT_NEAR(ccw[0].sweep(), pi / 2, 1e-9);
    EXPECT_NEAR(cw[0].sweep(), 3 * pi / 2, 1e-9);
}

// The seeds' controller (manual §4.3, fig. 7b): in Z-X, I is along Z and J along X. G03 G91 X0 Z-400
// I-200 is a half circle of radius 200 whose centre is 200 along -Z from the start.
TEST(MotionArcs, GostZxCentreByIAndJ) {
    auto c = run("%\nN1 G18 G90 G00 X0 Y0 Z0\nN2 G03 G91 X0 Z-400.0 I-200.0 F100\nN3 M02\n", Dialect::gost);
    auto arcs = c.of(MoveKind::arc);
    ASSERT_EQ(arcs.size(), 1u);
    expect_point(arcs[0].centre, 0, 0, -200);
    EXPECT_NEAR(arcs[0].radius, 200, 1e-9);
    EXPECT_NEAR(arcs[0].sweep(), pi, 1e-9);
    EXPECT_TRUE(c.findings.empty());
    expect_point(arcs[0].end, 0, 0, -400);
}

// From (0,0) to (10,10) by R10: clockwise the short way around (10,0), a quarter; R-10 the long way
// around (0,10), three quarters.
TEST(MotionArcs, RBothWays) {
    auto shortway = run("G90 G0 X0 Y0 Z0\nG2 X10 Y10 R10 F100\nM2\n").of(MoveKind::arc);
    auto longway = run("G90 G0 X0 Y0 Z0\nG2 X10 Y10 R-10 F100\nM2\n").of(MoveKind::arc);
    ASSERT_EQ(shortway.size(), 1u);
    expect_point(shortway[0].centre, 10, 0, 0);
    EXPECT_NEAR(shortway[0].sweep(), pi / 2, 1e-9);
    expect_point(longway[0].centre, 0, 10, 0);
    EXPECT_NEAR(longway[0].sweep(), 3 * pi / 2, 1e-9);
    auto ccw = run("G90 G0 X0 Y0 Z0\nG3 X10 Y10 R10 F100\nM2\n").of(MoveKind::arc);
    expect_point(ccw[0].centre, 0, 10, 0);
}

TEST(MotionArcs, FullCircles) {
    auto c = run("G90 G0 X0 Y0 Z0\nG2 X0 Y0 I10 J0 F100\nM2\n");
    auto arcs = c.of(MoveKind::arc);
    ASSERT_EQ(arcs.size(), 1u);
    EXPECT_EQ(arcs[0].turns, 1);
    EXPECT_NEAR(arcs[0].sweep(), 2 * pi, 1e-9);
    EXPECT_NEAR(arcs[0].length(), 20 * pi, 1e-9);
    auto r = run("G90 G0 X0 Y0 Z0\nG2 X0 Y0 R10 F100\nM2\n");
    EXPECT_EQ(r.rule("arc-full-circle-r"), 1u);
    EXPECT_EQ(r.count(MoveKind::not_simulated), 1u);
    auto p = run("G90 G0 X10 Y0 Z0\nG3 X0 Y10 I-10 P3 F100\nM2\n").of(MoveKind::arc);  // LinuxCNC P: turns
    EXPECT_NEAR(p[0].sweep(), pi / 2 + 4 * pi, 1e-9);
}

TEST(MotionArcs, RShorterThanHalfTheChord) {
    auto c = run("G90 G0 X0 Y0 Z0\nG2 X30 Y0 R10 F100\nM2\n");
    EXPECT_EQ(c.rule("arc-radius-short"), 1u);
    auto ok = run("G90 G0 X0 Y0 Z0\nG2 X20 Y0 R10 F100\nM2\n");  // a half circle exactly
    EXPECT_EQ(ok.rule("arc-radius-short"), 0u);
}

// G17 G03 from (10,0,0) to (0,10,-5) around the Z axis: a quarter turn down 5 mm.
TEST(MotionArcs, Helix) {
    auto arcs = run("G90 G0 X10 Y0 Z0\nG3 X0 Y10 Z-5 I-10 J0 F100\nM2\n").of(MoveKind::arc);
    ASSERT_EQ(arcs.size(), 1u);
    expect_point(arcs[0].centre, 0, 0, 0);
    EXPECT_NEAR(arcs[0].length(), std::hypot(10 * pi / 2, 5), 1e-9);
    expect_point(arcs[0].end, 0, 10, -5);
}

// The end point moved off the circle along the radius by a given amount.
std::string off_circle(double radius, double off, const char* start) {
    std::ostringstream s;
    s << std::fixed;
    s.precision(6);
    s << start << "G90 G0 X" << radius << " Y0 Z0\nG3 X0 Y" << radius + off << " I" << -radius << " J0 F100\n";
    return s.str();
}

TEST(MotionTolerance, GostMicron) {
    auto inside = run(off_circle(10, 0.0009, "%\n") + "M02\n", Dialect::gost);
    auto outside = run(off_circle(10, 0.0011, "%\n") + "M02\n", Dialect::gost);
    EXPECT_EQ(inside.rule("arc-radius"), 0u);
    ASSERT_EQ(outside.rule("arc-radius"), 1u);
    EXPECT_NE(outside.findings[0].message.find("r1=10.0000 r2=10.0011"), std::string::npos)
        << outside.findings[0].message;
}

// LinuxCNC (interp_arc.cc, arc_data_ijk): off by more than 0.0283 mm AND by more than 0.1 % of the larger
// radius, or by more than 2.83 mm whatever the radius.
TEST(MotionTolerance, LinuxCncBothLimits) {
    EXPECT_EQ(run(off_circle(10, 0.0280, "") + "M2\n").rule("arc-radius"), 0u);    // 0.28 %, under 0.0283 mm
    EXPECT_EQ(run(off_circle(10, 0.0290, "") + "M2\n").rule("arc-radius"), 1u);    // 0.29 % and over 0.0283
    EXPECT_EQ(run(off_circle(100, 0.0990, "") + "M2\n").rule("arc-radius"), 0u);   // over 0.0283, 0.099 %
    EXPECT_EQ(run(off_circle(100, 0.1010, "") + "M2\n").rule("arc-radius"), 1u);   // 0.101 %
    EXPECT_EQ(run(off_circle(5000, 2.8000, "") + "M2\n").rule("arc-radius"), 0u);  // 0.056 %
    EXPECT_EQ(run(off_circle(5000, 2.8400, "") + "M2\n").rule("arc-radius"), 1u);  // over 100 x 0.0283
}

TEST(MotionTolerance, OptionWidens) {
    auto o = tape::motion_options(Dialect::gost);
    o.arc_tolerance_mm = 0.01;
    EXPECT_EQ(run(off_circle(10, 0.009, "%\n") + "M02\n", o).rule("arc-radius"), 0u);
    EXPECT_EQ(run(off_circle(10, 0.011, "%\n") + "M02\n", o).rule("arc-radius"), 1u);
}

TEST(MotionLathe, DiameterAndIncrementalUW) {
    auto o = tape::motion_options(Dialect::fanuc);
    o.lathe = true;
    auto c = run("O0001\nG00 X40. Z2.\nG01 U-10. W-5. F0.2\nG02 X40. Z-8. R5.\nM30\n", o);
    auto lines = c.of(MoveKind::linear);
    ASSERT_EQ(lines.size(), 1u);
    expect_point(lines[0].start, 20, 0, 2);
    expect_point(lines[0].end, 15, 0, -3);
    auto arcs = c.of(MoveKind::arc);
    ASSERT_EQ(arcs.size(), 1u);
    EXPECT_EQ(arcs[0].state.plane, tape::Plane::zx);
    expect_point(arcs[0].end, 20, 0, -8);
}

TEST(MotionLathe, LinuxCncDiameterMode) {
    auto o = tape::motion_options(Dialect::linuxcnc);
    o.lathe = true;
    auto c = run("G8 G0 X10 Z0\nG7 G0 X10 Z0\nM2\n", o);
    auto r = c.of(MoveKind::rapid);
    ASSERT_EQ(r.size(), 2u);
    EXPECT_NEAR(r[0].end.x, 10, 1e-9);
    EXPECT_NEAR(r[1].end.x, 5, 1e-9);
}

TEST(MotionWords, ImpliedPointPerDialect) {
    auto fanuc = run("O0001\nG90 G00 X1000 Y-2500 Z1.\nM30\n", Dialect::fanuc).of(MoveKind::rapid);
    ASSERT_EQ(fanuc.size(), 1u);
    expect_point(fanuc[0].end, 1, -2.5, 1);
    auto lcnc = run("G90 G0 X1 Y2 Z3\nM2\n").of(MoveKind::rapid);
    expect_point(lcnc[0].end, 1, 2, 3);
    auto gost = run("%\nN1 G90 G00 X1250 Y0\nN2 M02\n", Dialect::gost);
    EXPECT_EQ(gost.count(MoveKind::not_simulated), 1u);
    auto gost_points = run("%\nN1 G90 G00 X10. Y0\nN2 X1250\nN3 M02\n", Dialect::gost).of(MoveKind::rapid);
    ASSERT_EQ(gost_points.size(), 2u);
    EXPECT_NEAR(gost_points[1].end.x, 1250, 1e-9);  // §3.1.4: a whole number in a program with points
    static const tape::FormatSpec spec = tape::parse_format_spec("N03 G02 X+053 Y+053 Z+053 F031 M02");
    auto o = tape::motion_options(Dialect::gost);
    o.spec = &spec;
    auto spec_read = run("%\nN1 G90 G00 X+12500 Y0\nN2 M02\n", o).of(MoveKind::rapid);
    ASSERT_EQ(spec_read.size(), 1u);
    EXPECT_NEAR(spec_read[0].end.x, 12.5, 1e-9);
}

// The loader's digits (Word::digits_value) are read as the nearest double to the number written, the
// same as strtod; sixteen digits and more take the reading of the text, and a whole part of sixteen
// digits is no value any control reads.
TEST(MotionWords, NumbersAreTheNearestDoubles) {
    const char* written[] = {"123.456", "-0.001", ".5", "0.1", "499.999", "-2.675", "12345678901.2345", "7"};
    std::string text = "G90 G0 X0 Y0 Z0\n";
    for (const char* x : written) text += std::string("X") + x + "\n";
    text += "X1234567890.123456789\nX1234567890123456\nM2\n";
    auto c = run(text);
    auto r = c.of(MoveKind::rapid);
    ASSERT_EQ(r.size(), std::size(written) + 2);
    for (std::size_t k = 0; k < std::size(written); ++k)
        EXPECT_EQ(r[k + 1].end.x, std::strtod(written[k], nullptr)) << written[k];
    EXPECT_NEAR(r[std::size(written) + 1].end.x, 1234567890.123456789, 1e-6);  // 19 digits: the text's reading
    EXPECT_EQ(c.count(MoveKind::not_simulated), 1u);                           // 16 whole digits: unread
}

TEST(MotionWords, InchIncrementalAndKnownAxes) {
    auto c = run("G20 G90 G0 X1 Y0\nG91 X1 Z1\nG90 Z0\nM2\n");
    auto r = c.of(MoveKind::rapid);
    ASSERT_EQ(r.size(), 3u);
    EXPECT_NEAR(r[0].end.x, 25.4, 1e-9);
    EXPECT_EQ(r[0].end_known, unsigned(tape::axis_x | tape::axis_y));
    EXPECT_NEAR(r[1].end.x, 50.8, 1e-9);
    EXPECT_EQ(r[1].end_known & tape::axis_z, 0u);  // Z moved by an increment from an unknown place
    EXPECT_EQ(r[2].end_known, unsigned(tape::all_axes));
}

TEST(MotionWords, G92KeepsThePlaceKnown) {
    auto c = run("G90 G0 X5 Y5 Z5\nG92 X0 Y0 Z0\nG91 G0 X1\nM2\n");
    auto r = c.of(MoveKind::rapid);
    ASSERT_EQ(r.size(), 2u);
    expect_point(r[1].start, 0, 0, 0);
    expect_point(r[1].end, 1, 0, 0);
    EXPECT_EQ(r[1].known, unsigned(tape::all_axes));
}

TEST(MotionEvents, ToolSpindleCoolantDwellEnd) {
    auto c = run("%\nO0001\nN10 T2 M06\nN20 S1000 M03 M08\nN30 G04 P1500\nN40 M05 M09\nN50 M01\nN60 M30\n%\n",
                 Dialect::fanuc);
    std::vector<MoveKind> kinds;
    for (const auto& m : c.moves) kinds.push_back(m.kind);
    EXPECT_EQ(kinds,
              (std::vector<MoveKind>{MoveKind::tool_change, MoveKind::spindle, MoveKind::coolant, MoveKind::dwell,
                                     MoveKind::spindle, MoveKind::coolant, MoveKind::stop, MoveKind::program_end}));
    EXPECT_EQ(c.moves[0].code, 2);
    EXPECT_NEAR(c.moves[3].seconds, 1.5, 1e-9);
    EXPECT_EQ(c.moves[1].state.speed, 1000);
}

// G99 G81: to the hole at the initial level, down to R, feed to Z, back to R (G99); G98 back to the
// initial level.
TEST(MotionCycles, DrillingG81) {
    auto c = run("G90 G0 X0 Y0 Z50\nG99 G81 X10 Y10 Z-5 R2 F100\nX20\nG98 G81 X30 Z-5 R2\nG80\nM2\n");
    std::vector<std::pair<MoveKind, double>> zs;
    for (const auto& m : c.moves)
        if (m.depth == 1) zs.emplace_back(m.kind, m.end.z);
    std::vector<std::pair<MoveKind, double>> want = {
        {MoveKind::rapid, 50}, {MoveKind::rapid, 2}, {MoveKind::linear, -5}, {MoveKind::rapid, 2},
        {MoveKind::rapid, 2},  {MoveKind::rapid, 2}, {MoveKind::linear, -5}, {MoveKind::rapid, 2},
        {MoveKind::rapid, 2},  {MoveKind::rapid, 2}, {MoveKind::linear, -5}, {MoveKind::rapid, 50}};
    EXPECT_EQ(zs, want);
}

// G83 pecks every Q from R, back up to R after each; the last peck stops short of the bottom.
TEST(MotionCycles, PeckingG83) {
    auto c = run("G90 G0 X0 Y0 Z10\nG99 G83 X0 Y0 Z-10 R2 Q5 F100\nG80\nM2\n");
    std::vector<double> zs;
    for (const auto& m : c.moves)
        if (m.depth == 1) zs.push_back(m.end.z);
    EXPECT_EQ(zs, (std::vector<double>{10, 2, -3, 2, -3, -8, 2, -8, -10, 2}));
    auto exact = run("G90 G0 X0 Y0 Z10\nG99 G83 X0 Y0 Z-8 R2 Q5 F100\nG80\nM2\n");
    EXPECT_EQ(exact.count(MoveKind::linear), 2u);  // one peck at -3, then the bottom
}

// Hostile repeat counts and pecks: named at the block, never expanded into millions of moves.
TEST(MotionCycles, ExpansionBounded) {
    for (const char* text : {"G90 G0 X0 Y0 Z10\nG83 Z-100 R2 Q0.0001 F100\nG80\nM2\n",
                             "G91 G0 X0 Y0 Z10\nG81 X1 Z-1 R-1 L1000000 F100\nG80\nM2\n"}) {
        auto c = run(text);
        auto n = c.of(MoveKind::not_simulated);
        ASSERT_EQ(n.size(), 1u) << text;
        EXPECT_NE(n[0].note.find("more than 100 000 moves"), std::string::npos);
        EXPECT_LT(c.moves.size(), 10u);
    }
}

// A program's cycles together: 10 million moves, then each further cycle named.
TEST(MotionCycles, ExpansionBoundedByProgram) {
    struct Count : tape::MotionVisitor {
        std::size_t moves = 0;
        std::vector<std::string> notes;
        void move(const Move& m) override {
            ++moves;
            if (m.kind == MoveKind::not_simulated) notes.push_back(m.note);
        }
    } count;
    std::string text = "G90 G0 X0 Y0 Z10\nG98 G81 X0 Y0 Z-1 R2 L16000 F100\n";
    for (int i = 0; i < 105; ++i) text += "X1 L16000\n";  // L counts in its own block only
    tape::interpret_each(text + "G80\nM2\n", {}, count, tape::motion_options(Dialect::linuxcnc));
    ASSERT_EQ(count.notes.size(), 2u);
    EXPECT_NE(count.notes[0].find("10 million"), std::string::npos);
    EXPECT_LT(count.moves, 10'000'100u);
}

TEST(MotionNotSimulated, NamedAtItsBlock) {
    auto c = run("G90 G0 X0 Y0 Z0\nG0 X#1\nG1 X5 F10\nM2\n", Dialect::linuxcnc);
    auto n = c.of(MoveKind::not_simulated);
    ASSERT_EQ(n.size(), 1u);
    EXPECT_NE(n[0].note.find("X#1"), std::string::npos);
    EXPECT_EQ(n[0].where.line, 2u);
    EXPECT_EQ(n[0].end_known & tape::axis_x, 0u);
    EXPECT_EQ(c.of(MoveKind::linear)[0].end_known, unsigned(tape::all_axes));  // X5 sets it again
    auto unknown = run("G90 G0 X0 Y0 Z0\nG5.2 X1 Y1\nM2\n");
    EXPECT_EQ(unknown.count(MoveKind::not_simulated), 1u);
}

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The sample programs hold only what the interpreter covers, except the 16К20Ф3 tape, whose words have
// no decimal point and no format to place one.
TEST(MotionSamples, SampleTapesSimulated) {
    for (const char* name : {"circle-examples.txt", "gost-20999-format-example.txt", "koi7-comment.txt"}) {
        auto c = run(read(sample_path(name)), Dialect::gost);
        EXPECT_EQ(c.count(MoveKind::not_simulated), 0u) << name;
        EXPECT_GT(c.moves.size(), 0u) << name;
    }
    auto lathe = run(read(sample_path("16k20f3s5-turning.txt")), Dialect::gost);
    EXPECT_GT(lathe.count(MoveKind::not_simulated), 0u);
}

// Real programs from outside (../shared/data): those that hold only what the interpreter covers run
// with no move left out; in every one, every move is finite.
TEST(MotionSamples, OutsideProgramsCovered) {
    SKIP_WITHOUT_SHARED_DATA("outside2");
    const char* covered[] = {"outside/gcodes_circle.gcode",
                             "outside/lcnc/3dtest.ngc",
                             "outside/lcnc/arcspiral.ngc",
                             "outside/lcnc/cds.ngc",
                             "outside/lcnc/comp.ngc",
                             "outside/lcnc/hole-circle.ngc",
                             "outside/lcnc/lathe_pawn.ngc",
                             "outside/lcnc/lathecomp.ngc",
                             "outside/receiveFile1.nc",
                             "outside2/fanuc/gcw_FANUC0M.nc",
                             "outside2/fanuc/gcw_FANUC0T.nc",
                             "outside2/grbl/escriba_example11.gcode",
                             "outside2/grbl/pg328_bot_drill.nc",
                             "outside2/grbl/pg328_pta_etch.nc",
                             "outside2/haas/gcw_HAAS.nc",
                             "outside2/lcnc/lagun_HEMA-P005.ngc",
                             "outside2/other/gcw_TOKARKA.NC",
                             "outside3/cam/momemarian_Face.nc",
                             "outside3/cam/norn93_2_HELIX_BORES_modified.gcode",
                             "outside3/cam/norn93_demo.gcode",
                             "outside3/cam/sergey_EccentricFlag.nc",
                             "outside3/cam/sergey_adapter_BK12_1.tap",
                             "outside3/cam/sergey_petlya_step.nc",
                             "outside3/cam/shooshx_1024_block_14bit.nc",
                             "outside3/cam/shooshx_1110_wall_265bit.nc",
                             "outside3/fanuc/fcs_sub_2001.nc",
                             "outside3/haas/cade_TEAMMACHINE-ENGRAVE.nc",
                             "outside3/haas/cade_stepblock-steps-o78241.nc"};
    for (const char* name : covered) {
        if (!std::filesystem::exists(shared_data(name))) continue;
        std::string text = read(shared_data(name));
        if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
        auto c = run(text, tape::motion_options(tape::guess_dialect(text).dialect));
        EXPECT_EQ(c.count(MoveKind::not_simulated), 0u) << name;
        EXPECT_GT(c.moves.size(), 0u) << name;
        for (const auto& m : c.moves)
            ASSERT_TRUE(std::isfinite(m.end.x) && std::isfinite(m.end.y) && std::isfinite(m.end.z) &&
                        std::isfinite(m.length()))
                << name << " line " << m.where.line;
    }
}

}  // namespace
