// One conformance suite for the three adapter backends: adapter: (CDC, COBS on a pseudo-terminal),
// usb: (libusb, vendor bulk endpoints) and hid: (hidapi on hidraw). Each runs the same cases against
// the firmware core (fake::Adapter); for usb: and hid: the kernel's usbfs and hidraw are umockdev's,
// the only double. The library is driven in this process, and the tape CLI as a child process with
// umockdev's preload library, as a user would run it. A fourth time, link pico, the cases that apply
// run against the RP2040 firmware on an emulated Pico (tests/rp2040), its CDC port on a pseudo-terminal:
// those injecting link faults, unplugging, row flags, reading backwards or a control's own lines do not
// (the emulated board has none of these), and its serial string is its flash id.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "device/adapter_session.hpp"
#include "fake_adapter/fake_adapter.hpp"
#include "process_util.hpp"
#include "rp2040/pico_util.hpp"
#include "tape/adapter.hpp"
#include "tape/device.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace std::chrono_literals;
using fake::Link;

namespace {

std::vector<std::uint8_t> pattern(std::size_t n, unsigned salt = 0) {
    std::vector<std::uint8_t> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<std::uint8_t>((i * 37 + i / 251 + salt) & 0xFF);
    return t;
}

struct ReadRun {
    std::vector<std::uint8_t> frames;
    std::string error;  ///< the Error's message, when reading ended in one
    bool ended = false;
};

// Reads until the end of the tape, an error, or the deadline.
ReadRun read_all(tape::Transport& t, std::chrono::seconds limit = 30s) {
    ReadRun r;
    auto end = std::chrono::steady_clock::now() + limit;
    std::uint8_t buf[4096];
    try {
        while (std::chrono::steady_clock::now() < end) {
            auto got = t.read(buf, 100ms);
            r.frames.insert(r.frames.end(), buf, buf + got.count);
            if (got.end) {
                r.ended = true;
                break;
            }
        }
    } catch (const tape::Error& e) {
        r.error = e.what();
    }
    return r;
}

// Reads t to the tape's end: expected, every frame once, and no error.
void expect_reads(tape::Transport& t, const std::vector<std::uint8_t>& expected) {
    ReadRun r = read_all(t);
    EXPECT_EQ(r.error, "");
    EXPECT_TRUE(r.ended);
    EXPECT_EQ(r.frames, expected);
}

// What a case runs against: fake::Adapter, or for Link::pico the emulated Pico with the reader's tape, the
// punch, and the control when the options ask for one.
class Dut {
public:
    explicit Dut(const fake::Options& o) {
        if (o.link != Link::pico) {
            fake_ = std::make_unique<fake::Adapter>(o);
            return;
        }
        std::vector<std::string> args = {"--punch"};
        if (!o.tape.empty()) {
            std::ofstream(dir_.file("tape.bin"), std::ios::binary)
                .write(reinterpret_cast<const char*>(o.tape.data()), static_cast<std::streamsize>(o.tape.size()));
            args.insert(args.end(), {"--tape", dir_.file("tape.bin")});
        }
        if (o.sim.control) args.push_back("--control");
        pico_ = std::make_unique<pico::Pico>(dir_, args);
        if (pico_->device.empty()) throw std::runtime_error("the emulated Pico did not come up: " + pico_->err());
    }
    const std::string& device() const { return fake_ ? fake_->device() : pico_->device; }
    std::vector<std::uint8_t> punched() const { return fake_ ? fake_->punched() : pico_->bytes("punched.bin"); }
    std::vector<std::uint8_t> control_taken() const {
        return fake_ ? fake_->control_taken() : pico_->bytes("taken.bin");
    }
    std::string control_stats() const { return fake_ ? fake_->control_stats() : ""; }
    std::vector<std::string> unexpected() const { return fake_ ? fake_->unexpected() : std::vector<std::string>{}; }
    void send_garbage() { fake_->send_garbage(); }

private:
    TempDir dir_;
    std::unique_ptr<fake::Adapter> fake_;
    std::unique_ptr<pico::Pico> pico_;
};

// A case that does not apply to the emulated Pico says why.
#define NOT_ON_PICO(why) \
    if (GetParam() == Link::pico) GTEST_SKIP() << "not on the emulated Pico: " << why

class AdapterBackend : public ::testing::TestWithParam<Link> {
protected:
    void SetUp() override {
        if (GetParam() == Link::pico) {
            std::string why = pico::unavailable();
            if (!why.empty()) GTEST_SKIP() << why;
        } else if (GetParam() != Link::cdc) {
            std::string why = fake::umockdev_unavailable();
            if (!why.empty()) GTEST_SKIP() << why;
        }
    }
    fake::Options options(std::vector<std::uint8_t> tape = {}, const std::string& serial = "") {
        fake::Options o;
        o.link = GetParam();
        o.serial =
            serial.empty() ? std::string("T-") + fake::link_name(GetParam()) + "-" + std::to_string(++made_) : serial;
        o.tape = std::move(tape);
        return o;
    }
    // Every request the host made was one a host has business making.
    static void expect_clean(const Dut& a) {
        for (const auto& u : a.unexpected()) ADD_FAILURE() << "unexpected request: " << u;
    }
    // Waits until the simulated control has taken n frames, or until the deadline (the test then sees
    // fewer): tape emulate feeds it at its own pace from another process.
    static void wait_taken(const Dut& a, std::size_t n, std::chrono::seconds deadline) {
        auto end = std::chrono::steady_clock::now() + deadline;
        while (a.control_taken().size() < n && std::chrono::steady_clock::now() < end)
            std::this_thread::sleep_for(20ms);
    }
    int made_ = 0;
};

// The tape processes a test starts talk to the fake adapter through umockdev's preload, for the
// test's length.
struct ChildPreload {
    ChildPreload() { ::setenv("LD_PRELOAD", fake::child_preload().c_str(), 1); }
    ~ChildPreload() { ::unsetenv("LD_PRELOAD"); }
    ChildPreload(const ChildPreload&) = delete;
    ChildPreload& operator=(const ChildPreload&) = delete;
};

TEST_P(AdapterBackend, AnswersInfoWithItsSerialAndCapabilities) {
    NOT_ON_PICO("its serial string is its flash id (AdapterPico.InfoAndSelftestThroughTheCli)");
    Dut a(options({}, "INFO-" + std::string(fake::link_name(GetParam()))));
    tape::AdapterInfo info = tape::adapter_info(a.device());
    EXPECT_EQ(info.serial, "INFO-" + std::string(fake::link_name(GetParam())));
    EXPECT_TRUE(info.reader);
    EXPECT_TRUE(info.punch);
    EXPECT_EQ(info.max_read_rate, 1500u);
    EXPECT_EQ(info.tracks, (std::vector<int>{5, 6, 7, 8}));
    expect_clean(a);
}

TEST_P(AdapterBackend, ReadsATapeWholeEveryFrameOnce) {
    auto tape = pattern(9000);
    Dut a(options(tape));
    auto t = tape::open_device(a.device(), tape::DeviceUse::read);
    expect_reads(*t, tape);
    expect_clean(a);
}

// From the tape's end, direction=reverse: the rows come last first, and the rows the adapter flags are
// named in runs of alike ones, counted in the order they came.
TEST_P(AdapterBackend, ReadsBackwardsAndNamesTheRowsTheReaderDoubts) {
    NOT_ON_PICO("the board neither reads backwards nor flags rows");
    auto tape = pattern(3000, 9);
    auto o = options(tape);
    o.sim.head_at_end = true;
    o.sim.row_flags = {
        {10, tapefw::row_flag::no_sprocket}, {11, tapefw::row_flag::no_sprocket}, {2000, tapefw::row_flag::marginal}};
    Dut a(o);
    auto t = tape::open_device(a.device() + "&direction=reverse", tape::DeviceUse::read);
    EXPECT_TRUE(t->backwards());
    expect_reads(*t, std::vector<std::uint8_t>(tape.rbegin(), tape.rend()));
    auto doubts = t->take_doubts();
    ASSERT_EQ(doubts.runs.size(), 2u);
    EXPECT_EQ(doubts.runs[0].first, 1000u);  // tape frame 2001, the 1000th to come
    EXPECT_EQ(doubts.runs[0].last, 1000u);
    EXPECT_EQ(doubts.runs[0].what, "a track's level was near its threshold");
    EXPECT_EQ(doubts.runs[1].first, 2989u);
    EXPECT_EQ(doubts.runs[1].last, 2990u);
    EXPECT_EQ(doubts.runs[1].what, "read without a sprocket hole (sampled by time)");
    EXPECT_EQ(doubts.unkept, 0u);
    EXPECT_TRUE(t->take_doubts().runs.empty());
    expect_clean(a);
}

// A tape flagged throughout, every row unlike the one before: the first runs are kept, the rest only
// counted, so that the host's memory stays bounded however doubtful the tape.
TEST(AdapterDoubts, BeyondTheRunsKeptDoubtfulRowsAreCounted) {
    const std::size_t rows = tape::adapter::Session::max_doubts + 2500;
    std::vector<std::uint8_t> tape(rows, 0x55);
    fake::Options o{.link = Link::cdc, .serial = "FLAGGED"};
    o.tape = tape;
    for (std::uint64_t f = 0; f < rows; ++f)
        o.sim.row_flags.emplace_back(f, f % 2 ? tapefw::row_flag::timing : tapefw::row_flag::marginal);
    Dut a(o);
    auto t = tape::open_device(a.device(), tape::DeviceUse::read);
    expect_reads(*t, tape);
    auto doubts = t->take_doubts();
    ASSERT_EQ(doubts.runs.size(), tape::adapter::Session::max_doubts);
    EXPECT_EQ(doubts.runs.back().first, tape::adapter::Session::max_doubts);
    EXPECT_EQ(doubts.unkept, 2500u);
    for (const auto& u : a.unexpected()) ADD_FAILURE() << "unexpected request: " << u;
}

TEST_P(AdapterBackend, RecoversADroppedADuplicatedAndADamagedPacket) {
    NOT_ON_PICO("no fault to inject on its link");
    auto tape = pattern(6000, 1);
    auto o = options(tape);
    o.faults.drop_rows_packet = 3;
    o.faults.duplicate_rows_packet = 6;
    o.faults.corrupt_rows_packet = 9;
    Dut a(o);
    auto t = tape::open_device(a.device(), tape::DeviceUse::read);
    expect_reads(*t, tape);
    auto notes = t->take_notes();
    // The dropped and the damaged packet's frames came again: in one range, when one RESEND got both.
    EXPECT_GE(notes.size(), 1u);
    expect_clean(a);
}

TEST_P(AdapterBackend, GarbageOnTheLineIsSkippedWithoutReplugging) {
    NOT_ON_PICO("no noise to inject on its link");
    auto tape = pattern(12000, 2);
    Dut a(options(tape));
    auto t = tape::open_device(a.device(), tape::DeviceUse::read);
    std::thread noise([&a] {
        for (int i = 0; i < 10; ++i) {
            std::this_thread::sleep_for(30ms);
            a.send_garbage();
        }
    });
    ReadRun r = read_all(*t);
    noise.join();
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.frames, tape);
    expect_clean(a);
}

