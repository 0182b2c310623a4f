// The real `tape` binary driving real pseudo-terminals: feed, receive, read, punch, emulate.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include "device/adapter_session.hpp"
#include "process_util.hpp"
#include "pty_util.hpp"
#include "tape/encode.hpp"
#include "tape/image.hpp"
#include "tape/line_state.hpp"
#include "test_util.hpp"

extern char** environ;

using namespace tape;
using namespace std::chrono_literals;

namespace {

std::vector<Frame> image_frames(const std::string& path) {
    std::string bytes = read_text(path);
    auto* f = image_format_for_path(path);
    return f->read({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
}

// Whether the image tape writes as frames come (tape read, tape receive) held n frames within the deadline:
// the reader has taken them from the line, which may then go.
bool holds_frames(const std::string& path, std::size_t n) {
    return eventually([&] {
        try {
            return std::filesystem::exists(path) && image_frames(path).size() >= n;
        } catch (const std::exception&) {  // a line of a text image half written
            return false;
        }
    });
}

}  // namespace

TEST(CliFeed, SendsTheProgramThroughPausesExactlyOnce) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    std::string text = read_text(sample_path("gost-20999-format-example.txt"));
    auto expected = encode(text, EncodeOptions{.leader = 5, .trailer = 5});  // exactly as written
    Process tape({"feed", sample_path("gost-20999-format-example.txt"), pty.device("baud=38400&flow=xonxoff"),
                  "--leader", "5", "--trailer", "5", "--rate", "500"},
                 dir);
    std::vector<std::uint8_t> got;
    int pauses = 0;
    // 500 frames/s: at 2000 a loaded machine kept this thread off the processor while the rest of the
    // program went by, and a pause was never asked for (scripts/stress-tests.sh).
    while (got.size() < expected.size() && pty.receive(got, 5000ms) > 0) {
        if (got.size() > 40 * static_cast<std::size_t>(pauses + 1) && pauses < 4) {
            pty.send(dc3);
            pty.receive_until_quiet(got, 50ms);
            std::vector<std::uint8_t> quiet;
            pty.receive(quiet, 50ms);
            EXPECT_TRUE(quiet.empty());
            ++pauses;
            pty.send(dc1);
        }
    }
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(got, expected) << got.size() << " of " << expected.size();
    EXPECT_EQ(pauses, 4);
}

TEST(CliFeed, WaitXonGivesUpOnASilentController) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device(), "--wait-xon", "--xon-timeout", "0.5"},
                 dir);
    EXPECT_EQ(tape.wait(), 3);
    EXPECT_NE(tape.err().find("no DC1 (XON)"), std::string::npos) << tape.err();
    std::vector<std::uint8_t> got;
    pty.receive(got, 10ms);
    EXPECT_TRUE(got.empty());
}

TEST(CliFeed, ControllerHangingUpEndsWithADeviceError) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device(), "--rate", "1000"}, dir);
    std::vector<std::uint8_t> got;
    while (got.size() < 50) ASSERT_GT(pty.receive(got, 5000ms), 0U);
    pty.release_slave();
    pty.close_master();
    EXPECT_EQ(tape.wait(), 3);
    EXPECT_NE(tape.err().find("hung up"), std::string::npos) << tape.err();
}

TEST(CliFeed, CtrlCStopsCleanly) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device(), "--rate", "1000"}, dir);
    std::vector<std::uint8_t> got;
    while (got.size() < 20) ASSERT_GT(pty.receive(got, 5000ms), 0U);
    pty.send(dc3);
    std::this_thread::sleep_for(50ms);
    tape.interrupt();
    EXPECT_EQ(tape.wait(), 130);
    EXPECT_NE(tape.err().find("stopped after"), std::string::npos) << tape.err();
}

TEST(CliReceive, KeepsTheProgramUpToThePercentAfterM02) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"receive", pty.device(), "-o", dir.file("in.ptp"), "--timeout", "5"}, dir);
    ASSERT_TRUE(pty.wait_opened()) << tape.err();
    auto program = encode("%\nN1 G01 X1\nN2 M30\n%", EncodeOptions{.leader = 4, .trailer = 0});
    std::vector<std::uint8_t> wire = {dc2};
    wire.insert(wire.end(), program.begin(), program.end());
    wire.push_back(dc4);
    ASSERT_EQ(::write(pty.master, wire.data(), wire.size()), static_cast<ssize_t>(wire.size()));
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(image_frames(dir.file("in.ptp")), program);
    EXPECT_NE(tape.err().find("end of program"), std::string::npos) << tape.err();
}

