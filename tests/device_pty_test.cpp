// The device layer on real kernel pseudo-terminals; the test plays the controller on the master side.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <thread>

#include "pty_util.hpp"
#include "tape/device.hpp"
#include "tape/dnc.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace tape;
using namespace std::chrono_literals;

namespace {

std::vector<Frame> long_program() {
    std::string text = "%\n";
    for (int n = 1; n <= 300; ++n) text += "N" + std::to_string(n) + " G01 X+" + std::to_string(n) + ".5 Y-2.25 F120\n";
    text += "N999 M02\n";
    return encode(text, EncodeOptions{.leader = 10, .trailer = 10});
}

}  // namespace

// DC3 and DC1 at random points: every frame arrives once, in order, and after DC3 nothing comes
// beyond what was already on its way.
TEST(DevicePty, SenderObeysXonXoffAndLosesNothing) {
    Pty pty;
    auto frames = long_program();
    auto line = open_device(pty.device("baud=115200&flow=xonxoff"), DeviceUse::both);
    SendResult result;
    std::thread sender([&] { result = send_frames(*line, frames, SendOptions{.rate = 4000}); });
    std::vector<std::uint8_t> got;
    std::mt19937 rng(7);
    std::vector<std::size_t> pause_at;  // a dozen random points of the tape
    for (int k = 0; k < 12; ++k) pause_at.push_back(rng() % (frames.size() - 40));
    std::sort(pause_at.begin(), pause_at.end());
    std::size_t pauses = 0, worst_after_xoff = 0;
    while (got.size() < frames.size()) {
        pty.receive(got, 200ms);
        if (pauses < pause_at.size() && got.size() >= pause_at[pauses]) {
            pty.send(dc3);
            std::size_t at_xoff = got.size();
            pty.receive_until_quiet(got, 40ms);
            worst_after_xoff = std::max(worst_after_xoff, got.size() - at_xoff);
            std::vector<std::uint8_t> more;
            pty.receive(more, 60ms);  // paused: the line stays quiet
            EXPECT_TRUE(more.empty()) << more.size() << " frame(s) after DC3 and a quiet line";
            got.insert(got.end(), more.begin(), more.end());
            ++pauses;
            pty.send(dc1);
        }
    }
    sender.join();
    EXPECT_EQ(got, frames);
    EXPECT_EQ(pauses, pause_at.size());
    EXPECT_EQ(result.pauses, pauses);
    // Frames already on their way when DC3 was sent; the hard rule (nothing once the sender has seen
    // DC3) is the quiet line above. The bound is loose so that a loaded machine does not fail it.
    EXPECT_LE(worst_after_xoff, 8U) << "frames that arrived after DC3";
}

TEST(DevicePty, WaitXonSendsNothingBeforeDc1) {
    Pty pty;
    auto frames = long_program();
    auto line = open_device(pty.device(), DeviceUse::both);
    std::thread sender([&] { send_frames(*line, frames, SendOptions{.rate = 20000, .wait_xon = true}); });
    std::vector<std::uint8_t> got;
    pty.receive(got, 300ms);
    EXPECT_TRUE(got.empty());
    pty.send(dc1);
    while (got.size() < frames.size() && pty.receive(got, 1000ms) > 0) {
    }
    sender.join();
    EXPECT_EQ(got, frames);
}

TEST(DevicePty, ControllerThatNeverSendsDc1TimesOut) {
    Pty pty;
    auto line = open_device(pty.device(), DeviceUse::both);
    auto frames = long_program();
    try {
        send_frames(*line, frames, SendOptions{.wait_xon = true, .xon_timeout = 300ms});
        FAIL() << "sent without DC1";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::io);
        EXPECT_NE(std::string(e.what()).find("no DC1"), std::string::npos) << e.what();
    }
    std::vector<std::uint8_t> got;
    pty.receive(got, 50ms);
    EXPECT_TRUE(got.empty());
}

