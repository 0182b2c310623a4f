// The device layer on real kernel pseudo-terminals; the test plays the controller on the master side.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <limits>
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

// The code under test on its own thread. Every way out of the test joins it, a failed ASSERT
// included (a std::thread left joinable would abort the whole test program), and `end` first makes
// the run finish (a stop flag, a hang-up), so that no join waits for ever. What the run throws is
// kept in error.
class Worker {
public:
    Worker(std::function<void()> body, std::function<void()> end)
        : end_(std::move(end)), thread_([this, body = std::move(body)] {
              try {
                  body();
              } catch (const Error& e) {
                  error = e.what();
              }
              done_ = true;
          }) {}
    ~Worker() {
        if (thread_.joinable()) {
            end_();
            thread_.join();
        }
    }
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    /// Waits up to limit for the run to end by itself, else ends it. False when it had to be ended.
    bool join(std::chrono::milliseconds limit = std::chrono::seconds(20)) {
        auto deadline = std::chrono::steady_clock::now() + limit;
        while (!done_ && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        bool by_itself = done_;
        if (!by_itself) end_();
        thread_.join();
        return by_itself;
    }

    std::string error;

private:
    std::atomic<bool> done_{false};
    std::function<void()> end_;
    std::thread thread_;
};

std::vector<Frame> long_program() {
    std::string text = "%\n";
    for (int n = 1; n <= 300; ++n) text += "N" + std::to_string(n) + " G01 X+" + std::to_string(n) + ".5 Y-2.25 F120\n";
    text += "N999 M02\n";
    return encode(text, EncodeOptions{.leader = 10, .trailer = 10});
}

// The pty line as the sender sees it: "not one frame after DC3" is checked on the sender's side, on
// the bytes it read and the frames it wrote, in their order, whatever the scheduler does meanwhile.
// Plays the controller punching out sent on the pty while a receiver (flow codes dropped) takes
// frames until the program's end: the frames kept, or nothing when the run did not end there.
std::vector<Frame> receive_program_sent(Pty& pty, Transport& line, const std::vector<Frame>& sent) {
    std::vector<Frame> kept;
    ReceiveResult result;
    Worker receiver(
        [&] {
            result = receive_frames(line, ReceiveOptions{.idle_timeout = 3s,
                                                         .until_program_end = true,
                                                         .drop_flow_codes = true,
                                                         .sink = [&](std::span<const Frame> f) {
                                                             kept.insert(kept.end(), f.begin(), f.end());
                                                         }});
        },
        [&] { pty.close_master(); });
    EXPECT_EQ(::write(pty.master, sent.data(), sent.size()), static_cast<ssize_t>(sent.size()));
    EXPECT_TRUE(receiver.join());
    EXPECT_EQ(result.end, ReceiveResult::End::program_end);
    return kept;
}

// A line without modem lines on which nothing comes (or that has hung up), counting what is written.
struct QuietLine : Transport {
    explicit QuietLine(std::string name, bool hung_up = false) : name_(std::move(name)), hung_up_(hung_up) {}
    ReadResult read(std::span<std::uint8_t>, std::chrono::milliseconds) override { return {0, hung_up_}; }
    void write(std::span<const std::uint8_t> b) override { written += b.size(); }
    void drain() override {}
    std::string name() const override { return name_; }
    std::size_t written = 0;

private:
    std::string name_;
    bool hung_up_;
};

struct WatchedLine : Transport {
    Transport& line;
    bool paused = false;
    std::size_t writes_while_paused = 0;
    explicit WatchedLine(Transport& l) : line(l) {}
    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
        ReadResult r = line.read(buffer, timeout);
        for (std::size_t i = 0; i < r.count; ++i) {
            if (buffer[i] == dc3) paused = true;
            if (buffer[i] == dc1) paused = false;
        }
        return r;
    }
    void write(std::span<const std::uint8_t> b) override {
        if (paused) writes_while_paused += b.size();
        line.write(b);
    }
    void drain() override { line.drain(); }
    Flow flow() const override { return line.flow(); }
    double line_rate() const override { return line.line_rate(); }
    std::string name() const override { return line.name(); }
};

}  // namespace

