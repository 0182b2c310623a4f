// The adapter: backend end to end: the real tape-adapter-sim process (the firmware core with a
// simulated reader and punch) on a real pseudo-terminal, the library's Transport and the tape CLI on
// the other side, with every fault the simulator can inject.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <thread>

#include "bagit_reader.hpp"
#include "process_util.hpp"
#include "tape/adapter.hpp"
#include "tape/device.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace std::chrono_literals;

namespace {

// tape-adapter-sim running on its own pseudo-terminal; killed (SIGTERM, then SIGKILL) at the end.
class Sim {
public:
    Sim(const TempDir& dir, std::vector<std::string> args) : dir_(dir) {
        pid_ = spawn_to_files(TAPE_ADAPTER_SIM, args, dir.file("sim.out"), dir.file("sim.err"));
        // It prints its device string once the pseudo-terminal is there.
        auto end = std::chrono::steady_clock::now() + 10s;
        while (pid_ > 0 && std::chrono::steady_clock::now() < end) {
            std::string out = read_text(dir.file("sim.out"));
            if (out.find('\n') != std::string::npos) {
                device = out.substr(0, out.find('\n'));
                break;
            }
            std::this_thread::sleep_for(5ms);
        }
    }
    ~Sim() { stop(); }
    Sim(const Sim&) = delete;
    Sim& operator=(const Sim&) = delete;

    /// Ends it; its exit status (-1 when it had to be killed).
    int stop() {
        if (pid_ <= 0) return status_;
        ::kill(pid_, SIGTERM);
        auto status = wait_for_exit(pid_, 5s);
        if (!status) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
        pid_ = -1;
        return status_ = status && WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
    }
    std::string err() const { return read_text(dir_.file("sim.err")); }

    std::string device;  ///< "adapter:/dev/pts/N", empty when it did not start

private:
    const TempDir& dir_;
    pid_t pid_ = -1;
    int status_ = -1;
};

#define SIM_OR_SKIP(name, dir, ...)                                                   \
    Sim name(dir, __VA_ARGS__);                                                       \
    if (name.device.empty()) {                                                        \
        std::string why = name.err();                                                 \
        if (why.find("no pseudo-terminal") != std::string::npos) GTEST_SKIP() << why; \
        FAIL() << "tape-adapter-sim did not start: " << why;                          \
    }

std::vector<std::uint8_t> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

// A tape of n frames, every value in it, written as a raw image.
std::string write_tape(const TempDir& dir, std::size_t n, std::vector<std::uint8_t>* frames = nullptr) {
    std::string data(n, '\0');
    for (std::size_t i = 0; i < n; ++i) data[i] = static_cast<char>((i * 131 + i / 977) & 0xFF);
    if (frames) *frames = bytes_of(data);
    std::ofstream(dir.file("in.ptp"), std::ios::binary) << data;
    return dir.file("in.ptp");
}

struct ReadOutcome {
    std::vector<std::uint8_t> rows;
    std::string error;  ///< what the read threw, empty when it ended normally
    std::chrono::steady_clock::duration took{};
};

// Reads through t into rows until they number want, the tape ends or the deadline passes.
void read_until(tape::Transport& t, std::vector<std::uint8_t>& rows, std::chrono::steady_clock::time_point deadline,
                std::size_t want = SIZE_MAX) {
    std::uint8_t buf[4096];
    while (rows.size() < want && std::chrono::steady_clock::now() < deadline) {
        auto got = t.read(buf, 100ms);
        rows.insert(rows.end(), buf, buf + got.count);
        if (got.end) break;
    }
}

// Reads through the library's Transport, as tape read does, until the end, an error or the deadline.
ReadOutcome read_all(const std::string& device, std::chrono::seconds limit = 60s) {
    ReadOutcome r;
    auto start = std::chrono::steady_clock::now();
    try {
        auto t = tape::open_device(device, tape::DeviceUse::read);
        read_until(*t, r.rows, start + limit);
    } catch (const tape::Error& e) {
        r.error = e.what();
    }
    r.took = std::chrono::steady_clock::now() - start;
    return r;
}

}  // namespace

