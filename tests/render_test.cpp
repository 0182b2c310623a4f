// The tape drawn as SVG: to scale, the same bytes every run, valid XML (checked with xmllint), the
// marks and ranges where they were asked for. tests/render/browser_check.py looks at it in Chromium.
#include "tape/render.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>

#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"
#include "test_util.hpp"

using namespace tape;
using namespace tape::svg_geometry;

namespace {

std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (auto at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
}

std::string circle_at(Point p) {
    return "<circle cx=\"" + std::to_string(p.x) + "\" cy=\"" + std::to_string(p.y) + "\"";
}

}  // namespace

TEST(Render, OneHoleForEveryPunchedTrackAndAFeedHoleForEveryFrame) {
    std::vector<Frame> frames = {0x00, 0xFF, 0x01, 0x80, 0xA5};
    std::string svg = render_svg(frames, {});
    std::size_t holes = 0;
    for (Frame f : frames) holes += static_cast<std::size_t>(hole_count(f));
    EXPECT_EQ(count(svg, "r=\"91.5\""), holes);          // code holes 1.83 mm across
    EXPECT_EQ(count(svg, "r=\"58.5\""), frames.size());  // feed holes 1.17 mm across
    EXPECT_NE(svg.find(circle_at(hole_centre(2, 1, frames_per_strip(254), false))), std::string::npos);
    EXPECT_EQ(svg.find(circle_at(hole_centre(2, 2, frames_per_strip(254), false))), std::string::npos);
}

TEST(Render, ToScale) {
    // Frames and tracks 2.54 mm apart; the tape 25.4 mm wide; the feed hole between tracks 3 and 4.
    auto a = hole_centre(0, 1, 100, false), b = hole_centre(1, 1, 100, false);
    EXPECT_EQ(b.x - a.x, 254);
    EXPECT_EQ(hole_centre(0, 8, 100, false).y, hole_centre(0, 1, 100, false).y - 8 * 254);
    EXPECT_EQ(hole_centre(0, 0, 100, false).y, hole_centre(0, 3, 100, false).y - 254);
    EXPECT_EQ(hole_centre(0, 0, 100, false).y, hole_centre(0, 4, 100, false).y + 254);
    EXPECT_EQ(frames_per_strip(254), 100U);
    std::string svg = render_svg(std::vector<Frame>(100, 0x01), {});
    EXPECT_NE(svg.find("height=\"2540\""), std::string::npos);
    EXPECT_NE(svg.find("viewBox=\"0 0 "), std::string::npos);
}

TEST(Render, MirroredTrackOneIsOnTop) {
    auto top = hole_centre(0, 8, 100, false), mirrored = hole_centre(0, 1, 100, true);
    EXPECT_EQ(top.y, mirrored.y);
    std::string svg = render_svg(std::vector<Frame>{0x01}, RenderOptions{.mirror = true});
    EXPECT_NE(svg.find(circle_at(hole_centre(0, 1, frames_per_strip(254), true))), std::string::npos);
    EXPECT_NE(svg.find("track 1 on top"), std::string::npos);
}

TEST(Render, LongTapesWrapIntoStripsOfTheLengthAsked) {
    std::vector<Frame> frames(250, 0x41);
    std::string svg = render_svg(frames, RenderOptions{.strip_mm = 254});
    EXPECT_EQ(count(svg, "class=\"tape\""), 3U);
    EXPECT_EQ(frames_per_strip(25.4), 10U);
    EXPECT_EQ(count(render_svg(frames, RenderOptions{.strip_mm = 25.4}), "class=\"tape\""), 25U);
    // Frame 101 opens the second strip, at its left.
    auto second = hole_centre(100, 0, 100, false);
    EXPECT_EQ(second.x, hole_centre(0, 0, 100, false).x);
    EXPECT_EQ(second.y - hole_centre(0, 0, 100, false).y, strip_pitch);
}

TEST(Render, FrameNumbersEveryTenFramesAndTheCharacterBesideEachFrame) {
    auto code = FrameCode::iso();
    auto frames = encode("%\nN10 G01 X1\n", EncodeOptions{.leader = 10, .trailer = 10});
    std::string svg = render_svg(frames, RenderOptions{.code = &code});
    for (const char* n : {">1<", ">10<", ">20<", ">30<"}) EXPECT_NE(svg.find(n), std::string::npos) << n;
    EXPECT_EQ(svg.find(">11<"), std::string::npos);
    EXPECT_NE(svg.find(">%</text>"), std::string::npos);
    EXPECT_NE(svg.find(">LF</text>"), std::string::npos);
    EXPECT_NE(svg.find(">G</text>"), std::string::npos);
}

