// A Fanuc lathe's cycles in the interpreter (src/motion/lathe_cycles.cpp, cycles.cpp): G71/G70 drawn as
// their P-Q contour, G76 and G92 threads as passes, with the points worked by hand in each test; real
// Haas lathe programs from ../shared/data.
#include "motion/lathe_cycles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "tape/motion.hpp"
#include "test_util.hpp"

namespace {

using tape::Move;
using tape::MoveKind;

struct Collect : tape::MotionVisitor {
    std::vector<Move> moves;
    void move(const Move& m) override { moves.push_back(m); }
    std::vector<Move> paths() const {  // rapids, lines and arcs, in order
        std::vector<Move> out;
        for (const auto& m : moves)
            if (m.kind == MoveKind::rapid || m.kind == MoveKind::linear || m.kind == MoveKind::arc) out.push_back(m);
        return out;
    }
    std::vector<Move> unsimulated() const {
        std::vector<Move> out;
        for (const auto& m : moves)
            if (m.kind == MoveKind::not_simulated) out.push_back(m);
        return out;
    }
};

Collect lathe(const std::string& text) {
    auto o = tape::motion_options(tape::Dialect::fanuc);
    o.lathe = true;
    Collect c;
    tape::interpret_each(text, {}, c, o);
    return c;
}

// A move's kind and its end in X (a radius) and Z.
void expect_move(const Move& m, MoveKind kind, double x, double z, int depth = 1) {
    EXPECT_EQ(m.kind, kind) << "line " << m.where.line;
    EXPECT_NEAR(m.end.x, x, 1e-9) << "line " << m.where.line;
    EXPECT_NEAR(m.end.z, z, 1e-9) << "line " << m.where.line;
    EXPECT_EQ(m.depth, depth) << "line " << m.where.line;
}

constexpr auto R = MoveKind::rapid;
constexpr auto L = MoveKind::linear;

// X50 Z2 is the start point (radius 25). G71's contour drawn where roughing leaves it, U0.4 W0.1 over
// the finished shape (X +0.2 as a radius, Z +0.1), then back to the start; G70 along the shape itself.
const char* g71_g70 =
    "O0001\nN10 G00 X50. Z2.\nN20 G71 U2. R0.5\nN30 G71 P40 Q70 U0.4 W0.1 F0.25\n"
    "N40 G00 X20.\nN50 G01 Z-10. F0.1\nN60 X40. Z-20.\nN70 Z-30.\n"
    "N80 G70 P40 Q70\nN90 X60.\nN100 M30\n";

void expect_g71_g70(const Collect& c, int contour_line) {
    auto p = c.paths();
    ASSERT_EQ(p.size(), 12u);
    expect_move(p[0], R, 25, 2, 0);
    EXPECT_NEAR(p[1].start.x, 25, 1e-9);  // from the start point to the shifted contour
    expect_move(p[1], R, 10.2, 2.1);
    EXPECT_EQ(p[1].where.line, static_cast<std::uint64_t>(contour_line));
    expect_move(p[2], L, 10.2, -9.9);
    EXPECT_NEAR(p[2].start.x, 10.2, 1e-9);
    expect_move(p[3], L, 20.2, -19.9);
    expect_move(p[4], L, 20.2, -29.9);
    expect_move(p[5], R, 25, 2);  // the return to the start point
    // G70 (line 9): the finished shape, then back.
    expect_move(p[6], R, 10, 2);
    expect_move(p[7], L, 10, -10);
    expect_move(p[8], L, 20, -20);
    expect_move(p[9], L, 20, -30);
    expect_move(p[10], R, 25, 2);
    for (int i = 6; i <= 10; ++i)
        EXPECT_EQ(p[static_cast<std::size_t>(i)].where.line, static_cast<std::uint64_t>(contour_line + 4));
    // After the cycles the mode of N10 (G00) is in force again: N90's X60. is a rapid from the start.
    expect_move(p[11], R, 30, 2, 0);
    EXPECT_TRUE(c.unsimulated().empty());
}

TEST(LatheCycles, G71TwoBlockContourThenG70) { expect_g71_g70(lathe(g71_g70), 5); }

// The one-block form of the 0/6 controls and Haas (D: the depth of cut, not drawn) draws the same.
TEST(LatheCycles, G71OneBlockForm) {
    expect_g71_g70(lathe("O0001\nN10 G00 X50. Z2.\nN30 G71 P40 Q70 U0.4 W0.1 D2000 F0.25\n"
                         "N40 G00 X20.\nN50 G01 Z-10. F0.1\nN60 X40. Z-20.\nN70 Z-30.\n"
                         "N80 G70 P40 Q70\nN90 X60.\nN100 M30\n"),
                   4);
}

// A contour not where the cycle says: said at the cycle's block; the blocks after it run as written.
TEST(LatheCycles, ContourNotFoundIsSaidAtTheCycle) {
    auto c = lathe("O0001\nG00 X50. Z2.\nG71 P45 Q70 U0.4 W0.1 F0.25\nN40 G00 X20.\nN70 Z-30.\nM30\n");
    auto ns = c.unsimulated();
    ASSERT_EQ(ns.size(), 1u);
    EXPECT_EQ(ns[0].where.line, 3u);
    EXPECT_NE(ns[0].note.find("N45"), std::string::npos) << ns[0].note;
    auto p = c.paths();
    ASSERT_EQ(p.size(), 3u);
    expect_move(p[1], R, 10, 2, 0);
    expect_move(p[2], R, 10, -30, 0);
    // G70 of a contour no cycle drew, with nothing after it: said at the G70 at the program's end.
    auto g70 = lathe("O0001\nG00 X50. Z2.\nG70 P40 Q70\n").unsimulated();
    ASSERT_EQ(g70.size(), 1u);
    EXPECT_EQ(g70[0].where.line, 3u);
    // The program ends inside the contour: said at the cycle too.
    auto open = lathe("O0001\nG00 X50. Z2.\nG71 P40 Q70 U0.4 W0.1 F0.25\nN40 G00 X20.\nM30\n").unsimulated();
    ASSERT_EQ(open.size(), 1u);
    EXPECT_EQ(open[0].where.line, 3u);
    EXPECT_NE(open[0].note.find("N70"), std::string::npos) << open[0].note;
}

// Pass depths from the crest, k 0.92, first cut 0.4, minimum 0.1, allowance 0.05, one finishing pass:
// 0.4, 0.4√2, 0.4√3, 0.8 (0.4√4), then 0.4√5 = 0.894 is past 0.87 (k - d): 0.87; then 0.92.
TEST(LatheCycles, ThreadDepths) {
    auto d = tape::motion::thread_depths(0.92, 0.4, 0.1, 0.05, 1);
    std::vector<double> want = {0.4, 0.4 * std::sqrt(2.0), 0.4 * std::sqrt(3.0), 0.8, 0.87, 0.92};
    ASSERT_EQ(d.size(), want.size());
    for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(d[i], want[i], 1e-12) << i;
    // The minimum cut: 0.4√2 - 0.4 = 0.166 is under 0.2, so the second pass goes to 0.6.
    EXPECT_NEAR(tape::motion::thread_depths(0.92, 0.4, 0.2, 0, 0)[1], 0.6, 1e-12);
    EXPECT_TRUE(tape::motion::thread_depths(0.92, 0, 0, 0, 1).empty());
    EXPECT_TRUE(tape::motion::thread_depths(1e9, 1e-9, 0, 0, 1).empty());
}

// Depths written in decimal are not exact in binary: a pass that reaches the thread's height but for
// rounding reaches it, and a count of passes of exactly the bound is within it. K0.043075 D0.01076875
// is 4 first cuts deep: 16 passes, however the two values were rounded; K0.007 D0.00007 is 10 000.
TEST(LatheCycles, ThreadDepthsAreNotMadeByRounding) {
    for (double first : {0.01076875, std::nextafter(0.01076875, 0.0), std::nextafter(0.01076875, 1.0)}) {
        auto d = tape::motion::thread_depths(0.043075, first, 0, 0, 0);
        ASSERT_EQ(d.size(), 16u) << first;
        EXPECT_EQ(d.back(), 0.043075);
    }
    EXPECT_EQ(tape::motion::thread_depths(0.007, 0.00007, 0, 0, 0, 10000).size(), 10000u);
    EXPECT_TRUE(tape::motion::thread_depths(0.007, 0.00007, 0, 0, 0, 9999).empty());
}

// G76 two-block, M30x1.5 outside: X26.16 is the root at the end (radius 13.08), P920 the height 0.92,
// Q400 the first cut 0.4, Q100 the minimum 0.1, R0.05 the allowance. Each pass: X in to
// 13.08 + (0.92 - depth), along Z to -20, X out to 15, Z back to 5.
TEST(LatheCycles, G76TwoBlockPasses) {
    auto c = lathe("O0002\nG00 X30. Z5.\nG76 P010060 Q100 R0.05\nG76 X26.16 Z-20. R0 P920 Q400 F1.5\nM30\n");
    EXPECT_TRUE(c.unsimulated().empty());
    auto p = c.paths();
    ASSERT_EQ(p.size(), 1u + 6 * 4);
    std::vector<double> depths = {0.4, 0.4 * std::sqrt(2.0), 0.4 * std::sqrt(3.0), 0.8, 0.87, 0.92};
    for (std::size_t i = 0; i < depths.size(); ++i) {
        double x = 13.08 + (0.92 - depths[i]);
        expect_move(p[1 + 4 * i], R, x, 5);
        expect_move(p[2 + 4 * i], L, x, -20);
        expect_move(p[3 + 4 * i], R, 15, -20);
        expect_move(p[4 + 4 * i], R, 15, 5);
    }
}

// The one-block form (Haas, Fanuc 0/6): K the height, D the first cut; its last pass reaches K:
// 0.4, 0.4√2, 0.4√3, 0.8, 0.4√5, then 0.4√6 = 0.98 is past 0.92: 0.92. Taper I-1.: each pass starts
// 1 mm (radius) below where it ends.
TEST(LatheCycles, G76OneBlockPasses) {
    auto c = lathe("O0002\nG00 X30. Z5.\nG76 X26.16 Z-20. I-1. K0.92 D0.4 F1.5\nM30\n");
    EXPECT_TRUE(c.unsimulated().empty());
    auto p = c.paths();
    ASSERT_EQ(p.size(), 1u + 6 * 4);
    expect_move(p[1], R, 13.08 + 0.52 - 1, 5);
    expect_move(p[2], L, 13.08 + 0.52, -20);
    expect_move(p[21], R, 13.08 - 1, 5);
    expect_move(p[22], L, 13.08, -20);
}

// G92 (G-code system A): a thread pass a block, Z kept from the first: X in, thread at the feed, X out
// at rapid, Z back.
TEST(LatheCycles, G92ThreadPasses) {
    auto c = lathe("O0003\nG00 X30. Z5.\nG92 X27.4 Z-20. F1.5\nX26.8\nX26.16\nG00 X100. Z100.\nM30\n");
    EXPECT_TRUE(c.unsimulated().empty());
    auto p = c.paths();
    ASSERT_EQ(p.size(), 2u + 3 * 4);
    double xs[] = {13.7, 13.4, 13.08};
    for (std::size_t i = 0; i < 3; ++i) {
        expect_move(p[1 + 4 * i], R, xs[i], 5);
        expect_move(p[2 + 4 * i], L, xs[i], -20);
        expect_move(p[3 + 4 * i], R, 15, -20);
        expect_move(p[4 + 4 * i], R, 15, 5);
    }
    expect_move(p[13], R, 50, 100, 0);
}

// ",C1." (chamfer) and ",R2." (rounding) between G01 moves, X as a radius: from X5 Z0 to X10 Z0, ,C1. cuts
// it 1 short (X9) and chamfers to 1 along the next move (X10 Z-1); down to Z-10, ,R2. turns 90° to +X:
// the tangent points 2·tan(45°) = 2 from the corner (X10 Z-8, X12 Z-10), the centre X12 Z-8, clockwise
// seen from +Y (going -Z then +X turns right with Z across and X up).
TEST(LatheCycles, CornerWordsDrawn) {
    auto c = lathe("O0001\nG00 X10. Z0\nG01 X20. ,C1. F0.2\nG01 Z-10. ,R2.\nX30.\nM30\n");
    EXPECT_TRUE(c.unsimulated().empty());
    auto p = c.paths();
    ASSERT_EQ(p.size(), 6u);
    expect_move(p[1], L, 9, 0, 0);
    expect_move(p[2], L, 10, -1, 0);
    EXPECT_EQ(p[2].where.line, 3u);
    EXPECT_NEAR(p[3].start.z, -1, 1e-9);
    expect_move(p[3], L, 10, -8, 0);
    expect_move(p[4], MoveKind::arc, 12, -10, 0);
    EXPECT_EQ(p[4].where.line, 4u);
    EXPECT_NEAR(p[4].centre.x, 12, 1e-9);
    EXPECT_NEAR(p[4].centre.z, -8, 1e-9);
    EXPECT_TRUE(p[4].clockwise);
    EXPECT_NEAR(p[4].radius, 2, 1e-9);
    EXPECT_NEAR(p[4].sweep(), std::acos(-1.0) / 2, 1e-9);
    EXPECT_NEAR(p[5].start.x, 12, 1e-9);
    expect_move(p[5], L, 15, -10, 0);
    // A chamfer as long as its move takes all of it: the chamfer starts where the move did.
    auto whole = lathe("O0001\nG00 X10. Z0\nG01 Z-2. ,C2. F0.2\nX20.\nM30\n").paths();
    ASSERT_EQ(whole.size(), 3u);
    EXPECT_NEAR(whole[1].start.z, 0, 1e-9);
    expect_move(whole[1], L, 7, -2, 0);
    expect_move(whole[2], L, 10, -2, 0);
    // A corner that cannot be drawn (the next move a rapid; no move after it): said at its block.
    auto ns = lathe("O0001\nG00 X10. Z0\nG01 X20. ,C1. F0.2\nG00 Z-10.\nG01 X30. ,R1.\n").unsimulated();
    ASSERT_EQ(ns.size(), 2u);
    EXPECT_EQ(ns[0].where.line, 3u);
    EXPECT_NE(ns[0].note.find("chamfer"), std::string::npos) << ns[0].note;
    EXPECT_EQ(ns[1].where.line, 5u);
}

std::string outside(const std::string& name) {
    std::string text = read_text(shared_data(name));
    if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
    return text;
}

// Haas lathe programs: G71 in one block with D, then G70. No G20: the unit is the control's setting, read
// here as written. The contour of N46..N55 drawn at U0.005 (X +0.0025 as a radius), back to X2.0 Z0.1
// (the start point); G70 along it from X2.0 Z-0.1, where the chamfer after the contour left the tool.
TEST(LatheCycles, HaasLatheProgramsCovered) {
    SKIP_WITHOUT_SHARED_DATA("outside3/haas");
    auto c = lathe(outside("outside3/haas/cade_lathe-l5.nc"));
    EXPECT_TRUE(c.unsimulated().empty());
    std::vector<Move> g71, g70;
    for (const auto& m : c.paths()) {
        if (m.depth == 1 && m.where.line >= 17 && m.where.line <= 26) g71.push_back(m);
        if (m.where.line == 40) g70.push_back(m);
    }
    ASSERT_EQ(g71.size(), 11u);  // N46..N55 and the return
    ASSERT_EQ(g70.size(), 11u);
    expect_move(g71[0], R, 1.55 / 2 + 0.0025, 0.1);
    expect_move(g71[9], L, 1.45 / 2 + 0.0025, -2.0);
    expect_move(g71[10], R, 1.0, 0.1);
    EXPECT_NEAR(g70[0].start.z, -0.1, 1e-9);
    expect_move(g70[0], R, 1.55 / 2, 0.1);
    expect_move(g70[9], L, 1.45 / 2, -2.0);
    expect_move(g70[10], R, 1.0, -0.1);
    EXPECT_TRUE(lathe(outside("outside3/haas/cade_O58214.nc")).unsimulated().empty());
    // G71, G70 and a G76 in one block; only its G75 (grooving in passes) is not simulated.
    auto pin = lathe(outside("outside3/haas/enier_weld_pin.nc"));
    auto ns = pin.unsimulated();
    ASSERT_EQ(ns.size(), 1u);
    EXPECT_NE(ns[0].note.find("G75"), std::string::npos) << ns[0].note;
    // "G71 P45 Q58" with no N58 in the program: said at its block (and the G71 inside its contour at its).
    auto snowman = lathe(outside("outside3/haas/cade_O58215.nc")).unsimulated();
    bool said = false;
    for (const auto& m : snowman) said |= m.where.line == 15 && m.note.find("N58") != std::string::npos;
    EXPECT_TRUE(said);
}

}  // namespace