TEST(AdapterCdc, ReadsATapeWholeAtTheReadersSpeed) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 3000, &frames);
    SIM_OR_SKIP(sim, dir, {"--reader", in});
    auto r = read_all(sim.device);
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.rows, frames);
    // 3000 frames at 1500 frames/s: 2 s, and not much more.
    double s = std::chrono::duration<double>(r.took).count();
    EXPECT_GT(s, 1.9);
    EXPECT_LT(s, 4.0);
}

TEST(AdapterCdc, RecoversADroppedADuplicatedAndADamagedPacket) {
    for (std::vector<std::string> fault :
         std::vector<std::vector<std::string>>{{"--drop-packet", "5"},
                                               {"--duplicate-packet", "5"},
                                               {"--corrupt-packet", "5"},
                                               {"--corrupt-packet", "5", "--corrupt-times", "3"},
                                               {"--drop-packet", "5", "--drop-times", "3"},
                                               {"--garbage-every", "7", "--stats"}}) {
        TempDir dir;
        std::vector<std::uint8_t> frames;
        std::string in = write_tape(dir, 2000, &frames);
        std::vector<std::string> args = {"--reader", in, "--speed", "4"};
        args.insert(args.end(), fault.begin(), fault.end());
        SIM_OR_SKIP(sim, dir, args);
        auto r = read_all(sim.device);
        EXPECT_EQ(r.error, "") << fault[0];
        EXPECT_EQ(r.rows.size(), frames.size()) << fault[0];
        EXPECT_TRUE(r.rows == frames) << fault[0] << ": the frame counter lets no row be lost or doubled";
        if (fault[0] == "--garbage-every") {
            // Noise and cut packets, in turn, before every 7th ROWS packet: recovered without a replug.
            sim.stop();
            auto at = sim.err().find("desyncs=");
            ASSERT_NE(at, std::string::npos) << sim.err();
            EXPECT_GE(std::stoull(sim.err().substr(at + 8)), 5u) << sim.err();
        }
    }
}

TEST(AdapterCdc, FramesLostForGoodAreReportedWithTheirRangeWithinASecond) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 3000, &frames);
    SIM_OR_SKIP(sim, dir, {"--reader", in, "--drop-packet", "4", "--drop-times", "1000000"});
    auto r = read_all(sim.device);
    // The rows before the lost packet are kept, and the message names the rows lost.
    ASSERT_GT(r.rows.size(), 0u);
    EXPECT_TRUE(std::equal(r.rows.begin(), r.rows.end(), frames.begin()));
    std::string first = std::to_string(r.rows.size() + 1);
    std::string head = "frame " + first + ": frames " + first + "-";
    auto at = r.error.find(head);
    ASSERT_NE(at, std::string::npos) << r.error;
    std::uint64_t last = std::stoull(r.error.substr(at + head.size()));
    EXPECT_GE(last, r.rows.size() + 1);
    EXPECT_LE(last, r.rows.size() + 51) << "one packet holds 51 rows at most";
    EXPECT_NE(r.error.find(" lost: not received after 5 requests to resend"), std::string::npos) << r.error;
    // The fourth packet leaves within 0.1 s of the start, the loss is seen at the next (10 ms later)
    // and reported after 5 requests 150 ms apart: within a second of the loss.
    EXPECT_LT(std::chrono::duration<double>(r.took).count(), 1.1);
}

TEST(AdapterCdc, TornTapeTapeOutAndUnplugging) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 2000, &frames);
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--torn-at", "700"});
        auto r = read_all(sim.device);
        EXPECT_EQ(r.rows.size(), 700u) << "every row before the tear is kept";
        EXPECT_NE(r.error.find("frame 701: torn tape"), std::string::npos) << r.error;
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--unplug-after", "900"});
        auto r = read_all(sim.device);
        EXPECT_LE(r.rows.size(), 900u);
        EXPECT_GT(r.rows.size(), 800u);
        EXPECT_TRUE(std::equal(r.rows.begin(), r.rows.end(), frames.begin()));
        EXPECT_NE(r.error.find(": frame " + std::to_string(r.rows.size() + 1) + ": the adapter is gone (unplugged?)"),
                  std::string::npos)
            << r.error;
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--protocol", "7"});
        auto r = read_all(sim.device);
        EXPECT_NE(r.error.find("the adapter speaks protocol version 7, this tape speaks version 1: update tape"),
                  std::string::npos)
            << r.error;
    }
    {
        SIM_OR_SKIP(sim, dir, {"--no-reader"});
        auto r = read_all(sim.device);
        EXPECT_NE(r.error.find("this adapter has no reader"), std::string::npos) << r.error;
    }
}

