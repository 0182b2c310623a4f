// Image formats: a contract every registered format keeps, then each format's own rules.
#include "tape/image.hpp"

#include <gtest/gtest.h>

#include "tape/error.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {
// Every frame a format can hold: all 256 bytes, or the 32 frames of 5-track tape.
std::vector<Frame> every_frame(int tracks = 8) {
    std::vector<Frame> all;
    for (int f = 0; f < (1 << tracks); ++f) all.push_back(static_cast<Frame>(f));
    return all;
}
std::span<const std::uint8_t> bytes_of(const std::string& s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}
}  // namespace

TEST(ImageContract, EveryFormatRoundTripsEveryFrameAndKnowsItsOwnOutput) {
    FrameCode iso = FrameCode::iso();
    for (const auto& format : image_formats()) {
        if (!format.can_read() || !format.can_write()) continue;  // only reads or only writes
        for (const FrameCode* annotate :
             {static_cast<const FrameCode*>(nullptr), static_cast<const FrameCode*>(&iso)}) {
            std::string file = format.write(every_frame(format.tracks), ImageWriteOptions{annotate});
            EXPECT_EQ(format.read(bytes_of(file)), every_frame(format.tracks)) << format.id;
            EXPECT_EQ(&detect_image_format(bytes_of(file).first(std::min<std::size_t>(file.size(), 4096))), &format)
                << format.id;
        }
        EXPECT_FALSE(format.extensions.empty()) << format.id;
        for (auto ext : format.extensions)
            EXPECT_EQ(image_format_for_path("dir.x/part" + std::string(ext)), &format) << ext;
        EXPECT_EQ(find_image_format(format.id), &format);
        EXPECT_EQ(format.read({}), std::vector<Frame>{}) << format.id;
    }
}

TEST(ImageFormats, ExtensionsAreCaseInsensitiveAndNeedADot) {
    EXPECT_EQ(image_format_for_path("PART.PTP")->id, "raw");
    EXPECT_EQ(image_format_for_path("part.holes")->id, "holes");
    EXPECT_EQ(image_format_for_path("tapes.d/part"), nullptr);
    EXPECT_EQ(find_image_format("punchcard"), nullptr);
}

TEST(HolesFormat, ReadsCommentsAndAnnotations) {
    std::string file = "# header\n\n  |o o  .o o|  1 %\n|    o. o | anything here\n#|ooooo.ooo|\n|O*   .   |\r\n";
    auto frames = find_image_format("holes")->read(bytes_of(file));
    EXPECT_EQ(frames, (std::vector<Frame>{0xA5, 0x0A, 0xC0}));
}

TEST(HolesFormat, WriterAnnotatesCharactersAndMarksBadFrames) {
    FrameCode iso = FrameCode::iso();
    std::string out = find_image_format("holes")->write(std::vector<Frame>{0xA5, 0x25}, ImageWriteOptions{&iso});
    EXPECT_NE(out.find("|o o  .o o|      1  %\n"), std::string::npos) << out;
    EXPECT_NE(out.find("|  o  .o o|      2  ! parity error\n"), std::string::npos) << out;
}

TEST(HolesFormat, BadLinesAreErrorsWithTheirLineNumber) {
    auto line_of = [](const std::string& file) {
        try {
            find_image_format("holes")->read(bytes_of(file));
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_image);
            return *e.where().line;
        }
        return std::uint64_t{0};
    };
    EXPECT_EQ(line_of("|     .   |\n| x   .   |\n"), 2U);
    EXPECT_EQ(line_of("# c\n|     o   |\n"), 2U);  // feed hole column
    EXPECT_EQ(line_of("|     .  |\n"), 1U);        // too short
    EXPECT_EQ(line_of("%\nN1\n"), 1U);             // a text program is no picture
}

TEST(DetectFormat, RawUnlessItIsAPicture) {
    EXPECT_EQ(detect_image_format(bytes_of(std::string("\xA5\x0A\x4E", 3))).id, "raw");
    EXPECT_EQ(detect_image_format(bytes_of("# c\n|o o  .o o|\n")).id, "holes");
    EXPECT_EQ(detect_image_format({}).id, "raw");
    auto sample = read_text(sample_path("gost-20999-format-example.iso.holes"));
    EXPECT_EQ(detect_image_format(bytes_of(sample)).id, "holes");
}