// DC3 and DC1 at random points: every frame arrives once, in order, and once the sender has seen DC3
// nothing more goes out.
TEST(DevicePty, SenderObeysXonXoffAndLosesNothing) {
    PTY_OR_SKIP(pty);
    auto frames = long_program();
    auto pty_line = open_device(pty.device("baud=115200&flow=xonxoff"), DeviceUse::both);
    WatchedLine line(*pty_line);
    SendResult result;
    Worker sender([&] { result = send_frames(line, frames, SendOptions{.rate = 4000}); }, [&] { pty.close_master(); });
    std::vector<std::uint8_t> got;
    std::mt19937 rng(7);
    // A dozen random points of the tape's first half: on a busy machine the frames come in large pieces
    // (this thread off the processor), and a point near the end could be passed by the tape's end.
    std::vector<std::size_t> pause_at;
    for (int k = 0; k < 12; ++k) pause_at.push_back(rng() % (frames.size() / 2));
    std::sort(pause_at.begin(), pause_at.end());
    std::size_t pauses = 0, worst_after_xoff = 0;
    auto deadline = std::chrono::steady_clock::now() + 30s;
    while (got.size() < frames.size() && std::chrono::steady_clock::now() < deadline) {
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
    EXPECT_TRUE(sender.join()) << "the sender did not end";
    EXPECT_EQ(sender.error, "");
    EXPECT_EQ(got, frames);
    EXPECT_EQ(pauses, pause_at.size());
    // A DC3 and its DC1 can reach the sender in one read when it was off the processor for the whole
    // pause (a busy machine): it never stopped then, and rightly counts no pause for that one.
    EXPECT_LE(result.pauses, pauses);
    EXPECT_GT(result.pauses, 0U);
    EXPECT_EQ(line.writes_while_paused, 0U) << "frames written after the sender had read DC3";
    // Frames already on their way when DC3 was sent: how many depends on how long this thread was
    // off the processor between reading the line and sending DC3, so the bound is only a sanity check.
    EXPECT_LE(worst_after_xoff, 200U) << "frames that arrived after DC3";
}

TEST(DevicePty, WaitXonSendsNothingBeforeDc1) {
    PTY_OR_SKIP(pty);
    auto frames = long_program();
    auto line = open_device(pty.device(), DeviceUse::both);
    Worker sender([&] { send_frames(*line, frames, SendOptions{.rate = 20000, .wait_xon = true, .xon_timeout = 20s}); },
                  [&] { pty.close_master(); });
    std::vector<std::uint8_t> got;
    pty.receive(got, 300ms);
    EXPECT_TRUE(got.empty());
    pty.send(dc1);
    pty.receive_until_size(got, frames.size(), 20s);
    EXPECT_TRUE(sender.join()) << "the sender did not end";
    EXPECT_EQ(sender.error, "");
    EXPECT_EQ(got, frames);
}

TEST(DevicePty, ControllerThatNeverSendsDc1TimesOut) {
    PTY_OR_SKIP(pty);
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
    PTY_OR_SKIP(pty);
    auto frames = long_program();
    auto line = open_device(pty.device(), DeviceUse::both);
    pty.release_slave();
    Worker sender([&] { send_frames(*line, frames, SendOptions{.rate = 5000}); }, [&] { pty.close_master(); });
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, 200, 10s);
    EXPECT_GE(got.size(), 200U);
    pty.close_master();
    EXPECT_TRUE(sender.join()) << "the sender went on after the hang-up";
    EXPECT_NE(sender.error.find("hung up"), std::string::npos) << sender.error;
}

TEST(DevicePty, ReaderKeepsEveryFrameWhenTheOtherSideCloses) {
    PTY_OR_SKIP(pty);
    auto frames = long_program();
    auto line = open_device(pty.device("baud=9600&flow=none"), DeviceUse::read);
    pty.release_slave();
    std::vector<Frame> kept;
    std::atomic<std::size_t> taken{0};
    ReceiveResult result;
    Worker reader(
        [&] {
            result = receive_frames(*line, ReceiveOptions{.idle_timeout = 5s, .sink = [&](std::span<const Frame> f) {
                                                              kept.insert(kept.end(), f.begin(), f.end());
                                                              taken += f.size();
                                                          }});
        },
        [&] { pty.close_master(); });
    for (std::size_t i = 0; i < frames.size(); i += 97) {
        std::size_t n = std::min<std::size_t>(97, frames.size() - i);
        ASSERT_EQ(::write(pty.master, frames.data() + i, n), static_cast<ssize_t>(n));
        std::this_thread::sleep_for(2ms);  // in pieces, as a line brings them
    }
    // The line goes once the reader has taken the last bytes: a hang-up drops what it has not read.
    EXPECT_TRUE(eventually([&] { return taken == frames.size(); })) << taken << " of " << frames.size();
    pty.close_master();
    EXPECT_TRUE(reader.join());
    EXPECT_EQ(kept, frames);
    EXPECT_EQ(result.end, ReceiveResult::End::hangup);
}