TEST(AdapterCdc, ASecondRunOnTheSameAdapterStartsInStep) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 3000, &frames);
    SIM_OR_SKIP(sim, dir, {"--reader", in});
    // The first run stops half way (as Ctrl-C would): the next one resets the adapter and goes on
    // from where the tape stands, without replugging.
    std::vector<std::uint8_t> first;
    {
        auto t = tape::open_device(sim.device, tape::DeviceUse::read);
        read_until(*t, first, std::chrono::steady_clock::now() + 10s, 1000);
    }
    auto r = read_all(sim.device);
    EXPECT_EQ(r.error, "");
    ASSERT_GE(first.size(), 1000u);
    // The reader stopped within its stopping distance: what the first run did not take is lost with
    // the reset (the tape moved on), the rest comes in order.
    std::vector<std::uint8_t> all = first;
    all.insert(all.end(), r.rows.begin(), r.rows.end());
    EXPECT_LE(all.size(), frames.size());
    EXPECT_GE(all.size(), frames.size() - 100);
    EXPECT_TRUE(std::equal(first.begin(), first.end(), frames.begin()));
    EXPECT_TRUE(std::equal(r.rows.rbegin(), r.rows.rend(), frames.rbegin())) << "the second run reads to the end";
}

TEST(AdapterCdc, PunchesThroughTheCliAndAChadBoxFullStopsIt) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 600, &frames);
    {
        SIM_OR_SKIP(sim, dir, {"--punch", dir.file("punched.raw"), "--speed", "4"});
        Process tape({"punch", in, sim.device}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        sim.stop();
        EXPECT_EQ(bytes_of(read_text(dir.file("punched.raw"))), frames);
    }
    {
        SIM_OR_SKIP(sim, dir, {"--punch", dir.file("punched2.raw"), "--chad-full-after", "250", "--speed", "4"});
        Process tape({"punch", in, sim.device}, dir);
        EXPECT_EQ(tape.wait(20s), 3);
        EXPECT_NE(tape.err().find("frame 251: the chad box is full"), std::string::npos) << tape.err();
        sim.stop();
        EXPECT_EQ(read_text(dir.file("punched2.raw")).size(), 250u);
    }
}

