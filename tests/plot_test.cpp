// Toolpath pictures (tape/toolpath.hpp): moves made by hand, laid out, cut down, and drawn by the plot
// module; the PNG's pixels looked at where the toolpath is and where it is not.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tape/picture.hpp"
#include "tape/scan.hpp"
#include "tape/toolpath.hpp"

namespace {

using tape::Move;
using tape::MoveKind;
using tape::Point;

Move line(Point a, Point b, MoveKind kind = MoveKind::linear, int tool = 1, std::uint64_t block = 1) {
    Move m;
    m.kind = kind;
    m.start = a;
    m.end = b;
    m.state.tool = tool;
    m.block = block;
    return m;
}

Move arc(Point a, Point b, Point c, bool clockwise, tape::Plane plane = tape::Plane::xy) {
    Move m = line(a, b, MoveKind::arc);
    m.centre = c;
    m.clockwise = clockwise;
    m.state.plane = plane;
    m.radius = std::hypot(a.x - c.x, a.y - c.y, a.z - c.z);
    m.end_radius = m.radius;
    return m;
}

tape::PlotOptions options(tape::PlotView view = tape::PlotView::xy) {
    tape::PlotOptions o;
    o.view = view;
    o.width = 600;
    o.height = 400;
    return o;
}

// Where a point of the part is on the page, as the plan says.
std::pair<double, double> page_at(const tape::PlotPlan& p, double u, double v) {
    return {p.x0 + u * p.scale, p.y0 - v * p.scale};
}

std::size_t arcs_in(const tape::PlotPlan& p) {
    std::size_t n = 0;
    for (const auto& s : p.strokes) n += s.arc;
    return n;
}

TEST(Plot, FitsThePartAndKeepsItsProportions) {
    tape::Toolpath path;
    path.move(line({0, 0, 0}, {100, 0, 0}));
    path.move(line({100, 0, 0}, {100, 50, 0}));
    tape::PlotPlan p = tape::plan_plot(path, options());
    auto [x0, y0] = page_at(p, 0, 0);
    auto [x1, y1] = page_at(p, 100, 50);
    EXPECT_GE(x0, 0);
    EXPECT_LE(x1, 600);
    EXPECT_LT(y1, y0);  // Y up on the page
    EXPECT_NEAR((x1 - x0) / (y0 - y1), 2.0, 1e-9);
    ASSERT_EQ(p.strokes.size(), 1u);  // one polyline: the feed goes on from where it stopped
    EXPECT_EQ(p.strokes[0].count, 3u);
}

TEST(Plot, CollinearMovesBecomeOneSegmentAndRepeatedPassesOne) {
    tape::Toolpath path;
    for (int i = 0; i < 1000; ++i) path.move(line({i * 0.1, 0, 0}, {(i + 1) * 0.1, 0, 0}));
    // The same square at three depths: from above, one square.
    for (double z : {-1.0, -2.0, -3.0}) {
        Point c[] = {{0, 10, z}, {100, 10, z}, {100, 60, z}, {0, 60, z}, {0, 10, z}};
        for (int k = 0; k < 4; ++k) path.move(line(c[k], c[k + 1]));
        path.move(line({0, 10, z}, {0, 10, z - 1}));  // the plunge to the next depth: a point from above
    }
    tape::PlotPlan p = tape::plan_plot(path, options());
    std::size_t segments = 0;
    for (const auto& s : p.strokes) segments += s.count - 1;
    std::string drawn;
    for (const auto& s : p.strokes)
        for (std::uint32_t k = 0; k < s.count; ++k)
            drawn += std::to_string(p.points[2 * (s.first + k)]) + "," +
                     std::to_string(p.points[2 * (s.first + k) + 1]) + (k + 1 < s.count ? " " : "\n");
    EXPECT_EQ(segments, 1u + 4u) << drawn;
}

TEST(Plot, MovesUnderAPixelAreDroppedButTheirWayIsKept) {
    tape::Toolpath path;
    // A zigzag of 0.01 mm steps going up 100 mm: at 3 px/mm no step shows, the way up does.
    double y = 0;
    for (int i = 0; i < 10000; ++i, y += 0.01) path.move(line({i % 2 * 0.01, y, 0}, {(i + 1) % 2 * 0.01, y + 0.01, 0}));
    path.move(line({0, y, 0}, {100, y, 0}));
    tape::PlotPlan p = tape::plan_plot(path, options());
    EXPECT_LT(p.points.size() / 2, 400u);
    auto [tx, ty] = page_at(p, 100, y);
    EXPECT_NEAR(p.points[p.points.size() - 2], tx, 0.01);
    EXPECT_NEAR(p.points.back(), ty, 0.01);
}

// The page's angles grow clockwise (y down): an arc that turns clockwise as seen goes from a0 up to a1.
bool clockwise_on_page(const tape::PlotPlan& p) {
    for (const auto& s : p.strokes)
        if (s.arc) return s.a1 > s.a0;
    ADD_FAILURE() << "no arc drawn";
    return false;
}

TEST(Plot, ArcsAreTrueArcsTurningAsSeenFromTheView) {
    // G02 in G17 from above: clockwise.
    tape::Toolpath xy;
    xy.move(arc({0, 0, 0}, {20, 0, 0}, {10, 0, 0}, true));
    tape::PlotPlan p = tape::plan_plot(xy, options());
    EXPECT_EQ(arcs_in(p), 1u);
    EXPECT_TRUE(clockwise_on_page(p));
    // G02 in G18 is clockwise seen from +Y; the front view looks from -Y: counterclockwise there
    // (CAMotics#96, UGS#853: the backplots that drew it the other way).
    tape::Toolpath zx;
    zx.move(arc({0, 0, 0}, {0, 0, 20}, {0, 0, 10}, true, tape::Plane::zx));
    EXPECT_FALSE(clockwise_on_page(tape::plan_plot(zx, options(tape::PlotView::xz))));
    // A lathe with its tool behind the axis is seen from +Y (X up): clockwise; in front (X down): not.
    tape::PlotOptions lathe = options(tape::PlotView::lathe);
    EXPECT_TRUE(clockwise_on_page(tape::plan_plot(zx, lathe)));
    lathe.front_post = true;
    EXPECT_FALSE(clockwise_on_page(tape::plan_plot(zx, lathe)));
    // From above the G18 arc is edge on: a line along X, no arc.
    EXPECT_EQ(arcs_in(tape::plan_plot(zx, options())), 0u);
}

TEST(Plot, AnArcIsFittedByTheWayItBulges) {
    // A half circle above its chord: the page holds its top, 10 mm over the chord.
    tape::Toolpath path;
    path.move(arc({0, 0, 0}, {20, 0, 0}, {10, 0, 0}, true));
    tape::PlotPlan p = tape::plan_plot(path, options());
    auto [x, y] = page_at(p, 10, 10);
    EXPECT_GE(y, 59.0);  // under the title's band
    EXPECT_GT(x, 0);
}

TEST(Plot, DoubtfulMovesAreDrawnInTheDoubtColourAndNothingIsDrawnWithoutMoves) {
    tape::Toolpath path;
    Move m = line({0, 0, 0}, {10, 0, 0});
    m.where.frame = 40;
    m.last_frame = 52;
    path.move(m);
    m = line({10, 0, 0}, {10, 10, 0});
    m.where.frame = 53;
    m.last_frame = 60;
    path.move(m);
    path.mark_doubtful({45});
    ASSERT_TRUE(path.moves()[0].doubt);
    ASSERT_FALSE(path.moves()[1].doubt);
    tape::PlotPlan p = tape::plan_plot(path, options());
    bool doubt_drawn = false;
    for (const auto& s : p.strokes) doubt_drawn |= p.styles[s.style].rgb == 0xe69a1c;
    EXPECT_TRUE(doubt_drawn);
    EXPECT_THROW(tape::plan_plot(tape::Toolpath(), options()), tape::Error);
}

TEST(Plot, AViewDrawsTheMovesWhoseTwoAxesAreKnown) {
    tape::Toolpath path;
    Move first = line({0, 0, 0}, {10, 0, 0});
    first.known = 0;  // a program's first move: from where the tool stood before it
    path.move(first);
    EXPECT_EQ(path.unknown_moves(), 1u);
    Move flat = line({10, 0, 0}, {20, 5, 0});
    flat.known = tape::axis_x | tape::axis_y;  // Z never set
    path.move(flat);
    ASSERT_EQ(path.moves().size(), 1u);
    tape::PlotPlan above = tape::plan_plot(path, options());
    EXPECT_EQ(above.moves_drawn, 1u);
    EXPECT_EQ(above.unplaced, 0u);
    EXPECT_THROW(tape::plan_plot(path, options(tape::PlotView::xz)), tape::Error);
}

TEST(Plot, PngPixelsShowTheFeedWhereItIsAndPaperElsewhere) {
    if (!tape::plot_available()) GTEST_SKIP() << tape::plot_unavailable_message();
    if (!tape::scan_available()) GTEST_SKIP() << "reading the PNG back: " << tape::scan_unavailable_message();
    tape::Toolpath path;
    Point c[] = {{0, 0, 0}, {100, 0, 0}, {100, 50, 0}, {0, 50, 0}};
    for (int k = 0; k < 4; ++k) path.move(line(c[k], c[(k + 1) % 4], MoveKind::linear, 1));
    path.move(line({0, 0, 0}, {50, 25, 0}, MoveKind::rapid, 2));
    tape::PlotPlan p = tape::plan_plot(path, options());
    auto bytes = tape::draw_plot(p, "png");
    tape::Picture pic = tape::decode_picture(bytes);
    ASSERT_EQ(pic.width, 600);
    ASSERT_EQ(pic.height, 400);
    auto bgr = [&](double u, double v) {
        // The pixel whose square lies inside the 2-unit-wide line centred on the point.
        auto [x, y] = page_at(p, u, v);
        const std::uint8_t* px = pic.at(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
        return std::array<int, 3>{px[0], px[1], px[2]};
    };
    // T1, the first tool, in 0x1f5fbf: blue over red.
    for (auto [u, v] : {std::pair{50.0, 0.0}, {100.0, 25.0}, {30.0, 50.0}, {0.0, 40.0}}) {
        auto px = bgr(u, v);
        EXPECT_GT(px[0], 150) << u << "," << v;
        EXPECT_LT(px[2], 90) << u << "," << v;
    }
    for (auto [u, v] : {std::pair{75.0, 10.0}, {20.0, 40.0}}) {
        auto px = bgr(u, v);
        EXPECT_EQ(px[0] + px[1] + px[2], 3 * 255) << u << "," << v;  // paper
    }
}

TEST(Plot, SvgAndPdfComeFromTheSameDrawing) {
    if (!tape::plot_available()) GTEST_SKIP() << tape::plot_unavailable_message();
    tape::Toolpath path;
    path.move(arc({0, 0, 0}, {20, 0, 0}, {10, 0, 0}, true));
    tape::PlotPlan p = tape::plan_plot(path, options());
    auto svg = tape::draw_plot(p, "svg");
    std::string text(svg.begin(), svg.end());
    EXPECT_NE(text.find("<svg"), std::string::npos);
    EXPECT_NE(text.find("width=\"600px\""), std::string::npos) << text.substr(0, 300);
    auto pdf = tape::draw_plot(p, "pdf");
    ASSERT_GT(pdf.size(), 5u);
    EXPECT_EQ(std::string(pdf.begin(), pdf.begin() + 5), "%PDF-");
}

TEST(Plot, FormatsByExtension) {
    EXPECT_EQ(tape::plot_format_for_path("part.SVG"), "svg");
    EXPECT_EQ(tape::plot_format_for_path("a/b.htm"), "html");
    EXPECT_EQ(tape::plot_format_for_path("part.pdf"), "pdf");
    EXPECT_EQ(tape::plot_format_for_path("part.jpg"), "");
}

}  // namespace