TEST(CliRead, KeepsEveryFrameWhenTheOtherSideCloses) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"read", pty.device("baud=9600&flow=none"), "-o", dir.file("in.holes"), "--timeout", "5"}, dir);
    ASSERT_TRUE(pty.wait_opened()) << tape.err();
    auto frames = image_frames(sample_path("16k20f3s5-turning.iso.ptp"));
    ASSERT_EQ(::write(pty.master, frames.data(), 200), 200);
    ASSERT_TRUE(holds_frames(dir.file("in.holes"), 200)) << tape.err();  // in two pieces
    ASSERT_EQ(::write(pty.master, frames.data() + 200, frames.size() - 200), static_cast<ssize_t>(frames.size() - 200));
    ASSERT_TRUE(holds_frames(dir.file("in.holes"), frames.size())) << tape.err();
    pty.release_slave();
    pty.close_master();
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(image_frames(dir.file("in.holes")), frames);
}

TEST(CliRead, RefusesAnExistingOutputWithoutForce) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    std::ofstream(dir.file("in.ptp")) << "keep";
    Process tape({"read", pty.device(), "-o", dir.file("in.ptp"), "--timeout", "1"}, dir);
    EXPECT_EQ(tape.wait(), 2);
    EXPECT_EQ(read_text(dir.file("in.ptp")), "keep");
}

TEST(CliPunch, SendsEveryFrameOfTheImage) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape(
        {"punch", sample_path("16k20f3s5-turning.eia.ptp"), pty.device("baud=115200&flow=none"), "--rate", "5000"},
        dir);
    auto frames = image_frames(sample_path("16k20f3s5-turning.eia.ptp"));
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, frames.size(), 10s);
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(got, frames);
}

TEST(CliEmulate, ReadsTheProgramOnDc1AndRewindsAtItsEnd) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"emulate", sample_path("gost-20999-format-example.iso.ptp"), pty.device(), "--rate", "3000"}, dir);
    pty.send(dc1);
    std::vector<std::uint8_t> got;
    auto frames = image_frames(sample_path("gost-20999-format-example.iso.ptp"));
    std::vector<Frame> program(frames.begin() + 100, frames.end() - 100);  // no leader; stops after M02's LF
    pty.receive_until_size(got, program.size(), 10s);
    pty.receive_until_quiet(got, 200ms);
    EXPECT_EQ(got, program);
    tape.interrupt();
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    std::string log = tape.err();
    EXPECT_NE(log.find("frame 101: start"), std::string::npos) << log;
    EXPECT_NE(log.find("end of program"), std::string::npos) << log;
    EXPECT_NE(log.find("frame 101: rewound to the '%' stop"), std::string::npos) << log;
}

TEST(CliFeed, RtsCtsOnALineWithoutModemLinesIsRefused) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    // A pty has no modem lines: --flow rtscts is refused as flow=rtscts in the device string is.
    Process by_option({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device("flow=none"), "--flow", "rtscts"},
                      dir);
    EXPECT_EQ(by_option.wait(), 2) << by_option.err();
    std::string message = by_option.err();
    EXPECT_NE(message.find("flow=rtscts, but this device has no modem lines"), std::string::npos) << message;
    std::vector<std::uint8_t> got;
    pty.receive(got, 100ms);
    EXPECT_TRUE(got.empty()) << got.size() << " frame(s) sent without flow control";
    Process by_string({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device("flow=rtscts")}, dir);
    EXPECT_EQ(by_string.wait(), 2) << by_string.err();
    EXPECT_EQ(by_string.err(), message);
}

TEST(CliEmulate, RtsCtsOnALineWithoutModemLinesIsRefused) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape(
        {"emulate", sample_path("gost-20999-format-example.iso.ptp"), pty.device("flow=none"), "--flow", "rtscts"},
        dir);
    EXPECT_EQ(tape.wait(5s), 2) << tape.err();
    EXPECT_NE(tape.err().find("flow=rtscts, but this device has no modem lines"), std::string::npos) << tape.err();
}

