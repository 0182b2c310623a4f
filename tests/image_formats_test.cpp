// Contract test over the image format table: every format, the ones added later included, writes any
// tape and reads it back frame for frame, and content detection does not take its files for another's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <numeric>

#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/image.hpp"

using namespace tape;

namespace {

std::vector<std::string> format_ids(bool (*keep)(const ImageFormat&) = nullptr) {
    std::vector<std::string> ids;
    for (const auto& f : image_formats())
        if (!keep || keep(f)) ids.emplace_back(f.id);
    return ids;
}

bool reads_and_writes(const ImageFormat& f) { return f.can_read() && f.can_write(); }
bool one_way(const ImageFormat& f) { return !reads_and_writes(f); }

const ImageFormat& format(const std::string& id) {
    const ImageFormat* f = find_image_format(id);
    if (!f) throw std::logic_error("no format " + id);
    return *f;
}

// Every frame the format holds: all 256 bytes, or the 32 frames of 5-track tape.
std::vector<Frame> every_frame_value(const ImageFormat& f) {
    std::vector<Frame> frames(std::size_t{1} << f.tracks);
    std::iota(frames.begin(), frames.end(), 0);
    return frames;
}

std::span<const std::uint8_t> bytes_of(const std::string& file) {
    return {reinterpret_cast<const std::uint8_t*>(file.data()), file.size()};
}

// What the file backend and the CLI look at to choose a format by content.
constexpr std::size_t detection_prefix = 4096;

class ImageFormatContract : public ::testing::TestWithParam<std::string> {};
/// Formats that read and write: what one writes, it reads back.
class RoundTripFormat : public ImageFormatContract {};
/// Formats that only read (a hex dump) or only write.
class OneWayFormat : public ImageFormatContract {};

}  // namespace

TEST_P(ImageFormatContract, DescribesItselfInTheTable) {
    const ImageFormat& f = format(GetParam());
    EXPECT_FALSE(f.description.empty());
    EXPECT_NE(f.match, nullptr);
    EXPECT_TRUE(f.can_read() || f.can_write()) << "a format reads, writes or both";
    auto ids = format_ids();
    EXPECT_EQ(std::count(ids.begin(), ids.end(), GetParam()), 1) << "an id names one format";
    for (auto ext : f.extensions) {
        EXPECT_TRUE(ext.starts_with(".")) << ext;
        EXPECT_EQ(image_format_for_path("dir/part" + std::string(ext)), &f) << ext;
    }
}

// A tape holding every frame value, annotated by either code or not at all, reads back the same.
TEST_P(RoundTripFormat, WritesAndReadsBackEveryFrameValue) {
    const ImageFormat& f = format(GetParam());
    const auto frames = every_frame_value(f);
    const FrameCode iso = FrameCode::iso(), eia = FrameCode::eia(), ita2 = FrameCode::five_track(Code::ita2),
                    mtk2 = FrameCode::five_track(Code::mtk2);
    for (const FrameCode* annotate : {static_cast<const FrameCode*>(nullptr), &iso, &eia, &ita2, &mtk2}) {
        SCOPED_TRACE(annotate ? std::string(code_name(annotate->code())) : "no annotation");
        std::string file = f.write(frames, ImageWriteOptions{.annotate = annotate});
        std::vector<Frame> back;
        ASSERT_NO_THROW(back = f.read(bytes_of(file)));
        EXPECT_EQ(back, frames);
    }
}

// Detection on the written file picks this format, or a more general one that reads the file as
// the same frames; never one that would read something else.
TEST_P(RoundTripFormat, DetectionPicksItOrAMoreGeneralOne) {
    const ImageFormat& f = format(GetParam());
    const auto frames = every_frame_value(f);
    std::string file = f.write(frames, ImageWriteOptions{});
    auto bytes = bytes_of(file);
    auto prefix = bytes.first(std::min(bytes.size(), detection_prefix));
    EXPECT_GT(f.match(prefix), 0) << "the format does not know its own file";
    const ImageFormat& picked = detect_image_format(prefix);
    if (&picked == &f) return;
    EXPECT_GE(picked.match(prefix), f.match(prefix));
    std::vector<Frame> read_as_picked;
    ASSERT_NO_THROW(read_as_picked = picked.read(bytes)) << "detection picked " << picked.id;
    EXPECT_EQ(read_as_picked, frames) << "detection picked " << picked.id << ", which reads other frames";
}

// A file cut anywhere reads as the same frames, and frames written in pieces give the same file:
// what lets every command stream an image of any length.
TEST_P(RoundTripFormat, ReadsAndWritesTheSameHoweverCut) {
    const ImageFormat& f = format(GetParam());
    const auto frames = every_frame_value(f);
    const FrameCode iso = FrameCode::iso();
    const std::string whole = f.write(frames, ImageWriteOptions{.annotate = &iso});
    for (std::size_t piece : {std::size_t{1}, std::size_t{3}, std::size_t{7}, std::size_t{100}, std::size_t{4096}}) {
        SCOPED_TRACE("pieces of " + std::to_string(piece));
        auto writer = f.make_writer(ImageWriteOptions{.annotate = &iso});
        std::string written;
        for (std::size_t i = 0; i < frames.size(); i += piece)
            writer->write(std::span(frames).subspan(i, std::min(piece, frames.size() - i)), written);
        writer->finish(written);
        EXPECT_EQ(written, whole);
        auto reader = f.make_reader();
        std::vector<Frame> back;
        auto bytes = bytes_of(whole);
        for (std::size_t i = 0; i < bytes.size(); i += piece)
            reader->read(bytes.subspan(i, std::min(piece, bytes.size() - i)), back);
        reader->finish(back);
        EXPECT_EQ(back, frames);
    }
}