TEST(DevicePty, ControllerHangingUpMidProgramIsReportedWithTheFrame) {
    Pty pty;
    auto frames = long_program();
    auto line = open_device(pty.device(), DeviceUse::both);
    pty.release_slave();
    std::string message;
    std::thread sender([&] {
        try {
            send_frames(*line, frames, SendOptions{.rate = 5000});
        } catch (const Error& e) {
            message = e.what();
        }
    });
    std::vector<std::uint8_t> got;
    while (got.size() < 200) pty.receive(got, 500ms);
    pty.close_master();
    sender.join();
    EXPECT_NE(message.find("hung up"), std::string::npos) << message;
}

TEST(DevicePty, ReaderKeepsEveryFrameWhenTheOtherSideCloses) {
    Pty pty;
    auto frames = long_program();
    auto line = open_device(pty.device("baud=9600&flow=none"), DeviceUse::read);
    pty.release_slave();
    std::vector<Frame> kept;
    ReceiveResult result;
    std::thread reader([&] {
        result = receive_frames(*line, ReceiveOptions{.idle_timeout = 5s, .sink = [&](std::span<const Frame> f) {
                                                          kept.insert(kept.end(), f.begin(), f.end());
                                                      }});
    });
    for (std::size_t i = 0; i < frames.size(); i += 97) {
        std::size_t n = std::min<std::size_t>(97, frames.size() - i);
        ASSERT_EQ(::write(pty.master, frames.data() + i, n), static_cast<ssize_t>(n));
        std::this_thread::sleep_for(2ms);
    }
    std::this_thread::sleep_for(100ms);  // let the reader take the last bytes before the line goes
    pty.close_master();
    reader.join();
    EXPECT_EQ(kept, frames);
    EXPECT_EQ(result.end, ReceiveResult::End::hangup);
}

TEST(DevicePty, ReceiverEndsAtThePercentAfterM02AndDropsFlowCodes) {
    Pty pty;
    auto line = open_device(pty.device(), DeviceUse::read);
    std::vector<Frame> tape = encode("%\nN1 G01 X1\nN2 M02\n%", EncodeOptions{.leader = 3, .trailer = 0});
    std::vector<Frame> sent = tape;
    sent.insert(sent.begin(), dc2);              // punch on
    auto after = encode("N3 X9\n", EncodeOptions{.leader = 0, .trailer = 0});
    sent.insert(sent.end(), after.begin(), after.end());  // beyond the end: not taken
    std::vector<Frame> kept;
    ReceiveResult result;
    std::thread receiver([&] {
        result = receive_frames(*line, ReceiveOptions{.idle_timeout = 3s, .until_program_end = true, .drop_flow_codes = true,
                                                      .sink = [&](std::span<const Frame> f) { kept.insert(kept.end(), f.begin(), f.end()); }});
    });
    ASSERT_EQ(::write(pty.master, sent.data(), sent.size()), static_cast<ssize_t>(sent.size()));
    receiver.join();
    EXPECT_EQ(result.end, ReceiveResult::End::program_end);
    EXPECT_EQ(kept, tape);
}

TEST(DevicePty, StoppedReceiverSendsDc3AndStillTakesTheLastCharacters) {
    Pty pty;
    auto line = open_device(pty.device(), DeviceUse::read);
    std::atomic<bool> stop{false};
    std::vector<Frame> kept;
    std::thread receiver([&] {
        receive_frames(*line, ReceiveOptions{.stop = &stop, .sink = [&](std::span<const Frame> f) { kept.insert(kept.end(), f.begin(), f.end()); }});
    });
    std::vector<std::uint8_t> first(50, 0xA5);
    ASSERT_EQ(::write(pty.master, first.data(), first.size()), 50);
    std::this_thread::sleep_for(100ms);
    stop = true;
    std::vector<std::uint8_t> answer;
    pty.receive(answer, 1000ms);
    ASSERT_EQ(answer, std::vector<std::uint8_t>{dc3});
    std::vector<std::uint8_t> late(10, 0x0A);  // a controller may send up to 10 more after DC3
    ASSERT_EQ(::write(pty.master, late.data(), late.size()), 10);
    receiver.join();
    EXPECT_EQ(kept.size(), 60U);
}