// The generic reader's normal end is the user stopping it: Ctrl-C or SIGTERM, exit 0, every frame kept.
TEST(CliRead, InterruptedOrHungUpKeepsEveryFrameAndExitsZero) {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        TempDir dir;
        PTY_OR_SKIP(pty);
        Process tape({"read", pty.device("baud=9600&flow=none"), "-o", dir.file("in.ptp"), "--timeout", "0"}, dir);
        ASSERT_TRUE(pty.wait_opened()) << tape.err();
        auto frames = image_frames(sample_path("16k20f3s5-turning.iso.ptp"));
        ASSERT_EQ(::write(pty.master, frames.data(), frames.size()), static_cast<ssize_t>(frames.size()));
        ASSERT_TRUE(holds_frames(dir.file("in.ptp"), frames.size())) << "signal " << sig << ": " << tape.err();
        tape.signal(sig);
        std::vector<std::uint8_t> answer;
        pty.receive(answer, 2000ms);  // DC3: "stop reader"
        EXPECT_EQ(tape.wait(), 0) << "signal " << sig << ": " << tape.err();
        EXPECT_EQ(image_frames(dir.file("in.ptp")), frames) << "signal " << sig;
    }
}

TEST(CliEmulate, HangUpWhileWaitingIsADeviceError) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"emulate", sample_path("gost-20999-format-example.iso.ptp"), pty.device()}, dir);
    // Hung up once it has the line, configured, and waits: before, the open or the set-up would fail.
    ASSERT_TRUE(tape.wait_for_err("loaded, waiting for DC1")) << tape.err();
    pty.release_slave();
    pty.close_master();
    EXPECT_EQ(tape.wait(), 3) << tape.err();
    EXPECT_NE(tape.err().find("hung up; 0 frame(s) sent"), std::string::npos) << tape.err();
}

TEST(CliEmulate, HangUpWhileSendingIsADeviceError) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"emulate", sample_path("16k20f3s5-turning.iso.ptp"), pty.device(), "--rate", "200"}, dir);
    ASSERT_TRUE(tape.wait_for_err("loaded, waiting for DC1")) << tape.err();
    pty.send(dc1);
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, 10, 5s);
    ASSERT_GE(got.size(), 10U);
    pty.release_slave();
    pty.close_master();
    EXPECT_EQ(tape.wait(), 3) << tape.err();
    EXPECT_NE(tape.err().find("hung up; "), std::string::npos) << tape.err();
    EXPECT_NE(tape.err().find(" frame(s) sent"), std::string::npos) << tape.err();
}

// A file: device gets the whole image at once, atomically: Ctrl-C at any moment leaves the whole file
// or none, never a part of it under its name, and no temporary beside it.
TEST(CliPunch, InterruptedFileOutputIsWholeOrAbsent) {
    TempDir dir;
    std::vector<Frame> frames = image_frames(sample_path("16k20f3s5-turning.iso.ptp"));
    {
        std::ofstream big(dir.file("big.ptp"), std::ios::binary);
        for (std::size_t n = 0; n < (16U << 20); n += frames.size())
            big.write(reinterpret_cast<const char*>(frames.data()), static_cast<std::streamsize>(frames.size()));
    }
    std::string big = read_text(dir.file("big.ptp"));
    // Interrupted at moments from the start to after the end of a run (about 60 ms when idle).
    for (auto delay = 0ms; delay <= 150ms; delay += 15ms) {
        std::filesystem::remove(dir.file("copy.ptp"));
        int status;
        {
            Process tape({"punch", dir.file("big.ptp"), "file:" + dir.file("copy.ptp")}, dir);
            std::this_thread::sleep_for(delay);
            tape.interrupt();
            status = tape.wait(60s);
        }
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(dir.path))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        EXPECT_TRUE(status == 0 || status == 130) << "status " << status << ", " << delay.count() << " ms";
        // A Ctrl-C just after the copy was put in place still ends the run with 130: the copy is whole then.
        bool copied = std::find(names.begin(), names.end(), "copy.ptp") != names.end();
        EXPECT_TRUE(copied || status != 0) << delay.count() << " ms";
        std::vector<std::string> expected = {"big.ptp", "stderr", "stdout"};
        if (copied) expected.insert(expected.begin() + 1, "copy.ptp");
        EXPECT_EQ(names, expected) << delay.count() << " ms: a temporary file left behind?";
        EXPECT_TRUE(!copied || read_text(dir.file("copy.ptp")) == big)
            << "copy.ptp differs from the image, " << delay.count() << " ms";
    }
}

