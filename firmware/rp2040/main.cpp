// The tape adapter on a Raspberry Pi Pico: clocks, the board, USB CDC, and the adapter core's engine
// (firmware/core) fed from the main loop. The pins are in pins.hpp; docs/rp2040-wiring.md shows them.
#include <new>

#include "core/engine.hpp"
#include "rp2040/board.hpp"
#include "rp2040/clocks.hpp"
#include "rp2040/regs.hpp"

namespace {

rp2040::Board board;
alignas(tapefw::Engine) unsigned char engine_room[sizeof(tapefw::Engine)];
tapefw::Engine* engine = nullptr;
char serial[17] = "unknown";

// Boot stage 2 left the flash's 64-bit unique id below itself, marked "FLID" (boot2.S): the serial
// string is its hex digits, as every W25Q's id differs. Without the mark it stays "unknown".
void read_serial() {
    const volatile std::uint8_t* id = reinterpret_cast<const volatile std::uint8_t*>(0x20041EF0);
    if (rp::reg(0x20041EF8) != 0x44494C46) return;
    const char* hex = "0123456789ABCDEF";
    for (int i = 0; i < 8; ++i) {
        serial[2 * i] = hex[id[i] >> 4];
        serial[2 * i + 1] = hex[id[i] & 0xF];
    }
    serial[16] = 0;
}

}  // namespace

extern "C" {
void timer_irq(unsigned alarm) { rp::reg(rp::timer::intr) = 1u << alarm; }
void timer0_irq() {
    timer_irq(0);
    board.on_sample_alarm();
}
void timer1_irq() {
    timer_irq(1);
    board.on_punch_alarm();
}
void timer2_irq() {
    timer_irq(2);
    board.on_frame_alarm();
}
void timer3_irq() {
    timer_irq(3);
    board.on_tick_alarm();
}
void usbctrl_irq() { board.usb.on_irq(); }
void io_bank0_irq() { board.on_gpio(); }
}

int main() {
    rp2040::clocks_init();
    read_serial();
    board.start();
    tapefw::Identity id;
    id.capabilities = tapefw::caps::reader | tapefw::caps::punch | tapefw::caps::emulate;
    id.serial = serial;
    engine = new (engine_room) tapefw::Engine(board, id, tapefw::Framing::stream);
    board.attach(*engine);
    board.usb.start(serial);
    std::uint8_t bytes[64];
    for (;;) {
        std::size_t n = board.usb.read(bytes, sizeof bytes);
        if (n) engine->receive(bytes, n);
        engine->poll();
        if (!n) __asm volatile("wfi");  // the next interrupt: USB, a pin, an alarm or the 1 ms tick
    }
}
