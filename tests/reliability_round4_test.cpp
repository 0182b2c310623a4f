// Issue 37's cases outside the DNC service (reliability, round four), each with real files and the real
// tape program: the doubts file beside a restored image (a frame past 2^64, controls in its reasons, the
// runs decided against a read), pictures given to scan (a declared size too large, /dev/zero, damaged
// data), a text program given to punch and emulate, and a blank read given to restore.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <span>

#include "process_util.hpp"
#include "scan/picture_header.hpp"
#include "tape/encode.hpp"
#include "tape/input.hpp"
#include "tape/restore.hpp"
#include "tape/restore_doubts.hpp"
#include "tape/scan.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

std::span<const std::uint8_t> bytes_of(std::string_view s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// A restored image of "%\nN1 X100\nN2 X200\nM02\n" and a doubts file beside it holding problems.
struct RestoredImage {
    TempDir dir;
    std::string image = dir.file("out.ptp");
    std::vector<Frame> tape = encode("%\nN1 X100\nN2 X200\nM02\n", EncodeOptions{.leader = 10, .trailer = 10});

    explicit RestoredImage(const std::string& problems) {
        write_frames(image, tape);
        std::ofstream(doubts_file_for(image)) << R"({"schema":"tape-restore/2","problems":[)" << problems << "],"
                                              << R"("image":{"bytes":)" << tape.size() << R"(,"fnv1a64":")"
                                              << image_fingerprint(bytes_of(read_text(image))) << "\"}}";
    }
};

}  // namespace

// 9. A frame past 2^64, negative, a fraction or an exponent is refused by name (no double-to-integer
// conversion, which UBSan calls float-cast-overflow); the other entries are still read.
TEST(Round4Doubts, AFrameNumberThatIsNoFrameIsRefusedByName) {
    RestoredImage r(R"({"status":"contested","in_doubt":true,"frame":1e20,"after":0,"reason":"huge"},)"
                    R"({"status":"contested","in_doubt":true,"frame":18446744073709551616,"after":0,"reason":"2^64"},)"
                    R"({"status":"contested","in_doubt":true,"frame":-3,"after":0,"reason":"negative"},)"
                    R"({"status":"contested","in_doubt":true,"frame":23.5,"after":0,"reason":"half"},)"
                    R"({"status":"contested","in_doubt":true,"frame":null,"after":1e300,"reason":"far"},)"
                    R"({"status":"contested","in_doubt":true,"frame":23,"after":22,"reason":"a good one"})");
    DoubtsFile file = read_doubts_beside(r.image);
    ASSERT_EQ(file.frames.size(), 1U);
    EXPECT_EQ(file.frames[0].frame, 23U);
    ASSERT_EQ(file.refused.size(), 5U);
    EXPECT_EQ(file.refused[0], "problem 1: its frame (1e+20) is no frame number: not read");
    EXPECT_NE(file.refused[2].find("(-3)"), std::string::npos);
    EXPECT_NE(file.refused[4].find("its after"), std::string::npos);
    // Every command reading the image says so, and still names the good one.
    Outcome decoded = tape_run({"decode", "-k", r.image, "-o", r.dir.file("o.nc")}, r.dir);
    EXPECT_EQ(decoded.status, 1) << decoded.err;
    EXPECT_NE(decoded.err.find("out.ptp.restore.json: problem 1: its frame (1e+20) is no frame number: not read"),
              std::string::npos)
        << decoded.err;
    EXPECT_NE(decoded.err.find("warning: "), std::string::npos);
    EXPECT_NE(decoded.err.find("frame 23 (byte 0x16, line 3): restored in doubt (contested): a good one"),
              std::string::npos)
        << decoded.err;
}