TEST(AdapterCdc, ReadThroughTheCliKeepsEveryFrameBeforeAFault) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 1500, &frames);
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in});
        Process tape({"read", sim.device, "-o", dir.file("out.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        EXPECT_EQ(bytes_of(read_text(dir.file("out.ptp"))), frames);
        EXPECT_NE(tape.err().find("1500 frames read"), std::string::npos) << tape.err();
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--torn-at", "1000"});
        Process tape({"read", sim.device, "-o", dir.file("torn.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 3);
        EXPECT_EQ(tape.err(),
                  "tape: " + sim.device + ": frame 1001: torn tape: no sprocket hole within the time-out\n");
        auto got = bytes_of(read_text(dir.file("torn.ptp")));
        ASSERT_EQ(got.size(), 1000u);
        EXPECT_TRUE(std::equal(got.begin(), got.end(), frames.begin()));
    }
}

TEST(AdapterCdc, TenMinutesOfTapeAtFifteenHundredFramesASecondNoneLostNorDoubled) {
    // 900,000 frames: 10 minutes of a ФС-1501 reading start-stop, run 30 times faster than real time
    // (about 20 s), with one packet dropped on the way; the frame counter proves every row came once.
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 900000, &frames);
    SIM_OR_SKIP(sim, dir, {"--reader", in, "--speed", "30", "--drop-packet", "10000"});
    auto r = read_all(sim.device, 100s);
    EXPECT_EQ(r.error, "");
    ASSERT_EQ(r.rows.size(), frames.size());
    EXPECT_TRUE(r.rows == frames);
    double s = std::chrono::duration<double>(r.took).count();
    std::cout << "[ figure ] 900000 frames (600 s of tape at 1500 frames/s) in " << s
              << " s at 30x: " << static_cast<double>(frames.size()) / s / 30
              << " simulated frames/s, 0 lost, 0 doubled\n";
    EXPECT_LT(s, 60.0);
    sim.stop();
    EXPECT_NE(sim.err().find("1 packet(s) dropped"), std::string::npos) << sim.err();
}

TEST(AdapterCdc, InfoAndSelftestThroughTheCli) {
    TempDir dir;
    SIM_OR_SKIP(sim, dir, {"--serial", "TP0042", "--no-punch"});
    {
        Process tape({"adapter", "info", sim.device}, dir);
        EXPECT_EQ(tape.wait(10s), 0) << tape.err();
        std::string out = read_text(dir.file("stdout"));
        EXPECT_NE(out.find("serial\tTP0042\n"), std::string::npos) << out;
        EXPECT_NE(out.find("protocol\t1\n"), std::string::npos) << out;
        EXPECT_NE(out.find("reader\tyes, 1500 frames/s, reverse, flags doubtful rows\n"), std::string::npos) << out;
        EXPECT_NE(out.find("punch\tno\n"), std::string::npos) << out;
    }
    {
        Process tape({"adapter", "selftest", sim.device, "--seconds", "0.5"}, dir);
        EXPECT_EQ(tape.wait(10s), 0) << tape.err();
        std::string out = read_text(dir.file("stdout"));
        EXPECT_NE(out.find("0 wrong, 0 bad packets in, 0 out"), std::string::npos) << out;
        auto echoes = std::stoull(out);
        EXPECT_GT(echoes, 50u) << out;
    }
    {
        auto r = tape::adapter_selftest(sim.device, 300ms, 5);
        EXPECT_GT(r.packets, 10u);
        EXPECT_EQ(r.bytes, r.packets * 56);
        EXPECT_EQ(r.mismatches, 0u);
        EXPECT_EQ(r.bad_in, 0u);
    }
}

// The line settings of the run the simulator ended with, from its --stats line.
std::string sim_config(const std::string& err) {
    auto at = err.find("config: ");
    return at == std::string::npos ? "" : err.substr(at + 8, err.find('\n', at) - at - 8);
}

TEST(AdapterCdc, ConfigThroughTheCliIsWhatTheAdapterReadsWith) {
    // A unit wired active low on every data line: rows come inverted until the adapter is told so.
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 300, &frames);
    {
        SIM_OR_SKIP(unconfigured, dir, {"--reader", in, "--active-low", "255"});
        auto r = read_all(unconfigured.device);
        ASSERT_EQ(r.error, "");
        ASSERT_EQ(r.rows.size(), 300u);
        EXPECT_EQ(r.rows[1], static_cast<std::uint8_t>(~frames[1])) << "unconfigured: the levels as they are";
    }
    SIM_OR_SKIP(sim, dir, {"--reader", in, "--active-low", "255", "--stats"});
    {
        Process tape({"adapter", "config", sim.device, "--invert", "0xFF", "--tracks", "7", "--strobe", "falling",
                      "--sample-delay", "80", "--drive", "pulse", "--drive-pulse", "300", "--watchdog", "1500"},
                     dir);
        ASSERT_EQ(tape.wait(10s), 0) << tape.err();
        EXPECT_EQ(read_text(dir.file("stdout")),
                  "invert\t0xFF\ntracks\t7\nsprocket\tactive high, sampled 80 us after its falling edge\n"
                  "drive\tpulses of 300 us, active high\nstatus inputs\tactive high\n"
                  "punch\tready active high, magnets active high, held 2500 us\nsprocket timeout\t50 ms\n"
                  "watchdog\t1500 ms\n");
    }
    // The setting outlives the session (a reset keeps it): this run reads true rows, masked to 7 tracks.
    auto r = read_all(sim.device);
    EXPECT_EQ(r.error, "");
    ASSERT_EQ(r.rows.size(), 300u);
    for (std::size_t i = 0; i < r.rows.size(); ++i) ASSERT_EQ(r.rows[i], frames[i] & 0x7F) << "frame " << i + 1;
    EXPECT_EQ(sim.stop(), 0);
    EXPECT_EQ(sim_config(sim.err()),
              "invert=0xFF lines=0x06 tracks=7 sample_delay_us=80 punch_pulse_us=2500 drive_pulse_us=300 "
              "sprocket_timeout_ms=50 watchdog_ms=1500")
        << sim.err();
}

TEST(AdapterCdc, DevicesProbeAsksEveryAdapterAttached) {
    // A sysfs laid out as the kernel does for two CDC ports of tape adapters: ttyACM0 is the simulator
    // (its port linked into a /dev of the test's own), ttyACM1 answers nothing (no such port).
    TempDir dir;
    namespace fs = std::filesystem;
    fs::path sys = dir.file("sys"), dev = dir.file("dev");
    fs::create_directories(dev);
    fs::create_directories(sys / "class/tty");
    for (std::string n : {"0", "1"}) {
        fs::path usb = sys / ("devices/pci0/usb1/1-" + n), tty = usb / ("1-" + n + ":1.0/tty/ttyACM" + n);
        fs::create_directories(tty);
        std::ofstream(usb / "idVendor") << "1209\n";
        std::ofstream(usb / "idProduct") << "0001\n";
        std::ofstream(usb / "serial") << "TP000" << n << "\n";
        fs::create_directory_symlink("../../../1-" + n + ":1.0", tty / "device");
        fs::create_directory_symlink(tty, sys / "class/tty" / ("ttyACM" + n));
    }
    SIM_OR_SKIP(sim, dir, {"--serial", "TP0000", "--no-punch", "--link", (dev / "ttyACM0").string()});
    ::setenv("TAPE_SYSFS_ROOT", sys.c_str(), 1);
    ::setenv("TAPE_DEV_ROOT", dev.c_str(), 1);
    Process tape({"devices", "--probe"}, dir);
    ::unsetenv("TAPE_SYSFS_ROOT");
    ::unsetenv("TAPE_DEV_ROOT");
    EXPECT_EQ(tape.wait(20s), 0) << tape.err();
    std::string out = read_text(dir.file("stdout"));
    std::string port0 = "adapter:" + (dev / "ttyACM0").string(), port1 = "adapter:" + (dev / "ttyACM1").string();
    EXPECT_NE(out.find(port0 + "\t1209:0001 serial TP0000\n\tprotocol 1, firmware 0.1.0, reader 1500 frames/s\n"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find(port1 + "\t1209:0001 serial TP0001\n\tno answer: "), std::string::npos) << out;
}

TEST(AdapterCdc, PunchVerifyReadsTheTapeBackAndNamesAFrameThatDiffers) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 400, &frames);
    {
        SIM_OR_SKIP(sim, dir, {"--loop", "--speed", "8"});
        Process tape({"-v", "punch", in, sim.device, "--verify", sim.device, "--verify-timeout", "1"}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        EXPECT_NE(tape.err().find("verified 400 frames"), std::string::npos) << tape.err();
    }
    {
        // Frame 123 is punched with its lowest hole missing (a worn pin): the read-back names it.
        SIM_OR_SKIP(sim, dir, {"--loop", "--speed", "8", "--miss-hole-at", "123"});
        Process tape({"punch", in, sim.device, "--verify", sim.device, "--verify-timeout", "1"}, dir);
        EXPECT_EQ(tape.wait(20s), 1) << tape.err();
        std::uint8_t want = frames[122], got = static_cast<std::uint8_t>(want & (want - 1));
        char expected[128];
        std::snprintf(expected, sizeof expected, "frame 123: punched 0x%02X, read back 0x%02X\n", want, got);
        EXPECT_EQ(tape.err(), "tape: " + sim.device + ": " + expected);
    }
}

TEST(AdapterCdc, AStalledHostIsStoppedByTheWatchdogAndToldSo) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 6000, &frames);
    SIM_OR_SKIP(sim, dir, {"--reader", in});
    std::vector<std::uint8_t> got;
    std::string error;
    try {
        auto t = tape::open_device(sim.device, tape::DeviceUse::read);
        auto end = std::chrono::steady_clock::now() + 10s;
        read_until(*t, got, end, 300);
        // The host stalls for 0.8 s: the adapter's watchdog (500 ms) stops the reader.
        std::this_thread::sleep_for(800ms);
        read_until(*t, got, end);
    } catch (const tape::Error& e) {
        error = e.what();
    }
    EXPECT_NE(error.find("frame " + std::to_string(got.size() + 1) +
                         ": the adapter's watchdog stopped the reader and the punch (the host was silent)"),
              std::string::npos)
        << error;
    EXPECT_LT(got.size(), 2000u) << "the reader stopped within the watchdog's time";
    EXPECT_TRUE(std::equal(got.begin(), got.end(), frames.begin())) << "every row before it is kept";
}