// receive and emulate take the tape's parity rule as decode does, and refuse it for EIA with decode's
// words, before the device is opened or the image created.
TEST(CliReceive, ParityIsForIsoTapesOnly) {
    TempDir dir;
    const std::string message = "--parity is for ISO tapes; EIA parity is always odd on track 5";
    Process decode({"decode", "--code", "eia", "--parity", "odd", sample_path("16k20f3s5-turning.eia.ptp")}, dir);
    EXPECT_EQ(decode.wait(), 2);
    EXPECT_NE(decode.err().find(message), std::string::npos) << decode.err();
    Process receive({"receive", "file:" + sample_path("16k20f3s5-turning.eia.ptp"), "-o", dir.file("in.ptp"), "--code",
                     "eia", "--parity", "odd"},
                    dir);
    EXPECT_EQ(receive.wait(), 2);
    EXPECT_EQ(receive.err(), "tape: " + message + "\n");
    EXPECT_FALSE(std::filesystem::exists(dir.file("in.ptp")));
    Process emulate({"emulate", sample_path("16k20f3s5-turning.eia.ptp"), "file:" + dir.file("out.ptp"), "--code",
                     "eia", "--parity", "mark"},
                    dir);
    EXPECT_EQ(emulate.wait(), 2);
    EXPECT_EQ(emulate.err(), "tape: " + message + "\n");
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.ptp")));
}

TEST(CliReceive, MarkParityProgramEndsAtItsPercent) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    Process tape({"receive", pty.device(), "-o", dir.file("in.ptp"), "--timeout", "5", "--parity", "mark"}, dir);
    ASSERT_TRUE(pty.wait_opened()) << tape.err();
    auto program = encode("%\nN1 G01 X1\nN2 M30\n%", EncodeOptions{.parity = Parity::mark, .leader = 4, .trailer = 0});
    std::vector<std::uint8_t> wire = program;
    auto after = encode("N3 X9\n", EncodeOptions{.parity = Parity::mark, .leader = 0, .trailer = 0});  // not taken
    wire.insert(wire.end(), after.begin(), after.end());
    ASSERT_EQ(::write(pty.master, wire.data(), wire.size()), static_cast<ssize_t>(wire.size()));
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(image_frames(dir.file("in.ptp")), program);
    EXPECT_NE(tape.err().find("end of program"), std::string::npos) << tape.err();
}

TEST(CliEmulate, MarkParityTapeRewindsAtItsProgramEnd) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    auto tape = encode("%\nN1 G01 X1\nN2 M02\n", EncodeOptions{.parity = Parity::mark, .leader = 10, .trailer = 10});
    std::ofstream(dir.file("mark.ptp"), std::ios::binary)
        .write(reinterpret_cast<const char*>(tape.data()), static_cast<std::streamsize>(tape.size()));
    Process emulate({"emulate", dir.file("mark.ptp"), pty.device(), "--rate", "3000", "--parity", "mark"}, dir);
    pty.send(dc1);
    std::vector<Frame> program(tape.begin() + 10, tape.end() - 10);  // no leader; stops after M02's LF
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, program.size(), 10s);
    pty.receive_until_quiet(got, 200ms);
    EXPECT_EQ(got, program);
    emulate.interrupt();
    EXPECT_EQ(emulate.wait(), 0) << emulate.err();
    EXPECT_NE(emulate.err().find("frame 11: rewound to the '%' stop"), std::string::npos) << emulate.err();
}

TEST(CliDevices, ALineOnARegularFileOrAFifoIsRefusedAndNothingWrittenIntoIt) {
    TempDir dir;
    std::string file = dir.file("image.ptp");
    std::filesystem::copy_file(sample_path("circle-examples.iso.ptp"), file);
    std::string before = read_text(file);
    std::string fifo = dir.file("fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const auto& path : {file, fifo}) {
        for (const auto& device : {"adapter:" + path, "serial:" + path}) {
            Process tape({"read", device, "-o", dir.file("out.ptp")}, dir);
            EXPECT_EQ(tape.wait(), 2) << device << ": " << tape.err();
            EXPECT_NE(tape.err().find("is no serial port or pseudo-terminal"), std::string::npos) << tape.err();
            EXPECT_FALSE(std::filesystem::exists(dir.file("out.ptp"))) << device;
        }
        Process punch({"punch", sample_path("circle-examples.iso.ptp"), "adapter:" + path}, dir);
        EXPECT_EQ(punch.wait(), 2) << punch.err();
    }
    EXPECT_EQ(read_text(file), before);
}

