// Hex dumps read back as tape images: what xxd, hexdump -C and od -t x1 print, '*' lines included.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <fstream>

#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "tape/image.hpp"
#include "tape/input.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

std::vector<Frame> read_image(const std::string& path) {
    Input in(path, InputOptions{.kind = InputKind::automatic});
    EXPECT_TRUE(in.is_image()) << path;
    EXPECT_EQ(in.format()->id, "dump") << path;
    std::vector<Frame> frames;
    for (auto f = in.next_frames(); !f.empty(); f = in.next_frames()) frames.insert(frames.end(), f.begin(), f.end());
    return frames;
}

std::vector<Frame> sample_tape() { return encode("%\nG01 X10\nM02\n%\n", EncodeOptions{.leader = 40, .trailer = 100}); }

}  // namespace

TEST(DumpImage, TheDumpProgramsOutputReadsAsTheTape) {
    TempDir dir;
    auto tape = sample_tape();
    std::ofstream(dir.file("t.ptp"), std::ios::binary)
        .write(reinterpret_cast<const char*>(tape.data()), static_cast<std::streamsize>(tape.size()));
    int run = 0;
    for (std::string tool : {"xxd", "hexdump -C", "od -t x1", "od -A o -t x1"}) {
        std::string program = tool.substr(0, tool.find(' '));
        if (std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) != 0) continue;
        std::string out = dir.file(program + std::to_string(run++) + ".txt");
        ASSERT_EQ(std::system((tool + " " + dir.file("t.ptp") + " > " + out).c_str()), 0) << tool;
        EXPECT_EQ(read_image(out), tape) << tool;
    }
    if (run == 0) GTEST_SKIP() << "neither xxd, hexdump nor od is installed";
}

TEST(DumpImage, RepeatedLinesAreFilledInByTheOffsets) {
    TempDir dir;
    std::ofstream(dir.file("d.txt"))
        << "00000000  00 00 00 00 00 00 00 00  00 00 00 00 00 00 00 00  |................|\n"
           "*\n"
           "00000030  a5 0a                                             |..|\n"
           "00000032\n";
    auto frames = read_image(dir.file("d.txt"));
    ASSERT_EQ(frames.size(), 50U);
    EXPECT_EQ(frames[48], 0xA5);
    EXPECT_EQ(frames[49], 0x0A);
}

// A short line repeated far (a blank tape dumped with od -An -tx1 --width=3): filled by whole copies, in
// order, to the byte; 3 is no power of two, so the doubling's last copy is a part.
TEST(DumpImage, ShortLineRepeatedFarIsFilledWhole) {
    TempDir dir;
    std::ofstream(dir.file("d.txt")) << "00000000  80 01 02\n*\n01000002  0a\n01000003\n";
    auto frames = read_image(dir.file("d.txt"));
    ASSERT_EQ(frames.size(), 0x1000003U);
    const std::array<Frame, 3> line{0x80, 1, 2};
    std::size_t wrong = 0;
    for (std::size_t i = 0; i + 1 < frames.size(); ++i) wrong += frames[i] != line[i % 3];
    EXPECT_EQ(wrong, 0U);
    EXPECT_EQ(frames.back(), 0x0A);
}

TEST(DumpImage, WordDumpsAndMissingLinesAreRefusedWithAdvice) {
    TempDir dir;
    auto fails = [&](const std::string& text, const std::string& words) {
        std::ofstream(dir.file("w.txt")) << text;
        try {
            read_image(dir.file("w.txt"));
            ADD_FAILURE() << text;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_image);
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    fails("0000000 000000 000000 000000 000000 000000 000000 000000 000000\n*\n0000040 000000 005245\n",
          "od -An -tx1 -v");
    fails("0000000 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00\n0000040 a5 0a\n", "a line is missing");
    fails("0000000 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00\n*\n", "'*' and no offset after it");
}

TEST(DumpImage, ATextProgramIsNoDump) {
    EXPECT_EQ(&detect_image_format(std::span(reinterpret_cast<const std::uint8_t*>("%\nN10 G01 X10\nM02\n"), 19)),
              find_image_format("raw"));
}