TEST_P(AdapterBackend, FramesLostForGoodAreReportedWithTheirRange) {
    NOT_ON_PICO("no fault to inject on its link");
    auto tape = pattern(6000, 3);
    auto o = options(tape);
    o.faults.drop_rows_packet = 4;
    o.faults.drop_times = 1000000;
    Dut a(o);
    auto t = tape::open_device(a.device(), tape::DeviceUse::read);
    auto start = std::chrono::steady_clock::now();
    ReadRun r = read_all(*t);
    ASSERT_NE(r.error, "");
    EXPECT_NE(r.error.find("frame " + std::to_string(r.frames.size() + 1)), std::string::npos) << r.error;
    EXPECT_LT(std::chrono::steady_clock::now() - start, 10s);
    // Every frame before the lost packet is kept, none after it.
    EXPECT_EQ(r.frames, std::vector<std::uint8_t>(tape.begin(), tape.begin() + static_cast<long>(r.frames.size())));
    expect_clean(a);
}

TEST_P(AdapterBackend, UnpluggedWhileReadingKeepsEveryFrameBeforeAndSaysSo) {
    NOT_ON_PICO("it cannot be unplugged");
    auto tape = pattern(20000, 4);
    auto o = options(tape);
    o.unplug_after = 3000;
    Dut a(o);
    auto t = tape::open_device(a.device(), tape::DeviceUse::read);
    ReadRun r = read_all(*t);
    EXPECT_NE(r.error.find("gone"), std::string::npos) << r.error;
    EXPECT_GT(r.frames.size(), 0u);
    EXPECT_LE(r.frames.size(), 3000u + 64);
    EXPECT_EQ(r.frames, std::vector<std::uint8_t>(tape.begin(), tape.begin() + static_cast<long>(r.frames.size())));
    expect_clean(a);
}

