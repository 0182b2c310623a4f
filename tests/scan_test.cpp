// tape scan: real scans and photos from ../shared/data/scans (skipped, saying why, where absent), and
// tapes drawn by tape render as a scanner or a camera would show them, read back frame for frame.
#include "tape/scan.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <random>

#include "scan/scan_geometry.hpp"
#include "scan_util.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

// Beside the project (../shared), or where TAPE_SHARED_DIR says (a worktree elsewhere).
std::string scans_dir() {
    const char* shared = std::getenv("TAPE_SHARED_DIR");
    return (shared ? std::string(shared) : std::string(TAPE_SOURCE_DIR) + "/../shared") + "/data/scans/";
}

#define NEED_SCAN(name)                                                                               \
    if (!std::filesystem::exists(scans_dir() + (name)))                                               \
    GTEST_SKIP() << scans_dir() << (name) << " is absent: the real scans live beside the project in " \
                 << "../shared/data/scans (see its SOURCES.md)"

std::vector<Frame> sample_tape(const std::string& label = "N1") {
    std::string text = read_text(sample_path("circle-examples.txt"));
    return encode(text, EncodeOptions{.leader = 40, .trailer = 20, .label = label});
}

ScanResult scan_one(const TempDir& dir, const Picture& p, const std::string& name, const ScanOptions& o = {}) {
    std::string path = dir.file(name);
    write_picture(p, path);
    std::vector<std::string> paths{path};
    return scan_images(paths, o);
}

// The frames the scan was sure of, in the punched part.
std::vector<Frame> sure_punched(const ScanResult& r) {
    std::vector<Frame> out;
    for (std::size_t i = 0; i < r.frames.size(); ++i)
        if (!doubtful_at(r, i + 1) && r.frames[i] != blank_frame) out.push_back(r.frames[i]);
    return out;
}

}  // namespace

TEST(ScanReal, PatinhoFeioScanGivesItsFortySixBytesWhoseSumIsZero) {
    NEED_SCAN("patinho_feio_fita_absoluta_scan03.png");
    std::vector<std::string> paths{scans_dir() + "patinho_feio_fita_absoluta_scan03.png"};
    ScanResult r = scan_images(paths);
    auto expected = read_frames(scans_dir() + "patinho_feio_fita_absoluta_scan03.expected.bin");
    auto read = punched_part(r.frames);
    ASSERT_EQ(std::vector<Frame>(read.begin(), read.end()), expected);
    EXPECT_EQ(std::accumulate(read.begin(), read.end(), 0U) % 256, 0U);
    EXPECT_TRUE(r.doubts.runs.empty());
    EXPECT_EQ(r.images[0].strip->frames.size(), 65U);  // the 65 feed holes of SOURCES.md
    EXPECT_NEAR(r.images[0].strip->skew_deg, 2.16, 0.1);
    EXPECT_TRUE(r.images[0].strip->reversed);  // read right to left in the picture
    // Nothing in a binary tape tells its direction but the blank runs, 10 and 9: said as weak.
    EXPECT_EQ(r.direction.basis, DirectionBasis::leader);
    EXPECT_TRUE(r.direction.weak);
}

TEST(ScanReal, FlatPhotoGivesWikipediaCrLf) {
    NEED_SCAN("ptap2dxf_wikipedia_flat_ruler.jpg");
    std::vector<std::string> paths{scans_dir() + "ptap2dxf_wikipedia_flat_ruler.jpg"};
    ScanResult r = scan_images(paths);
    auto expected = read_frames(scans_dir() + "WikipediaCRLF.expected.ptap");
    auto want = punched_part(expected);
    EXPECT_EQ(sure_punched(r), std::vector<Frame>(want.begin(), want.end()));
    EXPECT_EQ(r.direction.basis, DirectionBasis::code);
    // The corner cut off the tape's start is no hole: the frame there is doubtful, not a character.
    for (std::size_t i = 0; i < r.frames.size(); ++i)
        if (r.frames[i] != blank_frame && !doubtful_at(r, i + 1)) {
            EXPECT_GE(r.frames[i], 0x0A);
        }
}

