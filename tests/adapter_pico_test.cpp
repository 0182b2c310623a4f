// The tape adapter's RP2040 firmware (firmware/rp2040 and the shared core) on an emulated Raspberry Pi
// Pico (tests/rp2040/pico.mjs): its USB enumeration against the descriptors, and the tape CLI and the
// library reading from an emulated ФС-1501, punching, and feeding an emulated control, over the CDC
// port bridged to a pseudo-terminal, exactly as against a board.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "device/adapter_session.hpp"
#include "process_util.hpp"
#include "rp2040/pico_util.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace std::chrono_literals;

namespace {

#define PICO_OR_SKIP(name, dir, ...)                                              \
    if (std::string why = pico::unavailable(); !why.empty()) GTEST_SKIP() << why; \
    pico::Pico name(dir, __VA_ARGS__);                                            \
    ASSERT_FALSE(name.device.empty()) << "the emulated Pico did not come up: " << name.err()

std::vector<std::uint8_t> pattern(std::size_t n, unsigned salt) {
    std::vector<std::uint8_t> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<std::uint8_t>((i * 37 + i / 251 + salt) & 0xFF);
    return t;
}

std::string write_bytes(const TempDir& dir, const std::string& name, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(dir.file(name), std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return dir.file(name);
}

TEST(AdapterPico, EnumeratesAsItsDescriptorsSayWithTheFlashIdAsSerial) {
    TempDir dir;
    PICO_OR_SKIP(p, dir, {"--flash-id", "E66138528B4F4D2A"});
    std::string dump = p.file("usb.txt");
    for (const char* line :
         {"  bcdUSB 2.00\n", "  bDeviceClass 2\n", "  bMaxPacketSize0 64\n", "  idVendor 0x1209\n",
          "  idProduct 0x0001\n", "  iManufacturer 1 tape project\n", "  iProduct 2 tape adapter\n",
          "  iSerial 3 E66138528B4F4D2A\n", "    bNumInterfaces 2\n",
          // The communication interface: CDC, ACM, no AT-command protocol; then the data interface.
          "      bInterfaceNumber 0\n      bAlternateSetting 0\n      bNumEndpoints 1\n      bInterfaceClass 2\n"
          "      bInterfaceSubClass 2\n      bInterfaceProtocol 0\n",
          "      CDC functional descriptor subtype 0x06: 0x00 0x01\n",
          "        bEndpointAddress 0x83 EP 3 IN\n        Transfer Type Interrupt\n",
          "      bInterfaceNumber 1\n      bAlternateSetting 0\n      bNumEndpoints 2\n      bInterfaceClass 10\n",
          "        bEndpointAddress 0x02 EP 2 OUT\n        Transfer Type Bulk\n        wMaxPacketSize 0x0040\n",
          "        bEndpointAddress 0x81 EP 1 IN\n        Transfer Type Bulk\n        wMaxPacketSize 0x0040\n",
          "String languages: 0x0409\n", "Line coding read back: 115200 baud, 8 data bits, parity 0, stop 0\n"})
        EXPECT_NE(dump.find(line), std::string::npos) << "no\n" << line << "in\n" << dump;
}

TEST(AdapterPico, InfoAndSelftestThroughTheCli) {
    TempDir dir;
    PICO_OR_SKIP(p, dir, {"--flash-id", "0123456789ABCDEF"});
    auto info = tape_run({"adapter", "info", p.device}, dir);
    EXPECT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.out.find("serial\t0123456789ABCDEF\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("reader\tyes, 1500 frames/s\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("emulate\tyes"), std::string::npos) << info.out;
    auto self = tape_run({"adapter", "selftest", p.device}, dir);
    EXPECT_EQ(self.status, 0) << self.err;
    EXPECT_NE(self.out.find(" 0 wrong, 0 bad packets in, 0 out"), std::string::npos) << self.out;
}

// 10^5 frames from the emulated ФС-1501 at 1500 frames/s (67 s on the chip's clock; longer in real time
// on a loaded machine, where the emulator falls behind): every one once, in order.
TEST(AdapterPico, ReadsAHundredThousandFramesNoneLostNorDoubled) {
    TempDir dir;
    auto tape = pattern(100000, 3);
    PICO_OR_SKIP(p, dir, {"--tape", write_bytes(dir, "tape.bin", tape)});
    Process read({"read", p.device, "-o", dir.file("read.ptp")}, dir);
    EXPECT_EQ(read.wait(400s), 0) << read.err();
    auto got = read_text(dir.file("read.ptp"));
    EXPECT_EQ(got.size(), tape.size());
    EXPECT_TRUE(std::vector<std::uint8_t>(got.begin(), got.end()) == tape) << "the frames differ";
    ASSERT_TRUE(p.stop()) << p.err();
    EXPECT_EQ(nlohmann::json::parse(p.file("stats.json"))["sprockets"], 100000);
}

// Told to read 1000 rows, the adapter stops the reader before its next sprocket: no row beyond one more
// (the reader is not started again), and the host gets exactly the 1000.
TEST(AdapterPico, TheReaderStopsWithinAFrame) {
    TempDir dir;
    auto tape = pattern(5000, 4);
    PICO_OR_SKIP(p, dir, {"--tape", write_bytes(dir, "tape.bin", tape)});
    tape::adapter::Session s(tape::adapter::open_pipe(p.device));
    std::vector<std::uint8_t> got, buf(4096);
    tapefw::ReadStart start;
    start.max_rows = 1000;
    auto end = std::chrono::steady_clock::now() + 20s;
    while (std::chrono::steady_clock::now() < end) {
        auto r = s.read(buf, 200ms, start);
        got.insert(got.end(), buf.begin(), buf.begin() + static_cast<long>(r.count));
        if (r.end) break;
    }
    EXPECT_EQ(got, std::vector<std::uint8_t>(tape.begin(), tape.begin() + 1000));
    std::this_thread::sleep_for(200ms);  // the reader, if it had not stopped, would go on
    ASSERT_TRUE(p.stop()) << p.err();
    EXPECT_LE(nlohmann::json::parse(p.file("stats.json"))["sprockets"].get<int>(), 1001);
}

// A host that stops reading for a second (its watchdog set longer): the adapter stops the reader when
// its buffer is nearly full and starts it again; nothing is lost.
TEST(AdapterPico, AHostThatStallsForASecondLosesNothing) {
    TempDir dir;
    auto tape = pattern(6000, 5);
    PICO_OR_SKIP(p, dir, {"--tape", write_bytes(dir, "tape.bin", tape)});
    tape::adapter::Session s(tape::adapter::open_pipe(p.device));
    tapefw::Config config;
    config.watchdog_ms = 3000;
    s.configure(config);
    std::vector<std::uint8_t> got, buf(256);
    auto end = std::chrono::steady_clock::now() + 30s;
    bool stalled = false;
    while (std::chrono::steady_clock::now() < end) {
        auto r = s.read(buf, 200ms);
        got.insert(got.end(), buf.begin(), buf.begin() + static_cast<long>(r.count));
        if (r.end) break;
        if (!stalled && got.size() >= 1500) {
            stalled = true;
            std::this_thread::sleep_for(1s);
        }
    }
    EXPECT_TRUE(stalled);
    EXPECT_EQ(got, tape);
}

// The emulate role with a host that stalls for a second (its watchdog set longer): the queue runs dry,
// the strobe is held, and the control takes every frame once, in order, none wrong.
TEST(AdapterPico, AnEmulatingHostThatStallsForASecondHoldsTheStrobe) {
    TempDir dir;
    PICO_OR_SKIP(p, dir, {"--control"});
    auto frames = pattern(1500, 8);
    {
        tape::adapter::Session s(tape::adapter::open_pipe(p.device));
        tapefw::Config config;
        config.watchdog_ms = 3000;
        s.configure(config);
        s.start_emulation();
        auto feed = [&](std::size_t upto, std::chrono::seconds deadline) {
            auto end = std::chrono::steady_clock::now() + deadline;
            while (s.taken().taken < upto && std::chrono::steady_clock::now() < end) {
                std::size_t from = s.taken().next;
                s.offer(static_cast<std::uint32_t>(from), {frames.data() + from, std::min(upto, frames.size()) - from});
                s.pump_emulation(10ms);
            }
        };
        feed(400, 20s);
        std::this_thread::sleep_for(1s);  // the host stalls; the control has taken all it was given
        feed(frames.size(), 30s);
        EXPECT_EQ(s.taken().taken, frames.size());
    }
    ASSERT_TRUE(p.stop()) << p.err();
    EXPECT_EQ(p.bytes("taken.bin"), frames);
}

TEST(AdapterPico, PunchesEveryRowInOrderThroughTheCli) {
    TempDir dir;
    auto rows = pattern(450, 6);
    PICO_OR_SKIP(p, dir, {"--punch"});
    auto punch = tape_run({"punch", write_bytes(dir, "rows.ptp", rows), p.device}, dir);
    EXPECT_EQ(punch.status, 0) << punch.err;
    ASSERT_TRUE(p.stop()) << p.err();
    EXPECT_EQ(p.bytes("punched.bin"), rows);
}

// tape emulate feeding the emulated control, which stops at each DC3 (and every 40 frames): after each
// stop it sees at most one frame more (the ФС-1501's braking), and it takes the program in order.
TEST(AdapterPico, TapeEmulateStopsWithinAFrameOfTheControlsStop) {
    TempDir dir;
    std::vector<std::uint8_t> program = {0xA5, 0x0A};  // '%', LF
    for (int block = 1; block <= 12; ++block) {
        auto line = pattern(20, static_cast<unsigned>(block));
        for (auto& f : line) f = static_cast<std::uint8_t>(0x30 | (f & 0x0F));  // no DC3 by chance
        program.insert(program.end(), line.begin(), line.end());
        program.insert(program.end(), {0x0A, 0x93});  // LF, DC3
    }
    PICO_OR_SKIP(p, dir, {"--control", "--stop-every", "40"});
    Process emulate({"emulate", write_bytes(dir, "p.ptp", program), p.device}, dir);
    eventually([&] { return p.bytes("taken.bin").size() >= program.size(); }, 30s);
    emulate.interrupt();
    EXPECT_EQ(emulate.wait(20s), 0) << emulate.err();
    ASSERT_TRUE(p.stop()) << p.err();
    auto taken = p.bytes("taken.bin");
    ASSERT_GE(taken.size(), program.size()) << emulate.err();
    EXPECT_EQ(std::vector<std::uint8_t>(taken.begin(), taken.begin() + static_cast<long>(program.size())), program);
    auto stats = nlohmann::json::parse(p.file("stats.json"));
    EXPECT_GE(stats["frames_after_stop"].size(), 12u);
    for (unsigned after : stats["frames_after_stop"]) EXPECT_LE(after, 1u);
}

}  // namespace