TEST(DevicePty, ReceiverEndsAtThePercentAfterM02AndDropsFlowCodes) {
    PTY_OR_SKIP(pty);
    auto line = open_device(pty.device(), DeviceUse::read);
    std::vector<Frame> tape = encode("%\nN1 G01 X1\nN2 M02\n%", EncodeOptions{.leader = 3, .trailer = 0});
    std::vector<Frame> sent = tape;
    sent.insert(sent.begin(), dc2);  // punch on
    auto after = encode("N3 X9\n", EncodeOptions{.leader = 0, .trailer = 0});
    sent.insert(sent.end(), after.begin(), after.end());  // beyond the end: not taken
    EXPECT_EQ(receive_program_sent(pty, *line, sent), tape);
}

TEST(DevicePty, StoppedReceiverSendsDc3AndStillTakesTheLastCharacters) {
    PTY_OR_SKIP(pty);
    auto line = open_device(pty.device(), DeviceUse::read);
    std::atomic<bool> stop{false};
    std::vector<Frame> kept;
    std::atomic<std::size_t> taken{0};
    Worker receiver(
        [&] {
            receive_frames(*line, ReceiveOptions{.stop = &stop, .sink = [&](std::span<const Frame> f) {
                                                     kept.insert(kept.end(), f.begin(), f.end());
                                                     taken += f.size();
                                                 }});
        },
        [&] { stop = true; });
    std::vector<std::uint8_t> first(50, 0xA5);
    ASSERT_EQ(::write(pty.master, first.data(), first.size()), 50);
    ASSERT_TRUE(eventually([&] { return taken == 50; })) << taken;  // stopped while running
    stop = true;
    std::vector<std::uint8_t> answer;
    pty.receive(answer, 1000ms);
    ASSERT_EQ(answer, std::vector<std::uint8_t>{dc3});
    std::vector<std::uint8_t> late(10, 0x0A);  // a controller may send up to 10 more after DC3
    ASSERT_EQ(::write(pty.master, late.data(), late.size()), 10);
    EXPECT_TRUE(receiver.join());
    EXPECT_EQ(kept.size(), 60U);
}

// The emulated reader: start on DC1, stop on DC3 within one frame, rewind to '%' at the program's end.
TEST(DevicePty, EmulatorStartsStopsAndRewinds) {
    PTY_OR_SKIP(pty);
    auto tape = encode("%\n:1 G90\nN2 X1\n:3 X2\nN4 M02\n", EncodeOptions{.leader = 20, .trailer = 20});
    auto line = open_device(pty.device(), DeviceUse::both);
    std::atomic<bool> stop{false};
    std::vector<std::string> log;
    EmulatorResult result;
    Worker emulator(
        [&] {
            result = emulate_reader(
                *line, tape,
                EmulatorOptions{.rate = 200, .stop = &stop, .log = [&](std::uint64_t f, const std::string& w) {
                                    log.push_back(std::to_string(f) + " " + w);
                                }});
        },
        [&] { stop = true; });
    std::vector<std::uint8_t> got;
    pty.receive(got, 100ms);
    EXPECT_TRUE(got.empty()) << "sent before DC1";
    std::vector<Frame> program(tape.begin() + 20, tape.end() - 20);  // leader skipped, stops at the end of program
    // 200 frames/s: the DC3 sent after 8 frames must come before the program's last (at 2000 frames/s a
    // loaded machine kept this thread off the processor for the 10 ms that were left).
    pty.send(dc1);
    pty.receive_until_size(got, 8, 10s);
    ASSERT_GE(got.size(), 8U);
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
    pty.receive_until_size(again, 3, 10s);
    ASSERT_GE(again.size(), 3U);
    pty.send(dc3);
    pty.receive_until_quiet(again, 50ms);
    EXPECT_EQ(again[0], 0xA5);
    stop = true;
    EXPECT_TRUE(emulator.join());
    EXPECT_EQ(result.rewinds, 1U);
    EXPECT_GE(result.starts, 3U);
}