TEST(ScanReal, JoinerPhotoGivesTheFirstFramesOfTheAbsoluteLoader) {
    NEED_SCAN("ptap2dxf_absloader_joiner_start.jpg");
    std::vector<std::string> paths{scans_dir() + "ptap2dxf_absloader_joiner_start.jpg"};
    ScanResult r = scan_images(paths);
    auto loader = read_frames(scans_dir() + "DEC-11-L2PC-PO.expected.ptap");
    auto first_data = std::find(r.frames.begin(), r.frames.end(), Frame{0xE9}) - r.frames.begin();
    ASSERT_GE(r.frames.size(), static_cast<std::size_t>(first_data) + 14);
    for (std::size_t i = 0; i < 14; ++i) {
        std::size_t at = static_cast<std::size_t>(first_data) + i;
        EXPECT_EQ(r.frames[at], loader[i]) << "data frame " << i;
        if (at + 1 < r.frames.size()) {  // the last frame lies at the picture's edge
            EXPECT_FALSE(doubtful_at(r, at + 1)) << "data frame " << i;
        }
    }
    // Under the red joiner nothing sure is punched: the frames there are blank or doubtful.
    for (std::ptrdiff_t i = 0; i < first_data; ++i)
        if (!doubtful_at(r, static_cast<std::uint64_t>(i) + 1)) {
            EXPECT_EQ(r.frames[static_cast<std::size_t>(i)], blank_frame) << i;
        }
    EXPECT_EQ(r.direction.basis, DirectionBasis::leader);
}

TEST(ScanReal, CoiledTapeIsRefusedWithWhatWasSeen) {
    NEED_SCAN("djr_coiled_tape_unknown.png");
    std::vector<std::string> paths{scans_dir() + "djr_coiled_tape_unknown.png"};
    try {
        scan_images(paths);
        FAIL() << "a coiled tape was read";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::bad_image);
        EXPECT_NE(std::string(e.what()).find("straight"), std::string::npos) << e.what();
    }
}

TEST(Scan, ACleanPictureAt300DpiReadsBackExactly) {
    TempDir dir;
    auto tape = sample_tape();
    ScanResult r = scan_one(dir, render_picture(tape, RasterOptions{}), "clean.png");
    EXPECT_EQ(r.frames, tape);
    EXPECT_TRUE(r.complete());
    EXPECT_EQ(r.direction.basis, DirectionBasis::label);
    EXPECT_NEAR(r.images[0].strip->dpi, 300, 1);
    EXPECT_FALSE(r.images[0].strip->mirrored);
}

TEST(Scan, SkewBowStainsDustBlurNoiseAndJpegLeaveNoFrameSilentlyWrong) {
    TempDir dir;
    auto tape = sample_tape();
    for (double dpi : {300.0, 200.0}) {
        RasterOptions ro{.dpi = dpi, .skew_deg = -3, .bow_mm = 1.5, .stains = 6, .seed = 5};
        Picture p = render_picture(tape, ro);
        apply_effects(
            p,
            PictureEffects{.light = 0.4, .dust = 60, .blur_px = dpi / 250, .noise = 6, .jpeg_quality = 80, .seed = 5},
            dpi);
        ScanResult r = scan_one(dir, p, "worn.png");
        ReadScore s = score_read(tape, r);
        EXPECT_EQ(s.silently_wrong, 0U) << dpi << " dpi";
        EXPECT_GE(s.right_share(), 0.995) << dpi << " dpi";
        EXPECT_NEAR(r.images[0].strip->skew_deg, -3, 0.1);
    }
}

// A phone's photo of a tape lying flat, at 6 px a code hole (8 px a frame): orange paper on a light mat,
// holes light. A feed hole's centre off by a fraction of a pixel must not put track 8 beside its hole.
TEST(Scan, APhonePhotoAtSixPixelsAHoleLeavesNoFrameSilentlyWrong) {
    TempDir dir;
    auto tape = sample_tape();
    const double dpi = 6 / 1.83 * 25.4;
    RasterOptions ro{.dpi = dpi, .skew_deg = 2.5, .bow_mm = 1.8, .stains = 4, .seed = 18};
    ro.paper = 0xE8B060, ro.backing = 0xD0D0D0;
    Picture p = render_picture(tape, ro);
    apply_effects(
        p, PictureEffects{.light = 0.45, .dust = 10, .blur_px = 0.8, .noise = 7, .jpeg_quality = 78, .seed = 18}, dpi);
    ScanResult r = scan_one(dir, p, "phone.png");
    ReadScore s = score_read(tape, r);
    EXPECT_EQ(s.silently_wrong, 0U);
    EXPECT_GE(s.right_share(), 0.99) << s.right << " of " << s.frames << " right, " << s.doubtful << " doubtful";
}