// A hex dump (read only) as a hobby reader saves it: pairs of digits, comments, any line length.
TEST(HexImage, ReadsADumpAndRefusesWhatIsNoDump) {
    const ImageFormat& hex = format("hex");
    EXPECT_FALSE(hex.can_write());
    const std::string dump = "# read 2026-11-23\n00 00 A5 0a\n8D\t0A # end\r\n";
    EXPECT_EQ(hex.read(bytes_of(dump)), (std::vector<Frame>{0x00, 0x00, 0xA5, 0x0A, 0x8D, 0x0A}));
    EXPECT_EQ(&detect_image_format(bytes_of(dump)), &hex);
    EXPECT_EQ(hex.match(bytes_of("%\nN1 G01 X1\n")), 0) << "a program is no dump";
    for (const char* bad : {"00 0\n", "00 0A5\n", "00\nzz\n"}) {
        try {
            hex.read(bytes_of(bad));
            ADD_FAILURE() << bad;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_image) << bad;
            EXPECT_TRUE(e.where().line) << bad;
        }
    }
}

// The way a one-way format does not go is refused as a usage error naming the format, never an empty
// file or no frames.
TEST_P(OneWayFormat, TheOtherWayIsAUsageErrorNamingIt) {
    const ImageFormat& f = format(GetParam());
    try {
        if (f.can_read())
            f.write(std::vector<Frame>{0x00, 0xA5}, ImageWriteOptions{});
        else
            f.read(bytes_of("00\nA5\n"));
        ADD_FAILURE() << f.id << " went the way it does not go";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage) << e.what();
        EXPECT_NE(std::string(e.what()).find(f.id), std::string::npos) << e.what();
    }
}

// A 5-track format holds frames of tracks 1-5 only: writing a frame with tracks 6-8 is refused (the
// tape would lose holes), and so is reading one.
TEST_P(ImageFormatContract, FiveTrackFormatsHoldOnlyFiveTrackFrames) {
    const ImageFormat& f = format(GetParam());
    EXPECT_TRUE(f.tracks == 8 || f.tracks == 5) << f.id;
    if (f.tracks != 5) return;
    if (f.can_write()) {
        try {
            f.write(std::vector<Frame>{0x1F, 0x20}, ImageWriteOptions{});
            ADD_FAILURE() << f.id << " wrote a frame with track 6";
        } catch (const Error& e) {
            EXPECT_EQ(e.where().frame, 2U);
        }
    }
    if (f.can_read() && find_image_format("hex8") && find_image_format("hex8")->can_write()) {
        std::string eight = find_image_format("hex8")->write(std::vector<Frame>{0x1F, 0xA5}, ImageWriteOptions{});
        EXPECT_THROW(f.read(bytes_of(eight)), Error) << f.id << " read a frame with tracks 6-8";
    }
}

// hex8 and hex5: one frame a line, comments and blank lines, a comment after a frame.
TEST(HexLinesImage, ReadsOneFrameALineWithComments) {
    const std::string file = "# tape from the attic\n\n1f\n 03 # A\r\n\t00\n#\n1B";
    const std::vector<Frame> frames{0x1F, 0x03, 0x00, 0x1B};
    EXPECT_EQ(format("hex8").read(bytes_of(file)), frames);
    EXPECT_EQ(format("hex5").read(bytes_of(file)), frames);
    EXPECT_EQ(format("hex8").read(bytes_of("A5\nff\n")), (std::vector<Frame>{0xA5, 0xFF}));
    EXPECT_EQ(&detect_image_format(bytes_of("A5\n0A\nFF\n8D\n")), &format("hex8"));
    EXPECT_EQ(&detect_image_format(bytes_of("00\n1F\n0A\n15\n04\n1B\n")), &format("hex5"));
    EXPECT_EQ(&detect_image_format(bytes_of("00\n00\n00\n00\n00\n")), &format("hex8"))
        << "a blank leader alone does not say 5-track";
    EXPECT_EQ(&detect_image_format(bytes_of("A5 0A FF 8D\n")), &format("hex")) << "several a line: hex";
}

// A bad line is reported with its number, counted from the start of the file however it is cut.
TEST(HexLinesImage, BadLinesAreErrorsWithTheirLineNumber) {
    struct Case {
        std::string id, file;
        std::uint64_t line;
    };
    for (const Case& c : {Case{"hex5", "# c\n1F\n\n03\n41\n", 5}, Case{"hex5", "1F\n1\n", 2},
                          Case{"hex8", "1F\nA5 0A\n", 2}, Case{"hex8", "# c\n\n1FF\n", 3}, Case{"hex8", "zz", 1}}) {
        for (std::size_t piece : {std::size_t{1}, std::size_t{2}, std::size_t{100}}) {
            SCOPED_TRACE(c.id + " " + c.file + " in pieces of " + std::to_string(piece));
            auto reader = format(c.id).make_reader();
            std::vector<Frame> out;
            auto bytes = bytes_of(c.file);
            try {
                for (std::size_t i = 0; i < bytes.size(); i += piece)
                    reader->read(bytes.subspan(i, std::min(piece, bytes.size() - i)), out);
                reader->finish(out);
                ADD_FAILURE() << "read";
            } catch (const Error& e) {
                EXPECT_EQ(e.code(), Errc::bad_image);
                EXPECT_EQ(e.where().line, c.line);
            }
        }
    }
}

namespace {
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(EveryFormat, ImageFormatContract, ::testing::ValuesIn(format_ids()), test_name);
INSTANTIATE_TEST_SUITE_P(EveryFormat, RoundTripFormat, ::testing::ValuesIn(format_ids(reads_and_writes)), test_name);
INSTANTIATE_TEST_SUITE_P(EveryFormat, OneWayFormat, ::testing::ValuesIn(format_ids(one_way)), test_name);