TEST_P(AdapterBackend, PunchesEveryRowInOrder) {
    Dut a(options());
    auto rows = pattern(1200, 5);
    {
        auto t = tape::open_device(a.device(), tape::DeviceUse::write);
        t->write(rows);
        t->drain();
    }
    EXPECT_EQ(a.punched(), rows);
    expect_clean(a);
}

TEST_P(AdapterBackend, ChoosesTheAdapterBySerialAndNamesTheOthersWhenNoneMatches) {
    NOT_ON_PICO("its serial string is its flash id");
    Dut first(options(pattern(10), "SERIAL-A"));
    Dut second(options(pattern(10), "SERIAL-B"));
    {
        auto t = tape::open_device(second.device(), tape::DeviceUse::read);
        EXPECT_EQ(read_all(*t).frames, pattern(10));
    }
    std::string wrong = second.device().substr(0, second.device().find("?serial=")) + "?serial=SERIAL-X";
    try {
        tape::open_device(wrong, tape::DeviceUse::read);
        ADD_FAILURE() << "opened " << wrong;
    } catch (const tape::Error& e) {
        EXPECT_EQ(e.code(), tape::Errc::io);
        EXPECT_NE(std::string(e.what()).find("SERIAL-X"), std::string::npos) << e.what();
        // A port names one adapter; USB lists every one attached with the ids.
        if (GetParam() != Link::cdc) {
            EXPECT_NE(std::string(e.what()).find("SERIAL-A"), std::string::npos) << e.what();
        }
        EXPECT_NE(std::string(e.what()).find("SERIAL-B"), std::string::npos) << e.what();
    }
    expect_clean(first);
    expect_clean(second);
}

