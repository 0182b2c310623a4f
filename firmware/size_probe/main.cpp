// Links the adapter core with a board whose lines are made-up memory-mapped registers, only so that
// scripts/firmware-build.sh can measure the flash and RAM the core takes on a Cortex-M0+. It is no
// firmware to flash: firmware/rp2040 is the Raspberry Pi Pico's (docs/rp2040-wiring.md).
#include "core/engine.hpp"
namespace {
struct Probe final : tapefw::Hardware {
    volatile std::uint32_t* reg = reinterpret_cast<volatile std::uint32_t*>(0x40000000);
    std::uint32_t now_us() override { return reg[0]; }
    bool send(const std::uint8_t* b, std::size_t n) override {
        for (std::size_t i = 0; i < n; ++i) reg[1] = b[i];
        return true;
    }
    void drive(tapefw::Drive d) override { reg[2] = static_cast<std::uint32_t>(d); }
    bool punch_ready() override { return reg[3] != 0; }
    void punch(std::uint8_t row) override { reg[4] = row; }
    std::uint16_t status_lines() override { return static_cast<std::uint16_t>(reg[5]); }
    void configure(const tapefw::Config& c) override { reg[6] = c.lines; }
    void configure_emulation(const tapefw::Wiring& w) override { reg[9] = w.period_us(); }
    std::uint8_t drive_inputs() override { return static_cast<std::uint8_t>(reg[10]); }
    void frame_clock(std::uint32_t first_in_us) override { reg[11] = first_in_us; }
    void critical(bool masked) override { reg[12] = masked; }
};
Probe probe;
tapefw::Engine engine(probe, tapefw::Identity{});
}  // namespace
int main() {
    for (;;) {
        std::uint8_t b = static_cast<std::uint8_t>(probe.reg[7]);
        engine.receive(&b, 1);
        engine.on_row(static_cast<std::uint8_t>(probe.reg[8]));
        engine.on_drive(static_cast<std::uint8_t>(probe.reg[13]));
        std::uint8_t levels = 0;
        if (engine.next_frame(levels) == tapefw::Slot::frame) probe.reg[14] = levels;
        engine.poll();
    }
}