// A hostile file cannot flood the terminal, and one that is no JSON at all is said, not read.
TEST(Round4Doubts, ManyBadEntriesAreCountedAndNoJsonIsSaid) {
    std::string many;
    for (int i = 0; i < 50; ++i) many += std::string(i ? "," : "") + R"({"in_doubt":true,"frame":"x"})";
    RestoredImage r(many);
    DoubtsFile file = read_doubts_beside(r.image);
    ASSERT_EQ(file.refused.size(), 11U);
    EXPECT_EQ(file.refused.back(), "40 more problem(s) not read");
    std::ofstream(doubts_file_for(r.image)) << "{\"problems\": [";
    EXPECT_EQ(read_doubts_beside(r.image).refused,
              std::vector<std::string>{"not the JSON tape restore writes: not read"});
}

// 13. Controls from a doubts file (ESC, BEL) do not reach the SVG: shown as decode shows them, and the
// SVG parses as XML (python3's own parser, a real one).
TEST(Round4Doubts, ControlsOfADoubtReachNoSvg) {
    RestoredImage r(
        "{\"status\":\"contested\",\"in_doubt\":true,\"frame\":23,\"after\":22,"
        "\"reason\":\"bell \\u0007 escape \\u001b[31m red \\u0000 <&>\"}");
    std::string svg = r.dir.file("t.svg");
    Outcome rendered = tape_run({"render", r.image, "-o", svg}, r.dir);
    ASSERT_EQ(rendered.status, 0) << rendered.err;
    std::string text = read_text(svg);
    EXPECT_EQ(text.find('\x1B'), std::string::npos);
    EXPECT_EQ(text.find('\x07'), std::string::npos);
    EXPECT_NE(text.find("escape \\x1B[31m red"), std::string::npos);
    Outcome parsed =
        run("/usr/bin/python3", {"-c", "import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])", svg}, r.dir);
    EXPECT_EQ(parsed.status, 0) << parsed.err;
}

// 16. The runs decided two reads to one, from the issue's commands: every one in the doubts file with its
// odds (null where the program's rules decided), not in doubt; decode -v and lint name each, and the exit
// status is what it is without them.
TEST(Round4Doubts, RunsDecidedAgainstAReadAreNamedFromTheImage) {
    TempDir dir;
    std::string program;
    for (int i = 1; i <= 3000; ++i)
        program += "N" + std::to_string(i) + " G01 X" + std::to_string(i) + ".5 Y-" + std::to_string(i) + "\n";
    std::ofstream(dir.file("p.nc")) << program;
    std::string s = dir.file("s.ptp"), r = dir.file("r.ptp");
    ASSERT_EQ(tape_run({"encode", dir.file("p.nc"), "-o", s}, dir).status, 0);
    std::vector<std::string> restore{"restore"};
    for (int k = 1; k <= 3; ++k) {
        std::string d = dir.file("d" + std::to_string(k) + ".ptp");
        ASSERT_EQ(run(TAPE_DAMAGE_BINARY, {s, "-o", d, "--seed", std::to_string(k), "--damage", "0.01"}, dir).status,
                  0);
        restore.push_back(d);
    }
    restore.insert(restore.end(), {"-o", r, "--report", dir.file("report.txt")});
    Outcome restored = tape_run(restore, dir);
    ASSERT_NE(restored.status, 2) << restored.err;
    auto json = nlohmann::json::parse(read_text(doubts_file_for(r)));
    std::size_t decided = 0, by_odds = 0;
    for (const auto& p : json.at("problems")) {
        if (!p.at("run_length").get<bool>() || p.at("in_doubt").get<bool>()) continue;
        ++decided;
        const auto& odds = p.at("odds");
        EXPECT_EQ(odds.is_null(), p.at("reason").get<std::string>().find("times likelier") == std::string::npos)
            << p.dump();
        by_odds += odds.is_number() && odds.get<double>() >= 100;
    }
    ASSERT_GT(decided, 0U);
    EXPECT_GT(by_odds, 0U);
    EXPECT_EQ(read_doubts_beside(r).frames.size(), decided + doubts_beside(r).size());
    Outcome plain = tape_run({"decode", "-k", r, "-o", dir.file("a.nc")}, dir);
    Outcome verbose = tape_run({"-v", "decode", "-k", r, "-o", dir.file("b.nc")}, dir);
    EXPECT_EQ(plain.status, verbose.status);
    EXPECT_EQ(count_of(plain.err, "run length decided against a read"), 0U);
    EXPECT_EQ(count_of(verbose.err, ": note: run length decided against a read"), decided) << verbose.err;
    EXPECT_NE(verbose.err.find("times likelier"), std::string::npos);
    EXPECT_EQ(read_text(dir.file("a.nc")), read_text(dir.file("b.nc")));
    Outcome linted = tape_run({"lint", "-k", "--max-errors", "0", r}, dir);
    EXPECT_EQ(count_of(linted.out, ": run-decided: note: run length decided against a read"), decided)
        << linted.out.substr(0, 2000);
}