TEST_P(AdapterBackend, RefusesAnAdapterSpeakingAnotherProtocolVersion) {
    NOT_ON_PICO("its firmware speaks the one protocol version");
    auto o = options();
    o.faults.protocol = 99;
    Dut a(o);
    try {
        tape::adapter_info(a.device());
        ADD_FAILURE() << "no refusal";
    } catch (const tape::Error& e) {
        EXPECT_EQ(e.code(), tape::Errc::io);
        EXPECT_NE(std::string(e.what()).find("protocol version 99"), std::string::npos) << e.what();
    }
    expect_clean(a);
}

TEST_P(AdapterBackend, SelfTestEchoesEveryPacketUnchanged) {
    Dut a(options());
    // The emulated Pico runs at real time at most (the fake adapter at 20 times), behind two processes.
    tape::AdapterSelftest s = tape::adapter_selftest(a.device(), GetParam() == Link::pico ? 3000ms : 300ms, 7);
    EXPECT_GT(s.packets, 10u);
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.bad_in, 0u);
    EXPECT_EQ(s.bad_out, 0u);
    expect_clean(a);
}

// The CLI, a real process, reading through the backend: exit 0 and the tape on disk; unplugged, exit 3,
// with every frame read before on disk.
TEST_P(AdapterBackend, TapeReadThroughTheCliEndsWellOrWithExitThreeAndTheFramesOnDisk) {
    TempDir dir;
    auto tape = pattern(5000, 6);
    // The child sees the umockdev devices through the same preload library.
    ChildPreload preload;
    {
        Dut a(options(tape));
        Process read({"read", a.device(), "-o", dir.file("whole.ptp")}, dir);
        EXPECT_EQ(read.wait(60s), 0) << read.err();
        auto got = read_text(dir.file("whole.ptp"));
        EXPECT_EQ(std::vector<std::uint8_t>(got.begin(), got.end()), tape);
        expect_clean(a);
    }
    if (GetParam() == Link::pico) return;  // it cannot be unplugged
    {
        auto o = options(tape);
        o.unplug_after = 2000;
        Dut a(o);
        Process read({"read", a.device(), "-o", dir.file("part.ptp")}, dir);
        EXPECT_EQ(read.wait(60s), 3) << read.err();
        EXPECT_NE(read.err().find("gone"), std::string::npos) << read.err();
        auto got = read_text(dir.file("part.ptp"));
        EXPECT_GT(got.size(), 0u);
        EXPECT_EQ(std::vector<std::uint8_t>(got.begin(), got.end()),
                  std::vector<std::uint8_t>(tape.begin(), tape.begin() + static_cast<long>(got.size())));
        expect_clean(a);
    }
}

