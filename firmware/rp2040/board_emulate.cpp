// The Pico's side of the emulate role: the control's drive lines watched by edge interrupts, and the
// frame clock on timer alarm 2 (each slot: data on the lines, setup_us later the strobe for strobe_us;
// the data stay until the next slot, so they are held for the rest of the period).
#include <initializer_list>

#include "rp2040/board.hpp"
#include "rp2040/pins.hpp"
#include "rp2040/regs.hpp"

namespace rp2040 {
namespace {

using namespace rp;
namespace wb = tapefw::wiring_bit;
constexpr unsigned frame_alarm = 2;

bool usable(std::uint8_t gpio) { return gpio != tapefw::Wiring::no_pin && pico_pins::control_side(gpio); }

}  // namespace

// Only the X3 pins (pins.hpp): a wiring naming a reader or punch pin leaves that line out.
void Board::configure_emulation(const tapefw::Wiring& wiring) {
    wiring_ = wiring;
    emulate_pins_ = 0;
    for (unsigned t = 0; t < wiring.tracks && t < 8; ++t)
        if (usable(wiring.data_pins[t])) emulate_pins_ |= 1u << wiring.data_pins[t];
    if (usable(wiring.strobe_pin)) emulate_pins_ |= 1u << wiring.strobe_pin;
    for (unsigned g = 0; g < 30; ++g)
        if (emulate_pins_ & (1u << g)) {
            reg(io::ctrl(g)) = io::funcsel_sio;
            reg(sio::oe_set) = 1u << g;
        }
    set_strobe(false);
    watch_control_lines();
}

void Board::watch_control_lines() {
    for (std::uint8_t g : {wiring_.run_pin, wiring_.reverse_pin, wiring_.rewind_pin}) {
        if (!usable(g)) continue;
        reg(sio::oe_clr) = 1u << g;
        reg(pads::gpio(g)) = pads::ie | pads::schmitt | pads::pde;
        reg(io::ctrl(g)) = io::funcsel_sio;
        reg(io::intr(g)) = io::edge_low(g) | io::edge_high(g);
        set_bits(io::proc0_inte(g), io::edge_low(g) | io::edge_high(g));
    }
}

std::uint8_t Board::drive_inputs() {
    auto line = [this](std::uint8_t g, bool low) { return usable(g) && pin(g) != low; };
    std::uint8_t d = 0;
    if (line(wiring_.run_pin, wiring_.lines & wb::run_low)) d |= tapefw::drive_bit::run;
    if (line(wiring_.reverse_pin, wiring_.lines & wb::reverse_low)) d |= tapefw::drive_bit::reverse;
    if (line(wiring_.rewind_pin, wiring_.lines & wb::rewind_low)) d |= tapefw::drive_bit::rewind;
    return d;
}

void Board::set_strobe(bool on) {
    if (usable(wiring_.strobe_pin)) set_pin(wiring_.strobe_pin, on != bool(wiring_.lines & wb::strobe_low));
}

void Board::frame_clock(std::uint32_t first_in_us) {
    frame_clock_on_ = true;
    frame_phase_ = 0;
    slot_at_ = now_us() + first_in_us;
    arm_alarm(frame_alarm, slot_at_);
}

void Board::on_frame_alarm() {
    if (!frame_clock_on_ || !engine_) return;
    switch (frame_phase_) {
        case 0: {
            std::uint8_t levels = 0;
            tapefw::Slot slot = engine_->next_frame(levels);
            if (slot == tapefw::Slot::stop) {
                frame_clock_on_ = false;
                return;
            }
            if (slot == tapefw::Slot::frame) {
                for (unsigned t = 0; t < wiring_.tracks && t < 8; ++t)
                    if (usable(wiring_.data_pins[t])) set_pin(wiring_.data_pins[t], levels & (1u << t));
                frame_phase_ = 1;
                return arm_alarm(frame_alarm, slot_at_ + wiring_.setup_us);
            }
            break;  // hold: no strobe in this slot
        }
        case 1:
            set_strobe(true);
            frame_phase_ = 2;
            return arm_alarm(frame_alarm, slot_at_ + wiring_.setup_us + wiring_.strobe_us);
        default:
            set_strobe(false);
            break;
    }
    frame_phase_ = 0;
    slot_at_ += wiring_.period_us();
    arm_alarm(frame_alarm, slot_at_);
}

// The frame clock's alarm and the pins' interrupt masked while the main loop changes the frame queue.
void Board::critical(bool masked) {
    std::uint32_t irqs = (1u << nvic::irq_timer2) | (1u << nvic::irq_io_bank0) | (1u << nvic::irq_timer0);
    reg(masked ? nvic::iser + 0x80 : nvic::iser) = irqs;  // ICER is ISER + 0x80
}

// Edges of the reader's sprocket (a row to sample) and of the control's drive lines.
void Board::on_gpio() {
    unsigned s = pico_pins::reader_sprocket;
    std::uint32_t bank = reg(io::proc0_ints(s));
    std::uint32_t mask = io::edge_low(s) | io::edge_high(s);
    if (bank & mask) {
        reg(io::intr(s)) = bank & mask;
        arm_alarm(0, now_us() + config_.sample_delay_us);
    }
    bool control = false;
    for (std::uint8_t g : {wiring_.run_pin, wiring_.reverse_pin, wiring_.rewind_pin}) {
        if (!usable(g)) continue;
        std::uint32_t m = io::edge_low(g) | io::edge_high(g);
        if (reg(io::proc0_ints(g)) & m) {
            reg(io::intr(g)) = m;
            control = true;
        }
    }
    if (control && engine_) engine_->on_drive(drive_inputs());
}

void Board::on_tick_alarm() { arm_alarm(3, now_us() + 1000); }

}  // namespace rp2040
