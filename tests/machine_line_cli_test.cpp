// `tape feed --machine` and `tape emulate --machine` on real pseudo-terminals: the profile's line (baud,
// data bits, stop bits, the UART's parity on a 7-bit line, flow), its DC1 wait and its reader speed are
// what the line runs at where the command line and the device string give none; what they give wins.
#include <gtest/gtest.h>
#include <termios.h>

#include <algorithm>
#include <chrono>
#include <fstream>

#include "process_util.hpp"
#include "pty_util.hpp"
#include "tape/encode.hpp"
#include "tape/image.hpp"
#include "tape/line_state.hpp"
#include "test_util.hpp"

using namespace tape;
using namespace std::chrono_literals;

namespace {

// A control's profile with only a line: 7 data bits, even parity, 2 stop bits, XON/XOFF, DC codes.
std::string profile(const TempDir& dir, unsigned baud, double rate, const std::string& flow = "xonxoff") {
    std::string path = dir.file("ctl.toml");
    std::ofstream(path) << "name = \"ctl\"\nkind = \"mill\"\nsource = \"test\"\n[line]\ncode = \"iso\"\n"
                        << "parity = \"even\"\nbaud = " << baud << "\ndata_bits = 7\nstop_bits = 2\nflow = \"" << flow
                        << "\"\ndc_codes = true\n";
    if (rate > 0) std::ofstream(path, std::ios::app) << "reader_frames_per_second = " << rate << "\n";
    return path;
}

// The line's settings once the code under test has set its speed to `speed`.
bool line_at(const Pty& pty, speed_t speed, termios& t) {
    return eventually([&] { return ::tcgetattr(pty.slave_keep, &t) == 0 && ::cfgetospeed(&t) == speed; });
}

std::vector<Frame> image_frames(const std::string& path) {
    std::string bytes = read_text(path);
    return image_format_for_path(path)->read({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
}

// A pseudo-terminal keeps the speed and the stop bits it is given, but makes every line 8 bits without
// parity (Linux's pty_set_termios): the 7 data bits show in what is sent (track 8 dropped for the UART to
// make), and the parity in that the line opens at all (bits=7 without parity=even or odd is refused).
std::vector<std::uint8_t> seven_bits(std::vector<std::uint8_t> frames) {
    EXPECT_TRUE(std::any_of(frames.begin(), frames.end(), [](std::uint8_t f) { return f & 0x80; }));
    for (auto& f : frames) f &= 0x7F;
    return frames;
}

}  // namespace

TEST(CliFeedMachine, TheProfilesLineDc1WaitAndReaderSpeed) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    std::string program = sample_path("gost-20999-format-example.txt");
    Process tape({"feed", program, "serial:" + pty.slave_path, "--machine", profile(dir, 4800, 200), "--leader", "5",
                  "--trailer", "5"},
                 dir);
    termios t{};
    ASSERT_TRUE(line_at(pty, B4800, t)) << tape.err();
    EXPECT_TRUE(t.c_cflag & CSTOPB);
    std::vector<std::uint8_t> got;
    pty.receive(got, 300ms);
    EXPECT_TRUE(got.empty()) << got.size() << " frame(s) before the control's DC1";
    auto expected = seven_bits(encode(read_text(program), EncodeOptions{.leader = 5, .trailer = 5}));
    auto start = std::chrono::steady_clock::now();
    pty.send(dc1);
    pty.receive_until_size(got, expected.size(), 20s);
    auto took = std::chrono::steady_clock::now() - start;
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(got, expected);
    // The reader's 200 frames a second, not the line's 4800 baud (436 a second at 7E2).
    EXPECT_GE(took, std::chrono::milliseconds(static_cast<long>(expected.size() - 1) * 5 * 9 / 10));
}

TEST(CliFeedMachine, TheProfilesFlowIsTheLinesUnlessTheDeviceStringSaysOtherwise) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    std::string ctl = profile(dir, 9600, 0, "rtscts");
    // A pty has no modem lines: the profile's RTS/CTS is refused as flow=rtscts in the string would be.
    Process refused({"feed", sample_path("16k20f3s5-turning.iso.ptp"), "serial:" + pty.slave_path, "--machine", ctl},
                    dir);
    EXPECT_EQ(refused.wait(), 2) << refused.err();
    EXPECT_NE(refused.err().find("flow=rtscts, but this device has no modem lines"), std::string::npos)
        << refused.err();
    Process own({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device("baud=19200&flow=none&bits=8"),
                 "--machine", ctl, "--rate", "2000"},
                dir);
    termios t{};
    ASSERT_TRUE(line_at(pty, B19200, t)) << own.err();
    EXPECT_TRUE(t.c_cflag & CSTOPB);  // the profile's, which the string left out
    pty.send(dc1);
    std::vector<std::uint8_t> got;
    auto frames = image_frames(sample_path("16k20f3s5-turning.iso.ptp"));
    pty.receive_until_size(got, frames.size(), 20s);
    EXPECT_EQ(own.wait(), 0) << own.err();
    EXPECT_EQ(got, frames);  // bits=8: track 8 sent as it is
}

TEST(CliEmulateMachine, TheProfilesLineAndReaderSpeedWithTheStringsBaud) {
    TempDir dir;
    PTY_OR_SKIP(pty);
    std::string image = sample_path("gost-20999-format-example.iso.ptp");
    Process tape({"emulate", image, pty.device("baud=9600"), "--machine", profile(dir, 2400, 300)}, dir);
    ASSERT_TRUE(tape.wait_for_err("loaded, waiting for DC1")) << tape.err();
    termios t{};
    ASSERT_TRUE(line_at(pty, B9600, t)) << "the device string's baud=9600 wins over the profile's 2400";
    EXPECT_TRUE(t.c_cflag & CSTOPB);
    auto bytes = read_text(image);
    auto frames =
        image_format_for_path(image)->read({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
    auto program = seven_bits(std::vector<std::uint8_t>(frames.begin() + 100, frames.end() - 100));
    auto start = std::chrono::steady_clock::now();
    pty.send(dc1);
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, program.size(), 20s);
    auto took = std::chrono::steady_clock::now() - start;
    pty.receive_until_quiet(got, 200ms);
    EXPECT_EQ(got, program);
    EXPECT_GE(took, std::chrono::milliseconds(static_cast<long>(program.size() - 1) * 1000 / 300 * 9 / 10));
    tape.interrupt();
    EXPECT_EQ(tape.wait(), 0) << tape.err();
}