TEST(DevicePty, EmulatorSearchesAMainBlockOnRequest) {
    PTY_OR_SKIP(pty);
    auto tape = encode("%\n:1 G90\nN2 X1\n:3 X2\nN4 M02\n", EncodeOptions{.leader = 5, .trailer = 5});
    auto line = open_device(pty.device(), DeviceUse::both);
    std::atomic<bool> stop{false};
    Worker emulator([&] { emulate_reader(*line, tape, EmulatorOptions{.rate = 5000, .stop = &stop}); },
                    [&] { stop = true; });
    for (char c : std::string(":3")) pty.send(static_cast<std::uint8_t>(c));
    std::this_thread::sleep_for(100ms);
    pty.send(dc1);
    std::vector<std::uint8_t> got;
    auto expected = encode(":3 X2\nN4 M02\n", EncodeOptions{.leader = 0, .trailer = 0});
    pty.receive_until_size(got, expected.size(), 5s);
    pty.receive_until_quiet(got, 100ms);
    stop = true;
    EXPECT_TRUE(emulator.join());
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
    PTY_OR_SKIP(pty);
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
    std::atomic<bool> stop{false};
    Worker sender([&] { send_frames(line, frames, SendOptions{.rate = 10000, .stop = &stop}); }, [&] { stop = true; });
    std::this_thread::sleep_for(100ms);
    EXPECT_EQ(line.count.load(), 0U) << "sent with CTS down";
    line.clear = true;
    EXPECT_TRUE(sender.join());
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
    QuietLine line("line");
    std::vector<Frame> frames(10, 0xA5);
    send_frames(line, frames, SendOptions{.rate = 100}, clock);
    ASSERT_EQ(clock.sleeps.size(), 10U);
    for (std::size_t i = 1; i < clock.sleeps.size(); ++i) EXPECT_EQ(clock.sleeps[i] - clock.sleeps[i - 1], 10ms);
}

// A control with even parity on an 8N1 line sends DC3 as 0x93 and DC1 as 0x11 (or 0x91 with odd
// parity): the sender takes them as XOFF and XON all the same.
TEST(DevicePty, SenderTakesXonXoffWithTheParityBitSet) {
    PTY_OR_SKIP(pty);
    auto frames = long_program();
    auto line = open_device(pty.device("baud=115200&flow=xonxoff"), DeviceUse::both);
    SendResult result;
    Worker sender([&] { result = send_frames(*line, frames, SendOptions{.rate = 4000}); }, [&] { pty.close_master(); });
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, 100, 5s);
    pty.send(0x93);
    pty.receive_until_quiet(got, 40ms);
    std::vector<std::uint8_t> more;
    pty.receive(more, 200ms);
    EXPECT_TRUE(more.empty()) << more.size() << " frame(s) after a DC3 with the parity bit set";
    got.insert(got.end(), more.begin(), more.end());
    pty.send(0x91);
    pty.receive_until_size(got, frames.size(), 10s);
    EXPECT_TRUE(sender.join());
    EXPECT_EQ(got, frames);
    EXPECT_EQ(result.pauses, 1U);
}

// A stopped receiver drops the flow codes the control sends in its last moments, as it does before.
TEST(DevicePty, StoppedReceiverDropsFlowCodesInTheGracePeriod) {
    PTY_OR_SKIP(pty);
    auto line = open_device(pty.device(), DeviceUse::read);
    std::atomic<bool> stop{false};
    std::vector<Frame> kept;
    std::atomic<std::size_t> taken{0};
    Worker receiver(
        [&] {
            receive_frames(
                *line, ReceiveOptions{.drop_flow_codes = true, .stop = &stop, .sink = [&](std::span<const Frame> f) {
                                          kept.insert(kept.end(), f.begin(), f.end());
                                          taken += f.size();
                                      }});
        },
        [&] { stop = true; });
    std::vector<std::uint8_t> first = {dc2, 0xA5, 0x0A};
    ASSERT_EQ(::write(pty.master, first.data(), first.size()), 3);
    ASSERT_TRUE(eventually([&] { return taken == 2; })) << taken;  // DC2 dropped, both frames taken while running
    stop = true;
    std::vector<std::uint8_t> answer;
    pty.receive(answer, 1000ms);
    ASSERT_EQ(answer, std::vector<std::uint8_t>{dc3});
    std::vector<std::uint8_t> late = {0xB1, 0x0A, dc4, 0x13, 0x93, dc2};  // '1' LF, punch off, DC3 in both parities
    ASSERT_EQ(::write(pty.master, late.data(), late.size()), 6);
    EXPECT_TRUE(receiver.join());
    EXPECT_EQ(kept, (std::vector<Frame>{0xA5, 0x0A, 0xB1, 0x0A}));
}

// DC1-DC4 are dropped whichever parity the control gives them: 0x13 is DC3 from a control on 8N1
// that sends no parity bit, not a parity error on tape.
TEST(DevicePty, ReceiverDropsFlowCodesInEitherParity) {
    PTY_OR_SKIP(pty);
    auto line = open_device(pty.device(), DeviceUse::read);
    std::vector<Frame> tape = encode("%\nN1 G01 X1\nN2 M02\n%", EncodeOptions{.leader = 3, .trailer = 0});
    std::vector<Frame> sent = {dc2, 0x91};
    sent.insert(sent.end(), tape.begin(), tape.begin() + 8);
    sent.insert(sent.end(), {0x13, 0x93, dc1, 0x94});
    sent.insert(sent.end(), tape.begin() + 8, tape.end());
    EXPECT_EQ(receive_program_sent(pty, *line, sent), tape);
}