TEST(AdapterCdc, ARecoveredPacketIsNamedWithVerbose) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 1500, &frames);
    SIM_OR_SKIP(sim, dir, {"--reader", in, "--drop-packet", "5"});
    Process tape({"-v", "read", sim.device, "-o", dir.file("out.ptp")}, dir);
    EXPECT_EQ(tape.wait(20s), 0) << tape.err();
    EXPECT_EQ(bytes_of(read_text(dir.file("out.ptp"))), frames);
    EXPECT_NE(tape.err().find(" came again after a lost or damaged packet\n"), std::string::npos) << tape.err();
    EXPECT_NE(tape.err().find(": frames "), std::string::npos) << tape.err();
}

// Read backwards from the tape's end (direction=reverse), the image comes out in the tape's own order,
// the same as read forwards, in any format; cut short, the frames on disk are those read, in the order
// read, and the message says so. A reader that cannot reverse is refused before anything is written.
TEST(AdapterCdc, ReadingBackwardsGivesTheTapeInItsOwnOrder) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 1500, &frames);
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--at-end", "--no-sprocket-at", "100", "--no-sprocket-at", "101"});
        Process tape({"read", sim.device + "?direction=reverse", "-o", dir.file("back.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        EXPECT_EQ(bytes_of(read_text(dir.file("back.ptp"))), frames);
        // The doubtful frames are named where they are on the tape.
        EXPECT_EQ(tape.err(), "tape: " + sim.device + ": frame 100: doubtful, to frame 101: read without a sprocket " +
                                  "hole (sampled by time)\ntape: " + sim.device +
                                  "?direction=reverse: 1500 frames read into " + dir.file("back.ptp") +
                                  " (end of tape, or the other side hung up; read backwards, turned to the tape's "
                                  "order)\n");
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--at-end"});
        Process tape({"read", sim.device + "?direction=reverse", "-o", dir.file("back.holes")}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in});
        Process tape({"read", sim.device, "-o", dir.file("forward.holes")}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        EXPECT_EQ(read_text(dir.file("back.holes")), read_text(dir.file("forward.holes")));
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--at-end", "--unplug-after", "300"});
        Process tape({"read", sim.device + "?direction=reverse", "-o", dir.file("cut.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 3) << tape.err();
        auto got = bytes_of(read_text(dir.file("cut.ptp")));
        ASSERT_GT(got.size(), 200u);
        ASSERT_LE(got.size(), 300u);
        EXPECT_TRUE(std::equal(got.begin(), got.end(), frames.rbegin()));
        EXPECT_NE(tape.err().find("read backwards and not to the tape's start: its frames are in the order read, "
                                  "the tape's last first"),
                  std::string::npos)
            << tape.err();
    }
    {
        // Stopped by the user: a part of the tape, kept as read, not turned.
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--at-end", "--speed", "0.2"});
        Process tape({"read", sim.device + "?direction=reverse", "-o", dir.file("part.ptp")}, dir);
        auto end = std::chrono::steady_clock::now() + 10s;
        while (read_text(dir.file("part.ptp")).size() < 20 && std::chrono::steady_clock::now() < end)
            std::this_thread::sleep_for(10ms);
        tape.interrupt();
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        auto got = bytes_of(read_text(dir.file("part.ptp")));
        ASSERT_GE(got.size(), 20u);
        ASSERT_LT(got.size(), frames.size());
        EXPECT_TRUE(std::equal(got.begin(), got.end(), frames.rbegin()));
        EXPECT_NE(tape.err().find("its frames are in the order read"), std::string::npos) << tape.err();
        EXPECT_EQ(tape.err().find("turned"), std::string::npos) << tape.err();
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--at-end", "--no-reverse"});
        Process tape({"read", sim.device + "?direction=reverse", "-o", dir.file("never.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 3) << tape.err();
        EXPECT_EQ(tape.err(),
                  "tape: " + sim.device + ": this adapter's reader cannot read backwards (direction=reverse)\n");
        EXPECT_FALSE(std::filesystem::exists(dir.file("never.ptp")));
        Process punch({"punch", in, sim.device + "?direction=reverse"}, dir);
        EXPECT_EQ(punch.wait(20s), 2) << punch.err();
        EXPECT_NE(punch.err().find("direction is the reader's, and this device is opened to punch"), std::string::npos)
            << punch.err();
    }
}

// Rows the adapter flags (no sprocket seen, mistimed, a marginal level) are kept as read and named as
// doubtful, a run of alike ones at once; past --max-errors they are counted.
TEST(AdapterCdc, RowsTheReaderFlagsAreNamedAsDoubtful) {
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 1500, &frames);
    std::vector<std::string> faults = {"--reader",         in,    "--no-sprocket-at", "100", "--no-sprocket-at", "101",
                                       "--no-sprocket-at", "102", "--mistimed-at",    "500", "--marginal-at",    "500",
                                       "--marginal-at",    "900"};
    {
        SIM_OR_SKIP(sim, dir, faults);
        Process tape({"read", sim.device, "-o", dir.file("out.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        EXPECT_EQ(bytes_of(read_text(dir.file("out.ptp"))), frames);
        std::string d = "tape: " + sim.device + ": ";
        EXPECT_EQ(tape.err(),
                  d + "frame 100: doubtful, to frame 102: read without a sprocket hole (sampled by time)\n" + d +
                      "frame 500: doubtful: its sprocket hole came early or late; a track's level " +
                      "was near its threshold\n" + d + "frame 900: doubtful: a track's level was near its threshold\n" +
                      d + "1500 frames read into " + dir.file("out.ptp") +
                      " (end of tape, or the other side hung up)\n");
    }
    {
        SIM_OR_SKIP(sim, dir, faults);
        Process tape({"--max-errors", "1", "read", sim.device, "-o", dir.file("few.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        EXPECT_NE(tape.err().find("frame 100: doubtful"), std::string::npos) << tape.err();
        EXPECT_EQ(tape.err().find("frame 500"), std::string::npos) << tape.err();
        EXPECT_NE(tape.err().find("2 more doubtful frame(s) not shown (--max-errors 1)"), std::string::npos)
            << tape.err();
    }
    {
        SIM_OR_SKIP(sim, dir, faults);
        Process tape({"--max-errors", "0", "read", sim.device, "-o", dir.file("all.ptp")}, dir);  // 0: all
        EXPECT_EQ(tape.wait(20s), 0) << tape.err();
        EXPECT_NE(tape.err().find("frame 900: doubtful"), std::string::npos) << tape.err();
        EXPECT_EQ(tape.err().find("not shown"), std::string::npos) << tape.err();
    }
}

TEST(AdapterCdc, CtrlCOnAPunchRunEndsItAsStoppedAndStopsThePunchNow) {
    // The host stops answering the adapter once the user stops it; whatever the adapter says after (its
    // watchdog), the run ends as stopped (130), and the punch stops then, not when its queue has run out.
    TempDir dir;
    std::vector<std::uint8_t> frames;
    std::string in = write_tape(dir, 3000, &frames);
    for (int sig : {SIGINT, SIGHUP}) {
        SIM_OR_SKIP(sim, dir, {"--punch", dir.file("punched.ptp"), "--stats"});
        Process tape({"punch", in, sim.device}, dir);
        auto end = std::chrono::steady_clock::now() + 10s;
        while (read_text(dir.file("punched.ptp")).size() < 100 && std::chrono::steady_clock::now() < end)
            std::this_thread::sleep_for(10ms);
        std::size_t at_stop = read_text(dir.file("punched.ptp")).size();
        tape.signal(sig);
        EXPECT_EQ(tape.wait(20s), 130) << "signal " << sig << ": " << tape.err();
        EXPECT_NE(tape.err().find("stopped after "), std::string::npos) << tape.err();
        EXPECT_EQ(tape.err().find("watchdog"), std::string::npos) << tape.err();
        // A punch left running would punch its whole queue (256 rows at 150 a second) after the stop.
        std::this_thread::sleep_for(1s);
        EXPECT_LT(read_text(dir.file("punched.ptp")).size(), at_stop + 120) << "the punch went on after the stop";
    }
}

TEST(AdapterCdc, AnAdapterWithoutAReaderOrAPunchIsRefusedBeforeAnOutputIsCreated) {
    TempDir dir;
    std::string in = write_tape(dir, 100);
    {
        SIM_OR_SKIP(sim, dir, {"--no-reader"});
        Process tape({"read", sim.device, "-o", dir.file("out.ptp")}, dir);
        EXPECT_EQ(tape.wait(20s), 3) << tape.err();
        EXPECT_NE(tape.err().find("this adapter has no reader"), std::string::npos) << tape.err();
        EXPECT_FALSE(std::filesystem::exists(dir.file("out.ptp")));
    }
    {
        SIM_OR_SKIP(sim, dir, {"--no-punch"});
        Process tape({"punch", in, sim.device}, dir);
        EXPECT_EQ(tape.wait(20s), 3) << tape.err();
        EXPECT_NE(tape.err().find("this adapter has no punch"), std::string::npos) << tape.err();
    }
}

// tape archive create --from: the tape read three times through the adapter, forwards, backwards (turned to
// the tape's order) and forwards again, each read kept in the bag as it came and restored; a reader that
// cannot go back leaves no bag.
TEST(AdapterCdc, ArchiveReadsTheTapeTimesIntoTheBag) {
    TempDir dir;
    std::string in = sample_path("16k20f3s5-turning.iso.ptp"), tape_bytes = read_text(in);
    std::string bag = dir.file("bag");
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in});
        Process tape({"archive", "create", bag, "--from", sim.device, "--times", "3", "--timeout", "2"}, dir);
        ASSERT_EQ(tape.wait(60s), 0) << tape.err();
        for (int k = 1; k <= 3; ++k)
            EXPECT_EQ(read_text(bag + "/data/reads/read-" + std::to_string(k) + ".ptp"), tape_bytes) << k;
        EXPECT_EQ(read_text(bag + "/data/restored.ptp"), tape_bytes);
        EXPECT_NE(tape.err().find("read 2 of 3, backwards"), std::string::npos) << tape.err();
        EXPECT_NE(tape.err().find("turned to the tape's order"), std::string::npos) << tape.err();
        bagit_reader::Bag b = bagit_reader::read(bag);
        EXPECT_TRUE(b.errors.empty()) << ::testing::PrintToString(b.errors);
        EXPECT_EQ(b.info["Tape-Restoration"].find("restored.ptp from 3 read(s)"), 0u) << b.info["Tape-Restoration"];
        EXPECT_EQ(std::system(("cd " + bag + " && sha256sum -c --strict manifest-sha256.txt >/dev/null").c_str()), 0);
    }
    {
        SIM_OR_SKIP(sim, dir, {"--reader", in, "--no-reverse"});
        Process tape({"archive", "create", dir.file("never"), "--from", sim.device, "--timeout", "2"}, dir);
        EXPECT_EQ(tape.wait(60s), 3) << tape.err();
        EXPECT_NE(tape.err().find("cannot read backwards"), std::string::npos) << tape.err();
        EXPECT_FALSE(std::filesystem::exists(dir.file("never")));
        for (const auto& e : std::filesystem::directory_iterator(dir.path))
            EXPECT_EQ(e.path().filename().string().find(".never.partial"), std::string::npos) << e.path();
    }
    Outcome r = tape_run({"archive", "create", dir.file("serial"), "--from", "serial:/dev/null"}, dir);
    EXPECT_EQ(r.status, 2) << r.err;
}