TEST(Scan, EitherFaceAndEitherDirectionGiveTheSameRead) {
    TempDir dir;
    auto tape = sample_tape();
    for (bool mirror : {false, true}) {
        Picture p = render_picture(tape, RasterOptions{.mirror = mirror, .skew_deg = 1});
        for (bool turned : {false, true}) {
            ScanResult r = scan_one(dir, turned ? half_turn(p) : p, "face.png");
            EXPECT_EQ(r.frames, tape) << "mirror " << mirror << ", turned " << turned;
            EXPECT_EQ(r.images[0].strip->mirrored, mirror);
            EXPECT_EQ(r.images[0].strip->reversed, turned);
        }
    }
}

TEST(Scan, ProgramCodeDecidesTheDirectionWithoutALabel) {
    TempDir dir;
    auto tape = encode(read_text(sample_path("circle-examples.txt")), EncodeOptions{.leader = 20, .trailer = 20});
    ScanResult r = scan_one(dir, half_turn(render_picture(tape, RasterOptions{.mirror = true})), "code.png");
    EXPECT_EQ(r.frames, tape);
    EXPECT_EQ(r.direction.basis, DirectionBasis::code);
    EXPECT_FALSE(r.direction.weak);
}

TEST(Scan, OverlappingSegmentsInAnyOrderAndEitherWayMakeOneExactRead) {
    TempDir dir;
    auto tape = sample_tape();
    Picture whole = render_picture(tape, RasterOptions{.dpi = 200});
    std::vector<std::string> paths;
    const int segments = 8, width = whole.width / 5, step = (whole.width - width) / (segments - 1);
    std::mt19937 rng(7);
    for (int k = 0; k < segments; ++k) {
        Picture seg = columns(whole, k * step, k == segments - 1 ? whole.width : k * step + width);
        paths.push_back(dir.file("seg" + std::to_string(k) + ".png"));
        write_picture(rng() % 2 ? half_turn(seg) : seg, paths.back());
    }
    std::shuffle(paths.begin(), paths.end(), rng);
    ScanResult r = scan_images(paths);
    EXPECT_TRUE(r.gaps.empty());
    EXPECT_EQ(r.frames, tape);
    EXPECT_TRUE(r.doubts.runs.empty());
}

TEST(Scan, PicturesThatDoNotOverlapLeaveAGapSaidWithItsPlace) {
    TempDir dir;
    auto tape = sample_tape();
    Picture whole = render_picture(tape, RasterOptions{});
    std::vector<std::string> paths{dir.file("a.png"), dir.file("b.png")};
    write_picture(columns(whole, 0, whole.width / 3), paths[0]);
    write_picture(columns(whole, whole.width / 2, whole.width), paths[1]);
    ScanResult r = scan_images(paths);
    ASSERT_EQ(r.gaps.size(), 1U);
    EXPECT_FALSE(r.complete());
    EXPECT_EQ(r.gaps[0].before_image, paths[0]);
    EXPECT_EQ(r.gaps[0].after_image, paths[1]);
    EXPECT_LT(r.frames.size(), tape.size());
}

TEST(Scan, AHoleHalfCoveredMakesItsFrameDoubtfulNotAGuess) {
    TempDir dir;
    auto tape = sample_tape();
    Picture p = render_picture(tape, RasterOptions{});
    // A grey smear across frames 120 to 124: neither paper nor backing.
    const int x0 = static_cast<int>((6 + 119 * 2.54) / 25.4 * 300),
              x1 = static_cast<int>((6 + 124 * 2.54) / 25.4 * 300);
    for (int y = 0; y < p.height; ++y)
        for (int x = x0; x < x1; ++x) std::fill_n(p.at(x, y), 3, static_cast<std::uint8_t>(128));
    ScanResult r = scan_one(dir, p, "smear.png");
    ReadScore s = score_read(tape, r);
    EXPECT_EQ(s.silently_wrong, 0U);
    EXPECT_GT(s.doubtful, 0U);
    EXPECT_FALSE(r.complete());
}

TEST(Scan, FiveTrackTape) {
    TempDir dir;
    auto tape = encode("RYRYRY THE QUICK BROWN FOX\n", EncodeOptions{.code = Code::ita2, .leader = 25, .trailer = 25});
    ScanResult r =
        scan_one(dir, render_picture(tape, RasterOptions{.tracks = 5}), "five.png", ScanOptions{.tracks = 5});
    EXPECT_EQ(r.frames, tape);
}