// At a low rate the next frame's time is far off: a DC3 that comes meanwhile stops that frame.
TEST(DevicePty, EmulatorSendsNoFrameAfterDc3AtALowRate) {
    PTY_OR_SKIP(pty);
    auto tape = encode("%\nN1 G01 X1 Y2 Z3\nN2 M02\n", EncodeOptions{.leader = 0, .trailer = 0});
    auto line = open_device(pty.device(), DeviceUse::both);
    std::atomic<bool> stop{false};
    Worker emulator([&] { emulate_reader(*line, tape, EmulatorOptions{.rate = 4, .stop = &stop}); },
                    [&] { stop = true; });
    std::vector<std::uint8_t> got;
    for (std::size_t k = 1; k <= 3; ++k) {
        pty.send(dc1);
        pty.receive_until_size(got, k, 2s);  // the first frame goes at once, the next 250 ms later
        std::this_thread::sleep_for(20ms);
        pty.send(dc3);
        std::vector<std::uint8_t> more;
        pty.receive(more, 400ms);
        EXPECT_TRUE(more.empty()) << more.size() << " frame(s) after DC3, stop " << k;
        got.insert(got.end(), more.begin(), more.end());
    }
    stop = true;
    EXPECT_TRUE(emulator.join());
    EXPECT_EQ(got, std::vector<std::uint8_t>(tape.begin(), tape.begin() + static_cast<std::ptrdiff_t>(got.size())));
    EXPECT_EQ(got.size(), 3U);
}

namespace {

// Time that passes only when the code under test waits: in sleep_until, or in a read's time-out.
struct SteppedClock : Clock {
    time_point t{};
    time_point now() override { return t; }
    void sleep_until(time_point until) override {
        if (until > t) t = until;
    }
};

// A line whose other side sends bytes at given moments of a SteppedClock; writes are logged with
// their moment. Sets stop once the clock reaches `end`.
struct ScriptedLine : Transport {
    SteppedClock& clock;
    std::vector<std::pair<std::chrono::milliseconds, std::uint8_t>> incoming;
    std::vector<Clock::time_point> writes;
    std::chrono::milliseconds end;
    std::atomic<bool>& stop;
    ScriptedLine(SteppedClock& c, std::chrono::milliseconds e, std::atomic<bool>& s) : clock(c), end(e), stop(s) {}
    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
        if (clock.t >= Clock::time_point(end)) stop = true;
        if (!incoming.empty() && Clock::time_point(incoming.front().first) <= clock.t + timeout) {
            clock.sleep_until(Clock::time_point(incoming.front().first));
            buffer[0] = incoming.front().second;
            incoming.erase(incoming.begin());
            return {1, false};
        }
        clock.t += timeout;
        return {};
    }
    std::optional<std::pair<std::size_t, std::chrono::milliseconds>> stall;  // after the n-th write, this long
    void write(std::span<const std::uint8_t> b) override {
        writes.insert(writes.end(), b.size(), clock.t);
        if (stall && writes.size() == stall->first) clock.t += stall->second;
    }
    void drain() override {}
    std::string name() const override { return "scripted line"; }
};

}  // namespace

// The injected clock shows the order exactly: a DC3 that arrives while the reader waits for the next
// frame's time is seen before that frame would start.
TEST(DeviceEmulate, Dc3DuringTheWaitForTheNextFrameStopsIt) {
    SteppedClock clock;
    std::atomic<bool> stop{false};
    ScriptedLine line(clock, 2000ms, stop);
    line.incoming = {{10ms, dc1}, {300ms, dc3}, {1000ms, dc1}, {1101ms, dc3}};
    std::vector<Frame> tape(50, 0xA5);
    emulate_reader(line, tape, EmulatorOptions{.rate = 5, .stop = &stop}, clock);
    ASSERT_FALSE(line.writes.empty());
    for (auto w : line.writes) {
        auto at = std::chrono::duration_cast<std::chrono::microseconds>(w.time_since_epoch());
        EXPECT_FALSE(at >= 300ms && at < 1000ms) << "a frame at " << at.count() << " us, after DC3 at 300 ms";
        EXPECT_FALSE(at >= 1101ms) << "a frame at " << at.count() << " us, after DC3 at 1101 ms";
    }
    EXPECT_EQ(line.writes.size(), 3U);  // at 10 and 210 ms, then at 1000 ms (1200 ms would be after DC3)
}