// tape emulate through the backend, a real process: the control reads the program, stops at its end
// (M30), and reads it again from its '%' stop; its random stops see at most one frame more.
TEST_P(AdapterBackend, TapeEmulateFeedsTheControlAndGivesTheProgramAgainFromItsPercentStop) {
    NOT_ON_PICO(
        "the emulated control does not stop at a program's end "
        "(AdapterPico.TapeEmulateStopsWithinAFrameOfTheControlsStop)");
    TempDir dir;
    auto frames = tape::encode("%\nN1 G01 X10 F100\nN2 X20 Y-5\nN3 G00 Z50\nN4 M30\n", {});
    write_frames(dir.file("p.ptp"), frames);
    auto first = std::find_if(frames.begin(), frames.end(), [](tape::Frame f) { return f != tape::blank_frame; });
    // Up to the line feed ending the M30 block, the fifth of the program (even parity: LF is 0x0A).
    auto past_m30 = std::find(first, frames.end(), tape::Frame{0x0A});
    for (int lf = 0; lf < 4; ++lf) past_m30 = std::find(past_m30 + 1, frames.end(), tape::Frame{0x0A});
    std::vector<std::uint8_t> program(first, past_m30 + 1);
    auto o = options();
    o.sim.control = tapesim::ControlOptions{.stops = 4, .pause_min_us = 2000, .pause_max_us = 4000};
    Dut a(o);
    ChildPreload preload;
    Process emulate({"emulate", dir.file("p.ptp"), a.device()}, dir);
    wait_taken(a, 2 * program.size(), 30s);
    emulate.interrupt();
    EXPECT_EQ(emulate.wait(20s), 0) << emulate.err();
    auto taken = a.control_taken();
    ASSERT_GE(taken.size(), 2 * program.size()) << emulate.err();
    EXPECT_EQ(std::vector<std::uint8_t>(taken.begin(), taken.begin() + static_cast<long>(program.size())), program);
    EXPECT_EQ(std::vector<std::uint8_t>(taken.begin() + static_cast<long>(program.size()),
                                        taken.begin() + static_cast<long>(2 * program.size())),
              program);
    EXPECT_NE(emulate.err().find("end of program"), std::string::npos) << emulate.err();
    EXPECT_NE(emulate.err().find("rewound to the '%' stop"), std::string::npos) << emulate.err();
    auto stats = nlohmann::json::parse(a.control_stats());
    for (unsigned after : stats["frames_after_stop"]) EXPECT_LE(after, 1u);
    expect_clean(a);
}

// The control's own lines: its direction line reads backwards from where the tape stands, its rewind
// line rewinds to the '%' stop.
TEST_P(AdapterBackend, TapeEmulateFollowsTheControlsDirectionAndRewindLines) {
    NOT_ON_PICO("the emulated control has no direction or rewind line");
    TempDir dir;
    auto frames = tape::encode("%\nN1 G01 X10 F100\nN2 X20 Y-5\nN3 G00 Z50\nN4 X0\nN5 Y0\n", {});
    write_frames(dir.file("p.ptp"), frames);
    std::vector<std::uint8_t> program(
        std::find_if(frames.begin(), frames.end(), [](tape::Frame f) { return f != tape::blank_frame; }), frames.end());
    auto o = options();
    o.sim.control = tapesim::ControlOptions{.rewind_after = 70, .reverse_after = 40, .reverse_frames = 10};
    Dut a(o);
    ChildPreload preload;
    Process emulate({"emulate", dir.file("p.ptp"), a.device()}, dir);
    wait_taken(a, 100, 30s);
    emulate.interrupt();
    EXPECT_EQ(emulate.wait(20s), 0) << emulate.err();
    auto taken = a.control_taken();
    ASSERT_GE(taken.size(), 100u) << emulate.err();
    // Each stop lets one frame more through (the braking distance): 40 forwards and one, 10 backwards
    // and one (frames 40 down to 30), forwards again from frame 30 until 70 are taken and one, then
    // from the '%' stop.
    std::vector<std::uint8_t> expected(program.begin(), program.begin() + 41);
    for (int i = 40; i >= 30; --i) expected.push_back(program[static_cast<std::size_t>(i)]);
    expected.insert(expected.end(), program.begin() + 30, program.begin() + 49);
    expected.insert(expected.end(), program.begin(), program.begin() + 29);
    EXPECT_EQ(std::vector<std::uint8_t>(taken.begin(), taken.begin() + 100), expected);
    EXPECT_NE(emulate.err().find("reading backwards"), std::string::npos) << emulate.err();
    EXPECT_NE(emulate.err().find("the control's rewind line"), std::string::npos) << emulate.err();
    expect_clean(a);
}