TEST(Render, BadFramesAndMarksAreShadedWithIdsForLinks) {
    auto code = FrameCode::iso();
    std::vector<Frame> frames = {0x00, 0x25 | 0x80, 0xA5 & 0x7F, 0xB1, 0x00};  // frames 2 good '%', 3 bad parity
    RenderOptions o{.code = &code,
                    .marks = {{4, MarkKind::restored, "voted 2 of 3 <reads>"}, {5, MarkKind::doubtful, ""}}};
    std::string svg = render_svg(frames, o);
    EXPECT_NE(svg.find("id=\"f3\" class=\"mark parity\""), std::string::npos);
    EXPECT_NE(svg.find("id=\"f4\" class=\"mark restored\""), std::string::npos);
    EXPECT_NE(svg.find("id=\"f5\" class=\"mark doubtful\""), std::string::npos);
    EXPECT_NE(svg.find("frame 4: voted 2 of 3 &lt;reads&gt;"), std::string::npos);
    EXPECT_EQ(svg.find("id=\"f2\""), std::string::npos);
    for (const char* legend : {"parity error", "restored", "doubtful"}) EXPECT_NE(svg.find(legend), std::string::npos);
}

TEST(Render, FromAndToDrawOnlyThoseFramesWithTheirOwnNumbers) {
    std::vector<Frame> frames(300, 0x03);
    std::string svg = render_svg(frames, RenderOptions{.from = 101, .to = 150});
    EXPECT_EQ(count(svg, "r=\"58.5\""), 50U);
    EXPECT_NE(svg.find(">101<"), std::string::npos);
    EXPECT_NE(svg.find(">150<"), std::string::npos);
    EXPECT_EQ(svg.find(">160<"), std::string::npos);
    EXPECT_THROW(render_svg(frames, RenderOptions{.from = 200, .to = 100}), Error);
    EXPECT_THROW(render_svg(frames, RenderOptions{.from = 1, .to = 301}), Error);
}

TEST(Render, TheSameBytesEveryRunAndValidXml) {
    auto code = FrameCode::iso();
    auto frames = read_frames(sample_path("16k20f3s5-turning.iso.ptp"));
    frames[150] ^= 0x04;  // a parity error to shade
    RenderOptions o{.code = &code, .strip_mm = 300, .marks = {{160, MarkKind::restored, "a & b"}}};
    std::string first = render_svg(frames, o), second = render_svg(frames, o);
    EXPECT_EQ(first, second);
    TempDir dir;
    write_file_atomic(dir.file("t.svg"), first, false);
    std::string cmd = "timeout 30 xmllint --noout " + dir.file("t.svg") + " 2>" + dir.file("err");
    EXPECT_EQ(std::system(cmd.c_str()), 0) << read_text(dir.file("err"));
    // Mirrored and cut, still valid.
    write_file_atomic(dir.file("m.svg"), render_svg(frames, RenderOptions{.from = 5, .to = 50, .mirror = true}), false);
    cmd = "timeout 30 xmllint --noout " + dir.file("m.svg") + " 2>" + dir.file("err");
    EXPECT_EQ(std::system(cmd.c_str()), 0) << read_text(dir.file("err"));
}

TEST(Render, AMarkMayLinkAndSaysMoreThanTheParityShading) {
    auto code = FrameCode::iso();
    std::vector<Frame> frames = {0x25, 0x26, 0x29};  // all three fail even parity (3 holes each)
    RenderOptions o{.code = &code, .marks = {{2, MarkKind::doubtful, "unresolved", "#p2"}}};
    std::string svg = render_svg(frames, o);
    EXPECT_NE(svg.find("<a href=\"#p2\"><rect id=\"f2\" class=\"mark doubtful\""), std::string::npos);
    EXPECT_EQ(count(svg, "class=\"mark parity\""), 2U);  // frames 1 and 3; frame 2 has its own mark
    EXPECT_EQ(count(svg, "id=\"f2"), 1U);
}

TEST(Render, ALeaderLabelHasNoCharactersAndNoBadFrameShading) {
    auto code = FrameCode::eia();
    std::vector<Frame> frames = {0x00, 0x03, 0x13, 0x00};  // 0x03: even holes, a parity error in EIA
    std::string plain = render_svg(frames, RenderOptions{.code = &code});
    EXPECT_NE(plain.find("class=\"mark parity\""), std::string::npos);
    std::string labelled = render_svg(frames, RenderOptions{.code = &code, .label_first = 2, .label_frames = 2});
    EXPECT_EQ(labelled.find("class=\"mark"), std::string::npos);
    EXPECT_EQ(labelled.find(">!<"), std::string::npos);
}