// The emulated reader: start on DC1, stop on DC3 within one frame, rewind to '%' at the program's end.
TEST(DevicePty, EmulatorStartsStopsAndRewinds) {
    Pty pty;
    auto tape = encode("%\n:1 G90\nN2 X1\n:3 X2\nN4 M02\n", EncodeOptions{.leader = 20, .trailer = 20});
    auto line = open_device(pty.device(), DeviceUse::both);
    std::atomic<bool> stop{false};
    std::vector<std::string> log;
    EmulatorResult result;
    std::thread emulator([&] {
        result = emulate_reader(*line, tape, EmulatorOptions{.rate = 2000, .stop = &stop,
                                                             .log = [&](std::uint64_t f, const std::string& w) {
                                                                 log.push_back(std::to_string(f) + " " + w);
                                                             }});
    });
    std::vector<std::uint8_t> got;
    pty.receive(got, 100ms);
    EXPECT_TRUE(got.empty()) << "sent before DC1";
    std::vector<Frame> program(tape.begin() + 20, tape.end() - 20);  // leader skipped, stops at the end of program
    pty.send(dc1);
    while (got.size() < 8) pty.receive(got, 500ms);
    pty.send(dc3);
    std::size_t at_stop = got.size();
    pty.receive_until_quiet(got, 50ms);
    EXPECT_LE(got.size() - at_stop, 8U) << "frames after DC3";
    std::vector<std::uint8_t> quiet;
    pty.receive(quiet, 50ms);
    EXPECT_TRUE(quiet.empty()) << "the reader went on after DC3";
    pty.send(dc1);
    pty.receive_until_size(got, program.size(), 5s);
    pty.receive_until_quiet(got, 100ms);  // and nothing after the end of the program
    EXPECT_EQ(got, program);
    // Rewound to '%': the next start reads the program again from its start.
    std::vector<std::uint8_t> again;
    pty.send(dc1);
    while (again.size() < 3) pty.receive(again, 500ms);
    pty.send(dc3);
    pty.receive_until_quiet(again, 50ms);
    EXPECT_EQ(again[0], 0xA5);
    stop = true;
    emulator.join();
    EXPECT_EQ(result.rewinds, 1U);
    EXPECT_GE(result.starts, 3U);
}

TEST(DevicePty, EmulatorSearchesAMainBlockOnRequest) {
    Pty pty;
    auto tape = encode("%\n:1 G90\nN2 X1\n:3 X2\nN4 M02\n", EncodeOptions{.leader = 5, .trailer = 5});
    auto line = open_device(pty.device(), DeviceUse::both);
    std::atomic<bool> stop{false};
    std::thread emulator([&] { emulate_reader(*line, tape, EmulatorOptions{.rate = 5000, .stop = &stop}); });
    for (char c : std::string(":3")) pty.send(static_cast<std::uint8_t>(c));
    std::this_thread::sleep_for(100ms);
    pty.send(dc1);
    std::vector<std::uint8_t> got;
    auto expected = encode(":3 X2\nN4 M02\n", EncodeOptions{.leader = 0, .trailer = 0});
    pty.receive_until_size(got, expected.size(), 5s);
    pty.receive_until_quiet(got, 100ms);
    stop = true;
    emulator.join();
    EXPECT_EQ(got, expected);
}

// Pseudo-terminals refuse 7E settings, so the 7-bit line is a double at the lowest level: the transport.
TEST(DeviceSend, SevenBitLineDropsTrackEightForTheUart) {
    struct SevenBitLine : Transport {
        std::vector<std::uint8_t> written;
        ReadResult read(std::span<std::uint8_t>, std::chrono::milliseconds) override { return {}; }
        void write(std::span<const std::uint8_t> b) override { written.insert(written.end(), b.begin(), b.end()); }
        void drain() override {}
        bool seven_bit() const override { return true; }
        std::string name() const override { return "7E2 line"; }
    } line;
    std::vector<Frame> frames = {0xA5, 0x0A, 0xB1, 0x00, 0xFF};
    send_frames(line, frames, SendOptions{});
    EXPECT_EQ(line.written, (std::vector<std::uint8_t>{0x25, 0x0A, 0x31, 0x00, 0x7F}));
}

TEST(DevicePty, EightBitLineSendsFramesAsOnTape) {
    Pty pty;
    auto line = open_device(pty.device("baud=9600&bits=8&flow=none"), DeviceUse::both);
    EXPECT_FALSE(line->seven_bit());
    std::vector<Frame> frames = {0xA5, 0x0A, 0xB1};
    send_frames(*line, frames, SendOptions{.rate = 1000});
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, frames.size(), 5s);
    EXPECT_EQ(got, frames);
}