TEST(Scan, APictureWithoutTapeIsRefused) {
    TempDir dir;
    Picture p = render_picture(std::vector<Frame>(8, 0x41), RasterOptions{});
    try {
        scan_one(dir, p, "short.png");
        FAIL() << "read a strip of 8 frames";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::bad_image);
        EXPECT_NE(std::string(e.what()).find("20 frames"), std::string::npos) << e.what();
    }
}

TEST(Scan, AFileThatIsNoPictureIsAnIoError) {
    TempDir dir;
    std::ofstream(dir.file("x.png")) << "not a picture";
    std::vector<std::string> paths{dir.file("x.png")};
    EXPECT_THROW(scan_images(paths), Error);
    paths = {dir.file("missing.png")};
    try {
        scan_images(paths);
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::io);
    }
}

TEST(Scan, TheStartGivenByTheUserWins) {
    TempDir dir;
    auto tape = sample_tape();
    ScanResult r =
        scan_one(dir, render_picture(tape, RasterOptions{}), "start.png", ScanOptions{.start = TapeStart::right});
    EXPECT_EQ(r.direction.basis, DirectionBasis::user);
    EXPECT_EQ(r.frames, std::vector<Frame>(tape.rbegin(), tape.rend()));
}

TEST(ScanGeometry, ChainsFollowEvenlySpacedBlobsAndSkipAFewMissing) {
    std::vector<scan::Blob> blobs;
    for (int i = 0; i < 40; ++i)
        if (i != 10 && i != 11) blobs.push_back({100.0F + i * 30.0F, 50.0F + i * 0.5F, 14});      // feed holes
    for (int i = 0; i < 40; i += 3) blobs.push_back({100.0F + i * 30.0F, 80.0F + i * 0.5F, 22});  // code holes
    auto chains = scan::follow_chains(blobs, 20);
    ASSERT_FALSE(chains.empty());
    EXPECT_EQ(chains[0].frames(), 40U);
    EXPECT_TRUE(scan::feed_like(chains[0]));
    auto line = scan::feed_line(blobs, chains[0]);
    EXPECT_FALSE(line.seen[10]);
    EXPECT_NEAR(line.centre[10].x, 400, 1);
}

TEST(ScanGeometry, DirectionFromTextFromTheLeaderOrNone) {
    bool reverse = true;
    auto text = encode("%\nN10 G01 X-12.5 Y3\nN20 M30\n", EncodeOptions{.leader = 5, .trailer = 5});
    auto d = scan::decide_direction(text, {}, reverse);
    EXPECT_EQ(d.basis, DirectionBasis::code);
    EXPECT_FALSE(reverse);
    std::vector<Frame> back(text.rbegin(), text.rend());
    scan::decide_direction(back, {}, reverse);
    EXPECT_TRUE(reverse);
    std::vector<Frame> binary = {0, 0, 0, 0, 0, 0, 0x9E, 0xE1, 0x33, 0};
    d = scan::decide_direction(binary, {}, reverse);
    EXPECT_EQ(d.basis, DirectionBasis::leader);
    EXPECT_FALSE(reverse);
    std::vector<Frame> even = {0, 0x9E, 0xE1, 0};
    EXPECT_EQ(scan::decide_direction(even, {}, reverse).basis, DirectionBasis::none);
}

TEST(ScanGeometry, HoleReadings) {
    EXPECT_TRUE(scan::read_hole({0.95F, 0.9F}).punched);
    EXPECT_GE(scan::read_hole({0.95F, 0.9F}).confidence, scan::doubt_below);
    EXPECT_FALSE(scan::read_hole({0.05F, 0.1F}).punched);
    EXPECT_GE(scan::read_hole({0.05F, 0.1F}).confidence, scan::doubt_below);
    // A speck of dust: dark at the centre, paper on the ring.
    EXPECT_FALSE(scan::read_hole({0.9F, 0.05F}).punched);
    // Half there: doubtful.
    EXPECT_LT(scan::read_hole({0.5F, 0.45F}).confidence, scan::doubt_below);
    EXPECT_LT(scan::read_hole({0.9F, 0.9F, 0, false}).confidence, scan::doubt_below);
}
