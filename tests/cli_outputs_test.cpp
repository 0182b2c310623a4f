// Every command's outputs, through the real binaries: each subcommand with each output format ends in a
// message and a status (never an abort), and no output is written over an input or another output.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "process_util.hpp"
#include "tape/image.hpp"
#include "test_util.hpp"

namespace {

std::string text_program() { return sample_path("circle-examples.txt"); }
std::string iso_tape() { return sample_path("circle-examples.iso.ptp"); }

// One command line with OUT standing for the output's path and FMT for an --format id.
struct Case {
    std::string program;
    std::vector<std::string> args;
};

std::vector<Case> output_cases() {
    std::string text = text_program(), tape = iso_tape();
    return {
        {TAPE_BINARY, {"encode", text, "-o", "OUT"}},
        {TAPE_BINARY, {"encode", text, "--code", "ita2", "-o", "OUT"}},
        {TAPE_BINARY, {"label", "AB", "-o", "OUT"}},
        {TAPE_BINARY, {"restore", tape, "-o", "OUT"}},
        {TAPE_BINARY, {"format", text, "--spec", "N03 G02 X+053 Y+053 F031 M02", "-o", "OUT"}},
        {TAPE_BINARY, {"read", "file:" + tape, "-o", "OUT"}},
        {TAPE_BINARY, {"receive", "file:" + tape, "--whole", "-o", "OUT"}},
        {TAPE_BINARY, {"punch", tape, "file:OUT"}},
        {TAPE_BINARY, {"feed", text, "file:OUT"}},
        {TAPE_DAMAGE_BINARY, {tape, "--seed", "1", "--damage", "0.01", "-o", "OUT"}},
    };
}

std::vector<std::string> with_output(std::vector<std::string> args, const std::string& out) {
    for (auto& a : args) {
        if (a == "OUT") a = out;
        if (a == "file:OUT") a = "file:" + out;
    }
    return args;
}

void expect_a_message_and_a_status(const Outcome& r, const std::string& what) {
    EXPECT_GE(r.status, 0) << what << ": still running after 30 s";
    EXPECT_LE(r.status, 3) << what << ": " << r.err;
    if (r.status != 0) {
        EXPECT_FALSE(r.err.empty()) << what << ": failed without a word";
    }
    EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << what << ": " << r.err;
}

}  // namespace

// One test a writable format: each has its own time limit, and ctest runs them side by side (the whole
// sweep is 200 process starts, slow under AddressSanitizer on a loaded machine).
class CliEveryOutputFormat : public testing::TestWithParam<std::string> {};

TEST_P(CliEveryOutputFormat, EachSubcommandEndsInAMessageAndAStatus) {
    const tape::ImageFormat* format = tape::find_image_format(GetParam());
    ASSERT_NE(format, nullptr) << GetParam();
    std::string id(format->id), extension(format->extensions.empty() ? ".img" : format->extensions[0]);
    int runs = 0;
    for (const auto& c : output_cases()) {
        // By the output's extension, then by --format on a name that says nothing.
        TempDir dir;
        auto by_name = with_output(c.args, dir.file("out" + extension));
        expect_a_message_and_a_status(run(c.program, by_name, dir), c.args[0] + " to " + extension);
        auto by_option = with_output(c.args, dir.file("out.bin"));
        by_option.insert(by_option.end(), {"--format", id});
        expect_a_message_and_a_status(run(c.program, by_option, dir), c.args[0] + " --format " + id);
        runs += 2;
    }
    EXPECT_EQ(runs, 20);
}

std::vector<std::string> writable_formats() {
    std::vector<std::string> ids;
    for (const auto& format : tape::image_formats())
        if (format.can_write()) ids.emplace_back(format.id);
    return ids;
}

INSTANTIATE_TEST_SUITE_P(Writable, CliEveryOutputFormat, testing::ValuesIn(writable_formats()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             for (char& ch : name)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return name;
                         });

TEST(CliEveryOutput, EveryWritableFormatIsSwept) { EXPECT_GE(writable_formats().size(), 3U); }