// 12. A text program given to punch or emulate is refused (exit 2, nothing punched): they send frames as
// they are, and a text's characters would go out with no parity and no leader.
TEST(Round4Send, ATextProgramIsNotPunchedAsFrames) {
    TempDir dir;
    std::ofstream(dir.file("big.txt")) << "%\nO1000\nN10 G01 X10 Y20\nM30\n%\n";
    Outcome punched = tape_run({"punch", dir.file("big.txt"), "file:" + dir.file("o.ptp")}, dir);
    EXPECT_EQ(punched.status, 2);
    EXPECT_NE(punched.err.find("a text program: use feed, or encode it first"), std::string::npos) << punched.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.ptp")));
    Outcome emulated = tape_run({"emulate", dir.file("big.txt"), "file:" + dir.file("e.ptp")}, dir);
    EXPECT_EQ(emulated.status, 2);
    EXPECT_NE(emulated.err.find("a text program: use feed, or encode it first"), std::string::npos) << emulated.err;
    // Its bytes as they are, when asked for; and an image is punched as before.
    EXPECT_EQ(tape_run({"punch", "--format", "raw", dir.file("big.txt"), "file:" + dir.file("raw.ptp")}, dir).status,
              0);
    ASSERT_EQ(tape_run({"encode", dir.file("big.txt"), "-o", dir.file("t.ptp")}, dir).status, 0);
    EXPECT_EQ(tape_run({"punch", dir.file("t.ptp"), "file:" + dir.file("p.ptp")}, dir).status, 0);
    EXPECT_EQ(read_text(dir.file("t.ptp")), read_text(dir.file("p.ptp")));
}

// 14. A read of blank tape only is not "a read of another tape": it has no punched frame.
TEST(Round4Restore, ABlankReadHasNoPunchedFrame) {
    TempDir dir;
    auto tape = encode("%\nN1 X100\nN2 X200\nM02\n%\n", EncodeOptions{});
    write_frames(dir.file("a.ptp"), tape);
    write_frames(dir.file("b.ptp"), tape);
    write_frames(dir.file("blank.ptp"), std::vector<Frame>(300, 0));
    Outcome refused = tape_run(
        {"restore", dir.file("a.ptp"), dir.file("b.ptp"), dir.file("blank.ptp"), "-o", dir.file("r.ptp")}, dir);
    EXPECT_EQ(refused.status, 1) << refused.err;
    EXPECT_NE(refused.err.find("blank.ptp: no punched frame"), std::string::npos) << refused.err;
    EXPECT_EQ(refused.err.find("another tape"), std::string::npos) << refused.err;
    Outcome dropped = tape_run({"restore", "--drop-unrelated", dir.file("a.ptp"), dir.file("b.ptp"),
                                dir.file("blank.ptp"), "-o", dir.file("r.ptp")},
                               dir);
    EXPECT_NE(dropped.err.find("left out: no punched frame"), std::string::npos) << dropped.err;
    EXPECT_NE(dropped.out.find("left out: no punched frame"), std::string::npos) << dropped.out;
}

