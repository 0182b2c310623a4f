#include "rp2040/board.hpp"

#include <initializer_list>

#include "rp2040/pins.hpp"
#include "rp2040/regs.hpp"

namespace rp2040 {
namespace {

using namespace rp;
namespace lb = tapefw::line_bit;
constexpr unsigned punch_alarm = 1, tick_alarm = 3;
constexpr std::uint32_t tick_us = 1000;

std::uint32_t bit(unsigned gpio) { return 1u << gpio; }

void as_output(unsigned gpio) {
    reg(pads::gpio(gpio)) = pads::ie | pads::schmitt | (1u << 4);  // 4 mA
    reg(io::ctrl(gpio)) = io::funcsel_sio;
    reg(sio::oe_set) = bit(gpio);
}
void as_input(unsigned gpio) {
    reg(sio::oe_clr) = bit(gpio);
    reg(pads::gpio(gpio)) = pads::ie | pads::schmitt | pads::pde;  // a line not wired reads inactive (low)
    reg(io::ctrl(gpio)) = io::funcsel_sio;
}
void watch_edges(unsigned gpio, std::uint32_t edges) {
    reg(io::intr(gpio)) = io::edge_low(gpio) | io::edge_high(gpio);
    clear_bits(io::proc0_inte(gpio), io::edge_low(gpio) | io::edge_high(gpio));
    set_bits(io::proc0_inte(gpio), edges);
}
}  // namespace

void Board::start() {
    using namespace pico_pins;
    for (unsigned g = bus_first; g <= bus_strobe; ++g) as_output(g);
    for (unsigned g : {reader_start, reader_reverse, led}) as_output(g);
    for (unsigned g = reader_first; g < reader_first + 8; ++g) as_input(g);
    for (std::uint8_t g : {control_run, reader_sprocket, reader_tape_out, pico_pins::punch_ready, punch_tape_out,
                           control_reverse, control_rewind})
        as_input(g);
    reg(timer::inte) = 0xF;
    for (unsigned irq : {nvic::irq_timer0, nvic::irq_timer1, nvic::irq_timer2, nvic::irq_timer3, nvic::irq_usbctrl,
                         nvic::irq_io_bank0})
        reg(nvic::iser) = 1u << irq;
    arm_alarm(tick_alarm, now_us() + tick_us);
}

std::uint32_t Board::now_us() { return reg(timer::rawl); }

void Board::arm_alarm(unsigned alarm, std::uint32_t at) { reg(timer::alarm0 + 4 * alarm) = at; }

void Board::set_pin(unsigned gpio, bool high) { reg(high ? sio::out_set : sio::out_clr) = bit(gpio); }
bool Board::pin(unsigned gpio) const { return (reg(sio::in) & bit(gpio)) != 0; }

// Level form: start/stop on while driving, direction on for reverse (pulse form: not done on this board).
void Board::drive(tapefw::Drive d) {
    bool low = config_.lines & lb::drive_low;
    set_pin(pico_pins::reader_start, (d != tapefw::Drive::stop) != low);
    set_pin(pico_pins::reader_reverse, (d == tapefw::Drive::reverse) != low);
    set_pin(pico_pins::led, d != tapefw::Drive::stop);
}

bool Board::punch_ready() {
    return !punch_pulse_ && pin(pico_pins::punch_ready) != bool(config_.lines & lb::punch_ready_low);
}

// The row's code magnets and the feed-hole magnet for punch_pulse_us.
void Board::punch(std::uint8_t row) {
    bool low = config_.lines & lb::punch_magnet_low;
    for (unsigned t = 0; t < 8; ++t) set_pin(pico_pins::bus_first + t, bool(row & (1u << t)) != low);
    set_pin(pico_pins::bus_strobe, !low);
    punch_pulse_ = true;
    arm_alarm(punch_alarm, now_us() + config_.punch_pulse_us);
}

void Board::on_punch_alarm() {
    bool low = config_.lines & lb::punch_magnet_low;
    for (unsigned g = pico_pins::bus_first; g <= pico_pins::bus_strobe; ++g) set_pin(g, low);
    punch_pulse_ = false;
}

std::uint16_t Board::status_lines() {
    bool low = config_.lines & lb::status_low;
    std::uint16_t s = 0;
    if (pin(pico_pins::reader_tape_out) != low) s |= tapefw::status::tape_out;
    if (pin(pico_pins::punch_tape_out) != low) s |= tapefw::status::punch_tape_out;
    return s;
}

// The sprocket edge that marks a settled row: the leading one, or the trailing one with strobe_falling.
void Board::configure(const tapefw::Config& config) {
    config_ = config;
    bool rising = !(config.lines & lb::sprocket_low) != bool(config.lines & lb::strobe_falling);
    unsigned s = pico_pins::reader_sprocket;
    watch_edges(s, rising ? io::edge_high(s) : io::edge_low(s));
    if (!punch_pulse_ && !frame_clock_on_) on_punch_alarm();  // magnets at rest in the new polarity
}

void Board::on_sample_alarm() {
    std::uint32_t in = reg(sio::in);
    if (engine_) engine_->on_row(static_cast<std::uint8_t>(in >> pico_pins::reader_first));
}

}  // namespace rp2040