// The process not scheduled for 6 frame times: the reader catches up at no more than twice its speed,
// never sending frames back to back, so a DC3 meanwhile finds at most one frame on its way.
TEST(DeviceEmulate, CatchingUpAfterAStallNeverBursts) {
    SteppedClock clock;
    std::atomic<bool> stop{false};
    ScriptedLine line(clock, 1000ms, stop);
    line.incoming = {{0ms, dc1}};
    line.stall = {{5, 60ms}};
    std::vector<Frame> tape(80, 0xA5);
    emulate_reader(line, tape, EmulatorOptions{.rate = 100, .stop = &stop}, clock);
    ASSERT_EQ(line.writes.size(), 80U);
    for (std::size_t i = 1; i < line.writes.size(); ++i)
        EXPECT_GE(line.writes[i] - line.writes[i - 1], 5ms) << "frames " << i << " and " << i + 1;
    // It does catch up: the 80 frames take 790 ms of reading plus no more than half the stall.
    EXPECT_LE(line.writes.back() - line.writes.front(), 820ms);
}

namespace {

// A 7-bit line, as the UART hands it over: bytes from `wire`, a few at a time, then quiet.
struct SevenBitWire : Transport {
    std::vector<std::uint8_t> wire;
    std::size_t pos = 0;
    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
        if (pos == wire.size()) {
            std::this_thread::sleep_for(timeout);
            return {};
        }
        std::size_t n = std::min({buffer.size(), wire.size() - pos, std::size_t{7}});
        std::copy_n(wire.begin() + static_cast<std::ptrdiff_t>(pos), n, buffer.begin());
        pos += n;
        return {n, false};
    }
    void write(std::span<const std::uint8_t>) override {}
    void drain() override {}
    bool seven_bit() const override { return true; }
    std::string name() const override { return "7E2 line"; }
};

}  // namespace

// A 7E line's UART hands over 7 data bits: the receiver restores track 8 by the tape's parity rule
// (mark: always; space, none: never; even, odd: by the count of holes; blank tape stays blank), so
// the program's end is seen and the image is the tape, under every rule.
TEST(DeviceReceive, SevenBitLineRestoresTrackEight) {
    for (Parity rule : {Parity::even, Parity::odd, Parity::mark, Parity::space, Parity::none}) {
        SCOPED_TRACE(std::string(parity_name(rule)));
        SevenBitWire line;
        std::vector<Frame> tape =
            encode("%\nN1 G01 X1\nN2 M02\n%", EncodeOptions{.parity = rule, .leader = 3, .trailer = 0});
        auto after = encode("N3 X9\n", EncodeOptions{.parity = rule, .leader = 0, .trailer = 0});  // beyond the end
        line.wire = {dc2};
        for (Frame f : tape) line.wire.push_back(f & 0x7F);
        for (Frame f : after) line.wire.push_back(f & 0x7F);
        std::vector<Frame> kept;
        auto result = receive_frames(line, ReceiveOptions{.idle_timeout = 2s,
                                                          .until_program_end = true,
                                                          .parity = rule,
                                                          .drop_flow_codes = true,
                                                          .sink = [&](std::span<const Frame> f) {
                                                              kept.insert(kept.end(), f.begin(), f.end());
                                                          }});
        EXPECT_EQ(result.end, ReceiveResult::End::program_end);
        EXPECT_EQ(kept, tape);
    }
}

// The rules differ on the same 7 bits: 'A' (2 holes) and 'C' (3 holes), DEL (7 holes).
TEST(DeviceReceive, SevenBitLineRestoresTrackEightByTheRuleGiven) {
    const std::vector<std::uint8_t> wire = {'A', 'C', 0x7F, 0x00};
    const std::pair<Parity, std::vector<Frame>> expected[] = {
        {Parity::even, {0x41, 0xC3, 0xFF, 0x00}}, {Parity::odd, {0xC1, 0x43, 0x7F, 0x00}},
        {Parity::mark, {0xC1, 0xC3, 0xFF, 0x00}}, {Parity::space, {0x41, 0x43, 0x7F, 0x00}},
        {Parity::none, {0x41, 0x43, 0x7F, 0x00}},
    };
    for (const auto& [rule, frames] : expected) {
        SCOPED_TRACE(std::string(parity_name(rule)));
        SevenBitWire line;
        line.wire = wire;
        std::vector<Frame> kept;
        receive_frames(line,
                       ReceiveOptions{.idle_timeout = 100ms, .parity = rule, .sink = [&](std::span<const Frame> f) {
                                          kept.insert(kept.end(), f.begin(), f.end());
                                      }});
        EXPECT_EQ(kept, frames);
    }
}