namespace {

std::string big_endian(std::uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

// A PNG's signature and IHDR (8-bit grey) declaring width x height, then data that is no picture's.
std::string png_declaring(std::uint32_t width, std::uint32_t height) {
    return std::string("\x89PNG\r\n\x1A\n", 8) + big_endian(13) + "IHDR" + big_endian(width) + big_endian(height) +
           std::string("\x08\x00\x00\x00\x00", 5) + big_endian(0) + big_endian(1000) + "IDAT" +
           std::string(1000, '\x55');
}

}  // namespace

// 10. The size a picture declares is read from its header before any decoder allocates it; the bound lets
// a real 66 Mpx scan through.
TEST(Round4Pictures, ThePixelBoundIsReadFromTheHeader) {
    using scan::check_picture;
    auto bomb = png_declaring(20000, 20000);
    try {
        check_picture(bytes_of(bomb));
        ADD_FAILURE() << "a 400 Mpx picture was let through";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::bad_image);
        EXPECT_EQ(std::string(e.what()),
                  "a picture of 20000 x 20000 pixels (400 Mpx): scan reads at most 150 Mpx; scan the tape in pieces, "
                  "or at a lower resolution");
    }
    auto real = png_declaring(9921, 6654);  // 66 Mpx: an A4-long strip at 600 dpi and more
    EXPECT_EQ(check_picture(bytes_of(real)).width, 9921U);
    EXPECT_THROW(check_picture(bytes_of(std::string(64, '\0'))), Error);
    EXPECT_THROW(check_picture(bytes_of(png_declaring(0, 10))), Error);
    EXPECT_THROW(check_picture(bytes_of(png_declaring(20000, 20000).substr(0, 20))), Error);
    // JPEG: the size is in the start of frame, after whatever segments come first.
    std::string jpeg =
        std::string("\xFF\xD8\xFF\xE0\x00\x04xx\xFF\xC0\x00\x11\x08", 13) + "\x4E\x20\x4E\x20" + std::string(20, '\0');
    auto h = scan::read_picture_header(bytes_of(jpeg));
    ASSERT_TRUE(h);
    EXPECT_EQ(h->width * h->height, 400'000'000U);
    // TIFF: a width written twice (a fuzzer's find: libtiff keeps the first, 135, where the last said 2):
    // the larger counts, so the bound holds whichever a decoder takes.
    std::string tiff = std::string("II*\0\x08\0\0\0\x03\0", 10) +
                       std::string("\x00\x01\x03\0\x01\0\0\0\x87\0\0\0", 12) +
                       std::string("\x01\x01\x03\0\x01\0\0\0\x2D\0\0\0", 12) +
                       std::string("\x00\x01\x03\0\x01\0\0\0\x02\0\0\0", 12) + std::string(4, '\0');
    auto t = scan::read_picture_header(bytes_of(tiff));
    ASSERT_TRUE(t);
    EXPECT_EQ(t->width, 135U);
    EXPECT_EQ(t->height, 45U);
}

// The issue's commands: a 20000 x 20000 PNG, /dev/zero, a damaged picture. Each refused by name, at
// once, with no OpenCV or libpng internals.
TEST(Round4Pictures, ScanRefusesABombDevZeroAndDamageInWords) {
    if (!scan_available()) GTEST_SKIP() << scan_unavailable_message();
    TempDir dir;
    std::ofstream(dir.file("bomb.png"), std::ios::binary) << png_declaring(20000, 20000);
    auto started = std::chrono::steady_clock::now();
    Outcome bomb = tape_run({"scan", dir.file("bomb.png"), "-o", dir.file("o.ptp")}, dir);
    EXPECT_EQ(bomb.status, 1) << bomb.err;
    EXPECT_NE(bomb.err.find("20000 x 20000 pixels (400 Mpx): scan reads at most 150 Mpx"), std::string::npos)
        << bomb.err;
    Outcome zero = tape_run({"scan", "/dev/zero", "-o", dir.file("o.ptp")}, dir);
    EXPECT_EQ(zero.status, 1) << zero.err;
    EXPECT_NE(zero.err.find("/dev/zero: not a picture scan reads"), std::string::npos) << zero.err;
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(20));
    std::ofstream(dir.file("damaged.png"), std::ios::binary) << png_declaring(400, 300);
    Outcome damaged = tape_run({"scan", dir.file("damaged.png"), "-o", dir.file("o.ptp")}, dir);
    EXPECT_NE(damaged.status, 0);
    EXPECT_NE(damaged.err.find("damaged or cut short"), std::string::npos) << damaged.err;
    for (const auto* internal : {"OpenCV(", "Assertion", "libpng", ".cpp:"})
        EXPECT_EQ(damaged.err.find(internal), std::string::npos) << damaged.err;
}