TEST(CliEveryOutput, LabelIntoAFiveTrackImageIsRefusedNamingTheFile) {
    TempDir dir;
    Outcome r = tape_run({"label", "AB", "-o", dir.file("l.hex5")}, dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("l.hex5: frame "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("does not fit 5-track tape"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("l.hex5")));
}

namespace {

std::string copy_of(const std::string& from, const TempDir& dir, const std::string& name) {
    std::filesystem::copy_file(from, dir.file(name));
    return dir.file(name);
}

}  // namespace

TEST(CliSameFile, ReadingAFileIntoItselfIsRefusedAndTheFileKept) {
    TempDir dir;
    std::string x = copy_of(iso_tape(), dir, "x.ptp");
    std::string before = read_text(x);
    std::filesystem::create_symlink(x, dir.file("link.ptp"));
    std::filesystem::create_hard_link(x, dir.file("hard.ptp"));
    for (const auto& out : {x, dir.file("link.ptp"), dir.file("hard.ptp")}) {
        for (std::string command : {"read", "receive"}) {
            Outcome r = tape_run({command, "file:" + x, "-o", out, "--force"}, dir);
            EXPECT_EQ(r.status, 2) << command << " into " << out << ": " << r.err;
            EXPECT_NE(r.err.find("is also the input"), std::string::npos) << r.err;
            EXPECT_EQ(read_text(x), before) << command << " into " << out;
        }
    }
}

TEST(CliSameFile, EveryCommandRefusesToWriteOverItsInput) {
    TempDir dir;
    std::string tape = copy_of(iso_tape(), dir, "t.ptp"), text = copy_of(text_program(), dir, "t.txt");
    std::string gost = copy_of(sample_path("16k20f3s5-turning.txt"), dir, "g.txt");
    std::string table = copy_of(std::string(TAPE_SOURCE_DIR) + "/data/eia-rs244.tab", dir, "eia.tab");
    std::string tape_before = read_text(tape), text_before = read_text(text), gost_before = read_text(gost),
                table_before = read_text(table);
    std::vector<std::vector<std::string>> runs = {
        {"encode", text, "-o", text, "--force"},
        {"decode", tape, "-o", tape, "--force"},
        {"format", gost, "--spec", "% : / DS N03 G02 X+053 Z+053 F05 S02 T03 M03", "--from",
         "N03 G02 X+052 Z+052 F05 S02 T03 M03", "-o", gost, "--force"},
        {"restore", tape, "-o", tape, "--force"},
        {"render", tape, "-o", tape, "--force"},
        {"punch", tape, "file:" + tape, "--force"},
        {"feed", text, "file:" + text, "--force"},
        {"--eia-table", table, "encode", text, "-o", table, "--force"},
    };
    for (const auto& args : runs) {
        Outcome r = tape_run(args, dir);
        EXPECT_EQ(r.status, 2) << args[0] << " " << args[1] << ": " << r.err;
        EXPECT_EQ(read_text(tape), tape_before) << args[0];
        EXPECT_EQ(read_text(text), text_before) << args[0];
        EXPECT_EQ(read_text(gost), gost_before) << args[0];
        EXPECT_EQ(read_text(table), table_before) << args[0];
    }
    Outcome r = run(TAPE_DAMAGE_BINARY, {tape, "--seed", "1", "-o", tape, "--force"}, dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(read_text(tape), tape_before);
}

TEST(CliSameFile, TwoOutputsOfOneRunThatAreOneFileAreRefusedBeforeEitherIsWritten) {
    TempDir dir;
    std::string tape = iso_tape();
    std::filesystem::create_symlink(dir.file("x"), dir.file("link-to-x"));
    for (const auto& second : {std::vector<std::string>{"--report", dir.file("x")},
                               std::vector<std::string>{"--html", dir.file("link-to-x")}}) {
        std::vector<std::string> args = {"restore", tape, "-o", dir.file("x"), "--force"};
        args.insert(args.end(), second.begin(), second.end());
        Outcome r = tape_run(args, dir);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find("give each output its own file"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x")));
    }
    Outcome r = run(TAPE_DAMAGE_BINARY, {tape, "--seed", "1", "-o", dir.file("d"), "--log", dir.file("d")}, dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("d")));
}

TEST(CliOutputs, ReadIntoStandardOutputWritesTheImageThereAndMakesNoFileNamedDash) {
    TempDir dir;
    Outcome r = tape_run({"read", "file:" + iso_tape(), "-o", "-"}, dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, read_text(iso_tape()));
    EXPECT_FALSE(std::filesystem::exists(dir.file("-")));
    EXPECT_FALSE(std::filesystem::exists("-"));
}

TEST(CliOutputs, ReadIntoDevNullOrAFifoWithForceEndsWell) {
    TempDir dir;
    Outcome r = tape_run({"read", "file:" + iso_tape(), "-o", "/dev/null", "--force"}, dir);
    EXPECT_EQ(r.status, 0) << r.err;
    std::string fifo = dir.file("fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string got;
    std::thread reader([&] { got = read_text(fifo); });
    r = tape_run({"receive", "file:" + iso_tape(), "--whole", "-o", fifo, "--force"}, dir);
    reader.join();
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(got, read_text(iso_tape()));
}

TEST(CliOutputs, AFiveTrackImageFromAnEightTrackDeviceIsRefusedBeforeTheRun) {
    TempDir dir;
    Outcome r = tape_run({"read", "file:" + iso_tape(), "-o", dir.file("out.hex5")}, dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("hex5 images hold 5-track tape"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.hex5")));
    // A 5-track tape read into a 5-track image is what such an image is for.
    r = tape_run({"read", "file:" + sample_path("telegram.mtk2.hex5"), "-o", dir.file("copy.hex5")}, dir);
    EXPECT_EQ(r.status, 0) << r.err;
}

TEST(CliOutputs, AKilledEncodeLeavesNothingBehind) {
    TempDir dir;
    std::string fifo = dir.file("in.txt");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    Process encode({"encode", fifo, "-o", dir.file("out.ptp")}, dir);
    {
        // The first chunk is encoded and written (the output exists, unnamed); the run then waits for more.
        std::ofstream in(fifo);
        in << std::string(200000, 'G') << "\n" << std::flush;
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        encode.signal(SIGKILL);
        EXPECT_EQ(encode.wait(), 128 + SIGKILL);
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir.path)) {
        std::string name = entry.path().filename();
        EXPECT_TRUE(name == "in.txt" || name == "stdout" || name == "stderr") << "left behind: " << name;
    }
}

TEST(CliBounds, InputsLongerThanAnyTapeAreRefusedBeforeTheyAreRead) {
    TempDir dir;
    // 300 MB that take no room: a raw image of 3 * 10^8 frames.
    std::string big = dir.file("big.ptp");
    { std::ofstream(big).close(); }
    std::filesystem::resize_file(big, 300'000'000);
    Outcome r = tape_run({"emulate", big, "serial:/dev/null"}, dir);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("no paper tape is so long"), std::string::npos) << r.err;
    r = run(TAPE_DAMAGE_BINARY, {big, "--seed", "1", "-o", dir.file("d.ptp")}, dir);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("no paper tape is so long"), std::string::npos) << r.err;
    r = run(TAPE_ADAPTER_SIM, {"--reader", big}, dir);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("no paper tape is so long"), std::string::npos) << r.err;
    r = tape_run({"--eia-table", "/dev/zero", "decode", sample_path("gost-20999-format-example.eia.ptp")}, dir);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("is larger than"), std::string::npos) << r.err;
}

TEST(CliOutputs, BlocksAndSearchSpellOutTheControlBytesOfATape) {
    TempDir dir;
    // An ISO tape (even parity on track 8) whose block holds an ESC and a BEL: a terminal would act on them.
    std::string text = "%\nN1 G01 X10\x1b[2J\x07\nN2 M02\n%\n";
    std::string image;
    for (unsigned char c : text) image += static_cast<char>(__builtin_parity(c) ? c | 0x80 : c);
    std::ofstream(dir.file("t.ptp"), std::ios::binary) << std::string(10, '\0') << image << std::string(10, '\0');
    for (const auto& args : {std::vector<std::string>{"blocks", dir.file("t.ptp"), "-k"},
                             std::vector<std::string>{"search", dir.file("t.ptp"), "--block", "1", "-k"}}) {
        Outcome r = tape_run(args, dir);
        EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << args[0] << ": " << r.out;
        EXPECT_EQ(r.out.find('\x07'), std::string::npos) << args[0] << ": " << r.out;
        EXPECT_NE(r.out.find("\\x1B[2"), std::string::npos) << args[0] << ": " << r.out << r.err;
        EXPECT_NE(r.out.find("\\x07"), std::string::npos) << args[0] << ": " << r.out << r.err;
    }
}