TEST(DeviceReceive, SevenBitLineRefusesEia) {
    struct SevenBitLine : Transport {
        ReadResult read(std::span<std::uint8_t>, std::chrono::milliseconds) override { return {0, true}; }
        void write(std::span<const std::uint8_t>) override {}
        void drain() override {}
        bool seven_bit() const override { return true; }
        std::string name() const override { return "7E2 line"; }
    } line;
    try {
        receive_frames(line, ReceiveOptions{.code = Code::eia});
        FAIL() << "an EIA tape taken from a 7-bit line";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage);
        EXPECT_NE(std::string(e.what()).find("bits=8"), std::string::npos) << e.what();
    }
}

// RTS/CTS asked of a line without modem lines is refused before anything is sent, as it is when the
// device string asks for it.
TEST(DeviceSend, RtsCtsWithoutModemLinesIsRefused) {
    QuietLine line("bare line");
    std::vector<Frame> frames(10, 0xA5);
    try {
        send_frames(line, frames, SendOptions{.flow = Flow::rtscts});
        FAIL() << "sent without flow control";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage);
        EXPECT_EQ(std::string(e.what()), "bare line: flow=rtscts, but this device has no modem lines");
    }
    EXPECT_EQ(line.written, 0U);
    std::atomic<bool> stop{true};
    EXPECT_THROW(emulate_reader(line, frames, EmulatorOptions{.flow = Flow::rtscts, .stop = &stop}), Error);
}

// The emulator's hang-up is a device failure that says how far it came, whether or not it was sending.
TEST(DeviceEmulate, HangUpIsAnErrorWithTheFramesSent) {
    QuietLine line("line", true);
    std::vector<Frame> frames(10, 0xA5);
    try {
        emulate_reader(line, frames, EmulatorOptions{});
        FAIL() << "a hang-up ended the emulation normally";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::io);
        EXPECT_NE(std::string(e.what()).find("hung up; 0 frame(s) sent"), std::string::npos) << e.what();
    }
}

// Rates and time-outs a library user may pass: a rate so low that the time between frames overflows
// a duration is refused, not undefined.
TEST(DeviceSend, RatesOutOfRangeAreRefused) {
    QuietLine line("line");
    std::vector<Frame> frames(3, 0xA5);
    std::atomic<bool> stop{true};  // so that a rate taken by mistake cannot make the test wait
    for (double rate :
         {1e-300, -5.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        EXPECT_THROW(send_frames(line, frames, SendOptions{.rate = rate, .stop = &stop}), Error) << rate;
        EXPECT_THROW(emulate_reader(line, frames, EmulatorOptions{.rate = rate, .stop = &stop}), Error) << rate;
    }
}

namespace {

// A line with modem lines whose other side sends `wire` and then hangs up (or throws, as a line that
// fails does). It logs RTS changes and writes in their order, and counts reads by the state of RTS.
struct ModemLine : Transport, ModemLines {
    std::vector<std::uint8_t> wire;
    std::size_t pos = 0;
    bool fail_at_end = false;
    bool rts = false;
    std::size_t reads_with_rts = 0, reads_without_rts = 0;
    std::vector<std::string> events;
    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds) override {
        ++(rts ? reads_with_rts : reads_without_rts);
        if (pos == wire.size()) {
            if (fail_at_end) throw Error(Errc::io, name() + ": cannot read: Input/output error");
            return {0, true};
        }
        std::size_t n = std::min(buffer.size(), wire.size() - pos);
        std::copy_n(wire.begin() + static_cast<std::ptrdiff_t>(pos), n, buffer.begin());
        pos += n;
        return {n, false};
    }
    void write(std::span<const std::uint8_t> b) override {
        for (auto byte : b) events.push_back("write " + std::to_string(byte));
    }
    void drain() override {}
    ModemLines* modem() override { return this; }
    bool cts() override { return true; }
    void set_rts(bool on) override {
        rts = on;
        events.push_back(on ? "RTS on" : "RTS off");
    }
    std::string name() const override { return "modem line"; }
};

}  // namespace

// RTS says "we accept data": up before the first read, down once the run ends, however it ends.
TEST(DeviceReceive, RtsIsAssertedWhileReceiving) {
    auto program = encode("%\nN1 G01 X1\nN2 M02\n%", EncodeOptions{.leader = 3, .trailer = 0});
    for (auto end : {ReceiveResult::End::program_end, ReceiveResult::End::hangup}) {
        ModemLine line;
        line.wire = program;
        std::vector<Frame> kept;
        auto result = receive_frames(line, ReceiveOptions{.until_program_end = end == ReceiveResult::End::program_end,
                                                          .sink = [&](std::span<const Frame> f) {
                                                              kept.insert(kept.end(), f.begin(), f.end());
                                                          }});
        EXPECT_EQ(result.end, end);
        EXPECT_EQ(kept, program);
        EXPECT_EQ(line.events, (std::vector<std::string>{"RTS on", "RTS off"}));
        EXPECT_GT(line.reads_with_rts, 0U);
        EXPECT_EQ(line.reads_without_rts, 0U) << "read with RTS down";
    }
}