namespace {

// The frames from the first punched to the last: what a restoration must give back (blank leader and
// trailer follow the majority of the reads).
std::vector<Frame> punched_part(std::vector<Frame> f) {
    auto first = std::find_if(f.begin(), f.end(), [](Frame x) { return x != 0; });
    auto last = std::find_if(f.rbegin(), f.rend(), [](Frame x) { return x != 0; }).base();
    return first < last ? std::vector<Frame>(first, last) : std::vector<Frame>{};
}

}  // namespace

// 15. Many reads of one 1 %-damaged tape: where two reads garble the same stretch, the frames they have
// and the other 18 lack are not written (the issue's 20 reads wrote 4 such frames, in doubt).
TEST(Round4Restore, ManyReadsWriteNoFrameTheTapeLacks) {
    TempDir dir;
    std::string program;
    for (int i = 1; i <= 3000; ++i)
        program += "N" + std::to_string(i) + " G01 X" + std::to_string(i) + ".5 Y-" + std::to_string(i) + "\n";
    std::ofstream(dir.file("p.nc")) << program;
    std::string s = dir.file("s.ptp");
    ASSERT_EQ(tape_run({"encode", dir.file("p.nc"), "-o", s}, dir).status, 0);
    std::vector<std::string> reads;
    for (int k = 1; k <= 20; ++k) {
        reads.push_back(dir.file("d" + std::to_string(k) + ".ptp"));
        ASSERT_EQ(run(TAPE_DAMAGE_BINARY, {s, "-o", reads.back(), "--seed", std::to_string(k), "--damage", "0.01"}, dir)
                      .status,
                  0);
    }
    for (std::size_t n : {15U, 20U}) {
        std::vector<std::string> args{"restore"};
        args.insert(args.end(), reads.begin(), reads.begin() + static_cast<std::ptrdiff_t>(n));
        std::string r = dir.file("r" + std::to_string(n) + ".ptp");
        args.insert(args.end(), {"-o", r, "--report", dir.file("report.txt"), "--force"});
        Outcome restored = tape_run(args, dir);
        ASSERT_NE(restored.status, 2) << restored.err;
        EXPECT_EQ(punched_part(read_frames(r)), punched_part(read_frames(s))) << n << " reads";
    }
}

// 11. A read with a long blank leader the others lack is not aligned frame by frame: its blank frames
// past the others' longest leader (and a margin) are left out before aligning, so that the restoration
// is the one without them (the issue's 8.6 M frames of leader took 12 GB and 553 s).
TEST(Round4Restore, ALongBlankLeaderOnlyOneReadHasIsNotAligned) {
    auto tape = encode("%\nN1 G01 X10.5 Y-1\nN2 G01 X20.5 Y-2\nN3 X30.5\nM02\n%\n", EncodeOptions{});
    std::vector<Frame> long_leader(400'000, blank_frame);
    long_leader.insert(long_leader.end(), tape.begin(), tape.end());
    std::vector<std::span<const Frame>> reads{long_leader, tape, tape};
    auto started = std::chrono::steady_clock::now();
    RestoreResult r = restore(reads, RestoreOptions{.code = FrameCode::iso()});
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(20));
    EXPECT_EQ(punched_part(r.frames), punched_part(tape));
    EXPECT_LE(r.count(FrameStatus::extra), 1000U + 1U);  // the margin's blank frames, not 400 000
    EXPECT_TRUE(r.complete());
}