// A host gone while emulating: the adapter's watchdog stops the frames, and the next host hears of it.
TEST_P(AdapterBackend, AnEmulationTheWatchdogEndedIsToldToTheNextHost) {
    auto o = options();
    o.sim.control = tapesim::ControlOptions{};
    Dut a(o);
    std::vector<std::uint8_t> frames(5000, 0x55);
    {
        tape::adapter::Session s(tape::adapter::open_pipe(a.device()));
        s.start_emulation();
        auto end = std::chrono::steady_clock::now() + 10s;
        while (s.taken().taken < 100 && std::chrono::steady_clock::now() < end) {
            s.offer(s.taken().taken, {frames.data(), frames.size() - s.taken().taken});
            s.pump_emulation(10ms);
        }
        ASSERT_GE(s.taken().taken, 100u);
        // Silent now for longer than the watchdog (500 ms on the adapter's clock, 20 times real time).
        std::this_thread::sleep_for(1500ms);
    }
    std::size_t taken = a.control_taken().size();
    tape::adapter::Session next(tape::adapter::open_pipe(a.device()));
    ASSERT_TRUE(next.orphaned());
    EXPECT_TRUE(next.orphaned()->bits & tapefw::status::watchdog);
    EXPECT_EQ(next.orphaned()->frame, taken);
    EXPECT_LT(taken, frames.size());
    expect_clean(a);
}

// Two adapters at once, one on its vendor interface and one on HID: tape devices (a real process) finds
// both in sysfs, told apart by serial, under the device strings that reach them, and --probe asks each
// for its capabilities through them. (The CDC layout, a tty in sysfs, is the devices-list CLI case's.)
TEST(AdapterDevices, TapeDevicesListsUsbAndHidAdaptersBySerialAndProbesThem) {
    std::string why = fake::umockdev_unavailable();
    if (!why.empty()) GTEST_SKIP() << why;
    TempDir dir;
    fake::Adapter bulk(fake::Options{.link = Link::usb, .serial = "TP-BULK-7"});
    fake::Adapter hid(fake::Options{.link = Link::hid, .serial = "TP-HID-9"});
    ChildPreload preload;
    Process devices({"devices", "--probe"}, dir);
    EXPECT_EQ(devices.wait(60s), 0) << devices.err();
    std::string out = read_text(dir.file("stdout"));
    EXPECT_EQ(bulk.device(), "usb:1209:0001?serial=TP-BULK-7");
    EXPECT_EQ(hid.device(), "hid:1209:0001?serial=TP-HID-9");
    for (auto [a, serial] : {std::pair{&bulk, "TP-BULK-7"}, std::pair{&hid, "TP-HID-9"}}) {
        std::string line = a->device() + "\t1209:0001 serial " + serial + "\ttape project tape adapter\n";
        auto at = out.find(line);
        ASSERT_NE(at, std::string::npos) << "no line " << line << "in:\n" << out;
        EXPECT_EQ(out.compare(at + line.size(), 20, "\tprotocol 1, firmwar"), 0) << out;
        for (const auto& u : a->unexpected()) ADD_FAILURE() << "unexpected request: " << u;
    }
}

INSTANTIATE_TEST_SUITE_P(Links, AdapterBackend, ::testing::Values(Link::cdc, Link::usb, Link::hid, Link::pico),
                         [](const auto& info) { return std::string(fake::link_name(info.param)); });

}  // namespace