TEST(Devices, TableAndErrors) {
    ASSERT_GE(device_backends().size(), 2U);
    EXPECT_EQ(device_backends()[0].prefix, "file");
    try {
        open_device("tty:/dev/ttyS0", DeviceUse::read);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage);
        EXPECT_NE(std::string(e.what()).find("file:, serial:"), std::string::npos) << e.what();
    }
    try {
        open_device("serial:/dev/no-such-tty?baud=9600", DeviceUse::both);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::io);
    }
}

TEST(Devices, FileDeviceReadsImagesAndWritesNewFiles) {
    auto line = open_device("file:" + sample_path("gost-20999-format-example.iso.holes"), DeviceUse::read);
    std::vector<Frame> frames;
    std::uint8_t buf[100];
    for (;;) {
        ReadResult r = line->read(buf, 0ms);
        frames.insert(frames.end(), buf, buf + r.count);
        if (r.end) break;
    }
    EXPECT_EQ(frames.size(), 212U);  // 10 + 192 + 10
    EXPECT_THROW(open_device("file:" + sample_path("gost-20999-format-example.iso.ptp"), DeviceUse::write), Error);
}

// Pseudo-terminals have no modem lines: CTS is a double at the lowest level, the ModemLines interface.
TEST(DeviceSend, RtsCtsHoldsTheLineWhileCtsIsDown) {
    struct Line : Transport, ModemLines {
        std::atomic<bool> clear{false};
        std::atomic<std::size_t> count{0};
        ReadResult read(std::span<std::uint8_t>, std::chrono::milliseconds) override { return {}; }
        void write(std::span<const std::uint8_t> b) override { count += b.size(); }
        void drain() override {}
        ModemLines* modem() override { return this; }
        Flow flow() const override { return Flow::rtscts; }
        bool cts() override { return clear; }
        void set_rts(bool) override {}
        std::string name() const override { return "rts/cts line"; }
    } line;
    std::vector<Frame> frames(50, 0xA5);
    std::thread sender([&] { send_frames(line, frames, SendOptions{.rate = 10000}); });
    std::this_thread::sleep_for(100ms);
    EXPECT_EQ(line.count.load(), 0U) << "sent with CTS down";
    line.clear = true;
    sender.join();
    EXPECT_EQ(line.count.load(), 50U);
}

TEST(DeviceSend, SevenBitLineRefusesFramesItCannotCarry) {
    struct SevenBitLine : Transport {
        std::size_t written = 0;
        ReadResult read(std::span<std::uint8_t>, std::chrono::milliseconds) override { return {}; }
        void write(std::span<const std::uint8_t> b) override { written += b.size(); }
        void drain() override {}
        bool seven_bit() const override { return true; }
        std::string name() const override { return "7E2 line"; }
    } line;
    auto eia = encode("%\nN1\n", EncodeOptions{.code = Code::eia, .leader = 0, .trailer = 0});
    EXPECT_THROW(send_frames(line, eia, SendOptions{}), Error);
    EXPECT_EQ(line.written, 0U);
}

// The clock is injected: pacing is checked without waiting, on the times the sender asks for.
TEST(DeviceSend, PacingFollowsTheRateExactly) {
    struct FakeClock : Clock {
        time_point t{};
        std::vector<time_point> sleeps;
        time_point now() override { return t; }
        void sleep_until(time_point until) override {
            sleeps.push_back(until);
            if (until > t) t = until;
        }
    } clock;
    struct Line : Transport {
        ReadResult read(std::span<std::uint8_t>, std::chrono::milliseconds) override { return {}; }
        void write(std::span<const std::uint8_t>) override {}
        void drain() override {}
        std::string name() const override { return "line"; }
    } line;
    std::vector<Frame> frames(10, 0xA5);
    send_frames(line, frames, SendOptions{.rate = 100}, clock);
    ASSERT_EQ(clock.sleeps.size(), 10U);
    for (std::size_t i = 1; i < clock.sleeps.size(); ++i) EXPECT_EQ(clock.sleeps[i] - clock.sleeps[i - 1], 10ms);
}
