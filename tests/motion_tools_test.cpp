// Programs compared by what they cut (tape/motion_diff.hpp) and their figures (tape/motion_stats.hpp), on
// moves made by hand: the geometry worked out in each test.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tape/motion_diff.hpp"
#include "tape/motion_stats.hpp"

namespace {

using tape::Move;
using tape::MoveKind;
using tape::Point;

Move line(Point a, Point b, MoveKind kind = MoveKind::linear, double feed = 100, int tool = 1) {
    Move m;
    m.kind = kind;
    m.start = a;
    m.end = b;
    m.state.feed = feed;
    m.state.tool = tool;
    return m;
}

Move arc(Point a, Point b, Point c, bool clockwise, double feed = 100) {
    Move m = line(a, b, MoveKind::arc, feed);
    m.centre = c;
    m.clockwise = clockwise;
    m.radius = m.end_radius = std::hypot(a.x - c.x, a.y - c.y);
    return m;
}

std::vector<tape::PathPiece> pieces(std::initializer_list<Move> moves, double tol = 0.001) {
    tape::MotionPieces p(tol);
    for (const auto& m : moves) p.move(m);
    return p.pieces();
}

TEST(MotionDiff, ALineSplitInThreeIsOneLine) {
    auto one = pieces({line({0, 0, 0}, {30, 0, 0})});
    auto three = pieces({line({0, 0, 0}, {10, 0, 0}), line({10, 0, 0}, {20, 0, 0}), line({20, 0, 0}, {30, 0, 0})});
    ASSERT_EQ(three.size(), 1u);
    EXPECT_EQ(three[0].moves, 3u);
    EXPECT_TRUE(tape::compare_motion(one, three, 0.001).same);
}

TEST(MotionDiff, AnArcSplitInTwoIsOneArcAndAFullCircleByHalvesIsACircle) {
    // A quarter of the circle of radius 20 about (50, 30), from (50, 10) to (70, 30) counterclockwise;
    // split at 45 degrees.
    double h = 20 / std::numbers::sqrt2;
    auto whole = pieces({arc({50, 10, 0}, {70, 30, 0}, {50, 30, 0}, false)});
    auto halves = pieces({arc({50, 10, 0}, {50 + h, 30 - h, 0}, {50, 30, 0}, false),
                          arc({50 + h, 30 - h, 0}, {70, 30, 0}, {50, 30, 0}, false)});
    ASSERT_EQ(halves.size(), 1u);
    EXPECT_NEAR(halves[0].sweep, std::numbers::pi / 2, 1e-9);
    EXPECT_TRUE(tape::compare_motion(whole, halves, 0.001).same);
    // The other way round the same ends is not the same arc.
    auto clockwise = pieces({arc({50, 10, 0}, {70, 30, 0}, {50, 30, 0}, true)});
    auto d = tape::compare_motion(whole, clockwise, 0.001);
    EXPECT_FALSE(d.same);
    EXPECT_EQ(d.index, 0u);
    // Two halves of a circle and the full circle by I/J (turns 1, start on end).
    Move circle = arc({0, 0, 0}, {0, 0, 0}, {10, 0, 0}, true);
    circle.turns = 1;
    auto by_halves =
        pieces({arc({0, 0, 0}, {20, 0, 0}, {10, 0, 0}, true), arc({20, 0, 0}, {0, 0, 0}, {10, 0, 0}, true)});
    EXPECT_TRUE(tape::compare_motion(pieces({circle}), by_halves, 0.001).same);
}

TEST(MotionDiff, TheFirstDifferenceIsFoundWithinTheTolerance) {
    auto a = pieces({line({0, 0, 50}, {10, 10, 2}, MoveKind::rapid), line({10, 10, 2}, {10, 10, -5}),
                     line({10, 10, -5}, {50, 10, -5})});
    auto just_inside = pieces({line({0, 0, 50}, {10, 10, 2}, MoveKind::rapid), line({10, 10, 2}, {10, 10, -5.0009}),
                               line({10, 10, -5.0009}, {50, 10, -5})});
    EXPECT_TRUE(tape::compare_motion(a, just_inside, 0.001).same);
    auto outside = pieces({line({0, 0, 50}, {10, 10, 2}, MoveKind::rapid), line({10, 10, 2}, {10, 10, -5.002}),
                           line({10, 10, -5.002}, {50, 10, -5})});
    auto d = tape::compare_motion(a, outside, 0.001);
    ASSERT_FALSE(d.same);
    EXPECT_EQ(d.index, 1u);
    EXPECT_EQ(d.what, "they end at different places");
    // A rapid where the other feeds.
    auto fed = pieces({line({0, 0, 50}, {10, 10, 2})});
    EXPECT_EQ(tape::compare_motion(a, fed, 0.001).what, "not the same kind of move");
    // One program ends early.
    auto shorter = pieces({line({0, 0, 50}, {10, 10, 2}, MoveKind::rapid)});
    d = tape::compare_motion(a, shorter, 0.001);
    EXPECT_FALSE(d.same);
    EXPECT_FALSE(d.second);
}

TEST(MotionDiff, AMoveNotSimulatedLeavesNoAnswer) {
    Move macro;
    macro.kind = MoveKind::not_simulated;
    macro.note = "X#1: a macro value known only when the program runs";
    auto a = pieces({line({0, 0, 0}, {10, 0, 0}), macro});
    auto d = tape::compare_motion(a, a, 0.001);
    EXPECT_FALSE(d.same);
    EXPECT_TRUE(d.cannot_tell);
}

TEST(MotionStats, PerToolBoundsLengthsAndTimes) {
    tape::MotionStats stats(10000);                                      // rapids at 10 m/min
    stats.move(line({0, 0, 50}, {0, 0, 0}, MoveKind::rapid, 0, 1));      // 50 mm at rapid
    stats.move(line({0, 0, 0}, {100, 0, 0}, MoveKind::linear, 200, 1));  // 100 mm at 200 mm/min: 0.5 min
    // T2: a half circle of radius 10 about (10, 0), clockwise from (0, 0) over the top to (20, 0): up to y 10.
    Move half = arc({0, 0, 0}, {20, 0, 0}, {10, 0, 0}, true, 100);
    half.state.tool = 2;
    stats.move(half);
    const auto& f = stats.figures();
    ASSERT_EQ(f.tools.size(), 2u);
    const auto& t1 = f.tools[0];
    EXPECT_EQ(t1.tool, 1);
    EXPECT_DOUBLE_EQ(t1.rapid_mm, 50);
    EXPECT_DOUBLE_EQ(t1.cutting_mm, 100);
    EXPECT_DOUBLE_EQ(t1.cutting_min, 0.5);
    EXPECT_DOUBLE_EQ(t1.rapid_min, 0.005);
    EXPECT_DOUBLE_EQ(t1.max.x, 100);
    EXPECT_DOUBLE_EQ(t1.max.z, 50);
    const auto& t2 = f.tools[1];
    EXPECT_NEAR(t2.cutting_mm, 10 * std::numbers::pi, 1e-9);
    EXPECT_NEAR(t2.max.y, 10, 1e-9);
    EXPECT_NEAR(t2.min.y, 0, 1e-9);
    EXPECT_NEAR(f.total.cutting_min, 0.5 + 10 * std::numbers::pi / 100, 1e-9);
}

TEST(MotionStats, AFeedWithNoFeedRateIsNotTimed) {
    tape::MotionStats stats;
    stats.move(line({0, 0, 0}, {10, 0, 0}, MoveKind::linear, 0));
    EXPECT_EQ(stats.figures().total.untimed, 1u);
    EXPECT_EQ(stats.figures().total.cutting_min, 0);
    EXPECT_EQ(stats.figures().total.rapid_min, 0);
}

}  // namespace