TEST(DeviceReceive, RtsIsDroppedWhenTheLineFails) {
    ModemLine line;
    line.wire = {0xA5, 0x0A};
    line.fail_at_end = true;
    EXPECT_THROW(receive_frames(line, ReceiveOptions{}), Error);
    EXPECT_EQ(line.events, (std::vector<std::string>{"RTS on", "RTS off"}));
    EXPECT_FALSE(line.rts);
}

// Stopped, the receiver asks the other side to stop both ways, RTS down and DC3, and still takes what
// comes in the next moments (with RTS down: the reads that follow are the grace period's).
TEST(DeviceReceive, StoppedReceiverDropsRtsAndSendsDc3) {
    SteppedClock clock;
    ModemLine line;
    line.wire = {0xA5, 0x0A};
    std::atomic<bool> stop{true};
    std::vector<Frame> kept;
    receive_frames(
        line,
        ReceiveOptions{.stop = &stop,
                       .sink = [&](std::span<const Frame> f) { kept.insert(kept.end(), f.begin(), f.end()); }},
        clock);
    EXPECT_EQ(line.events, (std::vector<std::string>{"RTS on", "RTS off", "write " + std::to_string(dc3)}));
    EXPECT_EQ(kept, (std::vector<Frame>{0xA5, 0x0A}));
    EXPECT_FALSE(line.rts);
}

// A mark-parity tape (DEC-era ASCII): with --parity mark the reader sees its '%' and M02 and rewinds
// at the program's end; read as even parity they are parity errors and the whole tape runs out.
TEST(DeviceEmulate, TheParityRuleFindsTheProgramEnd) {
    auto tape = encode("%\nN1 G01 X1\nN2 M02\n", EncodeOptions{.parity = Parity::mark, .leader = 5, .trailer = 5});
    for (Parity rule : {Parity::mark, Parity::even}) {
        SCOPED_TRACE(std::string(parity_name(rule)));
        SteppedClock clock;
        std::atomic<bool> stop{false};
        ScriptedLine line(clock, 5000ms, stop);
        line.incoming = {{10ms, dc1}};
        auto result = emulate_reader(line, tape, EmulatorOptions{.rate = 100, .parity = rule, .stop = &stop}, clock);
        if (rule == Parity::mark) {
            EXPECT_EQ(result.rewinds, 1U);
            EXPECT_EQ(line.writes.size(), tape.size() - 10) << "leader skipped, stopped after M02's block";
        } else {
            EXPECT_EQ(result.rewinds, 0U);
            EXPECT_EQ(line.writes.size(), tape.size() - 5) << "leader skipped, on to the end of the tape";
        }
    }
}

// Over a real line (8 bits, frames as on tape): a mark-parity program ends at its '%' under its rule.
TEST(DevicePty, ReceiverEndsAMarkParityProgramByItsRule) {
    PTY_OR_SKIP(pty);
    auto line = open_device(pty.device("baud=115200&flow=none"), DeviceUse::read);
    auto tape = encode("%\nN1 G01 X1\nN2 M02\n%", EncodeOptions{.parity = Parity::mark, .leader = 3, .trailer = 0});
    auto after = encode("N3 X9\n", EncodeOptions{.parity = Parity::mark, .leader = 0, .trailer = 0});
    std::vector<Frame> sent = tape;
    sent.insert(sent.end(), after.begin(), after.end());
    std::vector<Frame> kept;
    ReceiveResult result;
    Worker receiver(
        [&] {
            result = receive_frames(*line, ReceiveOptions{.idle_timeout = 3s,
                                                          .until_program_end = true,
                                                          .parity = Parity::mark,
                                                          .sink = [&](std::span<const Frame> f) {
                                                              kept.insert(kept.end(), f.begin(), f.end());
                                                          }});
        },
        [&] { pty.close_master(); });
    ASSERT_EQ(::write(pty.master, sent.data(), sent.size()), static_cast<ssize_t>(sent.size()));
    EXPECT_TRUE(receiver.join());
    EXPECT_EQ(result.end, ReceiveResult::End::program_end);
    EXPECT_EQ(kept, tape);
}