namespace {

// A sysfs laid out as the kernel does for one USB serial port, with the USB device's attributes as given.
std::filesystem::path fake_sysfs(const TempDir& dir,
                                 const std::function<void(const std::filesystem::path&)>& usb_files) {
    namespace fs = std::filesystem;
    fs::path sys = dir.file("sys");
    fs::path usb = sys / "devices/pci0/usb1/1-1", tty = usb / "1-1:1.0/tty/ttyUSB0";
    fs::create_directories(tty);
    fs::create_directories(sys / "class/tty");
    std::ofstream(usb / "idVendor") << "0403\n";
    std::ofstream(usb / "idProduct") << "6001\n";
    usb_files(usb);
    fs::create_directory_symlink("../../../1-1:1.0", tty / "device");
    fs::create_directory_symlink(tty, sys / "class/tty/ttyUSB0");
    return sys;
}

std::string devices_under(const std::filesystem::path& sys, const TempDir& dir, int& status) {
    ::setenv("TAPE_SYSFS_ROOT", sys.c_str(), 1);
    Process tape({"devices"}, dir);
    ::unsetenv("TAPE_SYSFS_ROOT");
    status = tape.wait(5s);
    return read_text(dir.file("stdout"));
}

}  // namespace

TEST(CliDevices, AFifoOrAnEndlessFileAmongTheSysfsAttributesNeitherBlocksNorGrows) {
    TempDir dir;
    auto sys = fake_sysfs(dir, [](const std::filesystem::path& usb) {
        ASSERT_EQ(::mkfifo((usb / "serial").c_str(), 0600), 0);
        std::filesystem::create_symlink("/dev/zero", usb / "manufacturer");
        std::filesystem::create_symlink("/dev/urandom", usb / "product");
    });
    int status = -1;
    std::string out = devices_under(sys, dir, status);
    EXPECT_EQ(status, 0) << "within 5 s";
    EXPECT_NE(out.find("0403:6001"), std::string::npos) << out;
}

TEST(CliDevices, UsbStringsAreShownWithTerminalEscapesSpelledOutAndSerialsQuotedInDeviceStrings) {
    TempDir dir;
    auto sys = fake_sysfs(dir, [](const std::filesystem::path& usb) {
        std::ofstream(usb / "serial") << "A&B?\x1b[2J\n";
        std::ofstream(usb / "manufacturer") << "Evil\x1b]0;owned\x07 Corp\n";
    });
    int status = -1;
    std::string out = devices_under(sys, dir, status);
    EXPECT_EQ(status, 0);
    EXPECT_EQ(out.find('\x1b'), std::string::npos) << out;
    EXPECT_EQ(out.find('\x07'), std::string::npos) << out;
    EXPECT_NE(out.find("serial A&B?\\x1B[2J"), std::string::npos) << out;
    EXPECT_NE(out.find("Evil\\x1B]0;owned\\x07 Corp"), std::string::npos) << out;
    // An adapter's serial goes into its device string quoted: it selects that adapter and no other.
    EXPECT_EQ(tape::adapter::device_string("usb", {0x1209, 0x0001}, "A&serial=B?x"),
              "usb:1209:0001?serial=A%26serial%3DB%3Fx");
}

TEST(CliFeed, AnImageIsSentAsItIsReadNotOnceItIsWhole) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    std::string fifo = dir.file("tape.ptp");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    Process tape({"feed", fifo, pty.device("baud=115200&flow=none"), "--input", "image"}, dir);
    auto frames = image_frames(sample_path("16k20f3s5-turning.iso.ptp"));
    std::ofstream in(fifo, std::ios::binary);
    in.write(reinterpret_cast<const char*>(frames.data()), 200);
    in.flush();
    // The first frames reach the line while the rest of the tape has not been written yet.
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, 100, 3000ms);
    EXPECT_GE(got.size(), 100u);
    EXPECT_TRUE(std::equal(got.begin(), got.end(), frames.begin()));
    in.write(reinterpret_cast<const char*>(frames.data()) + 200, static_cast<std::streamsize>(frames.size() - 200));
    in.close();
    pty.receive_until_size(got, frames.size(), 5000ms);
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(got, frames);
}