// A program of `blocks` numbered blocks, as tape, and a read of it with `junk` frames of punched junk
// (random frames: no run of them is in the program) after its middle frame (a splice of other tape) or
// after its last (a reader that ran on over something else).
struct JunkRead {
    std::vector<Frame> tape, read;
    JunkRead(int blocks, std::size_t junk, bool at_end = false) {
        std::string program = "%\n";
        for (int i = 1; i <= blocks; ++i)
            program += "N" + std::to_string(i) + " G01 X" + std::to_string(i) + ".5 Y-" + std::to_string(i) + "\n";
        tape = encode(program + "M02\n%\n", EncodeOptions{});
        read = tape;
        std::uint32_t x = 12345;  // a fixed sequence: the same junk every run
        std::vector<Frame> frames(junk);
        for (auto& f : frames) {
            x = x * 1103515245U + 12345U;
            f = static_cast<Frame>(x >> 24 ? x >> 24 : 0xFF);  // punched: never blank tape
        }
        read.insert(read.begin() + static_cast<std::ptrdiff_t>(at_end ? tape.size() : tape.size() / 2), frames.begin(),
                    frames.end());
    }
};

// 11. A long stretch only one of three reads has is not aligned frame by frame: all but a margin at each
// side is left out before aligning, counted as frames only a minority has, and the restoration is the
// tape's. Each frame aligned would be a column voted and listed (about 1.4 KB each).
TEST(Round4Restore, ALongStretchOnlyOneReadHasIsLeftOutBeforeAligning) {
    JunkRead j(400, 300'000);
    std::vector<std::span<const Frame>> reads{j.tape, j.read, j.tape};
    RestoreResult r = restore(reads, RestoreOptions{.code = FrameCode::iso()});
    EXPECT_EQ(r.frames, j.tape);
    EXPECT_EQ(r.count(FrameStatus::extra), 300'000U);   // all of it, though only the margins were aligned
    EXPECT_LE(r.problems.size(), 2 * 1000U + 2 * 12U);  // the margins' frames, each listed; not 300 000
    EXPECT_TRUE(r.complete());
}

// Where only one other read lacks the stretch, nothing outvotes it: it is aligned as before.
TEST(Round4Restore, AStretchOneOfTwoReadsHasIsAlignedAsBefore) {
    JunkRead j(400, 5'000);
    std::vector<std::span<const Frame>> reads{j.read, j.tape};
    RestoreResult r = restore(reads, RestoreOptions{.code = FrameCode::iso()});
    EXPECT_GE(r.problems.size(), 5'000U);
}

// A reader that ran on past the trailer over 2 M frames of something else, as a real process under a
// bound of memory, with a deadline: each frame was a column voted and listed (gigabytes; the issue's
// 8.6 M frames of leader, 12.2 GB).
TEST(Round4Restore, ALongStretchOnlyOneReadHasIsRestoredInBoundedMemory) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: a bound on it says nothing here";
#endif
    JunkRead j(2000, 2'000'000, true);
    TempDir dir;
    write_frames(dir.file("a.ptp"), j.tape);
    write_frames(dir.file("b.ptp"), j.read);
    write_frames(dir.file("c.ptp"), j.tape);
    const std::string restore = std::string("ulimit -v 400000 && exec \"$0\" restore ") + dir.file("a.ptp") + " " +
                                dir.file("b.ptp") + " " + dir.file("c.ptp") + " -o " + dir.file("out.ptp");
    Outcome o = run("/bin/sh", {"-c", restore, TAPE_BINARY}, dir, std::chrono::seconds(120));
    EXPECT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(read_frames(dir.file("out.ptp")), j.tape);
}
