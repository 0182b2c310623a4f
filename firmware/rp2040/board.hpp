// The Pico as the adapter core's Hardware (firmware/core/hardware.hpp): its pins (pins.hpp), the
// timer's microsecond counter and alarms, the USB CDC port. Alarms: 0 samples the reader's data lines
// sample_delay_us after the sprocket edge, 1 ends the punch magnets' pulse, 2 is the emulate role's
// frame clock, 3 a 1 ms tick that wakes the main loop for the engine's time-outs.
#pragma once

#include "core/engine.hpp"
#include "rp2040/usb_cdc.hpp"

namespace rp2040 {

class Board final : public tapefw::Hardware {
public:
    /// Pins to their roles and levels, the timer's interrupts on.
    void start();
    void attach(tapefw::Engine& engine) { engine_ = &engine; }
    UsbCdc usb;

    std::uint32_t now_us() override;
    bool send(const std::uint8_t* bytes, std::size_t n) override { return usb.write(bytes, n); }
    void drive(tapefw::Drive d) override;
    bool punch_ready() override;
    void punch(std::uint8_t row) override;
    std::uint16_t status_lines() override;
    void configure(const tapefw::Config& config) override;
    void configure_emulation(const tapefw::Wiring& wiring) override;
    std::uint8_t drive_inputs() override;
    void frame_clock(std::uint32_t first_in_us) override;
    void critical(bool masked) override;

    // From the interrupt vectors.
    void on_sample_alarm();
    void on_punch_alarm();
    void on_frame_alarm();
    void on_tick_alarm();
    void on_gpio();

private:
    tapefw::Engine* engine_ = nullptr;
    tapefw::Config config_{};
    tapefw::Wiring wiring_{};
    std::uint32_t emulate_pins_ = 0;  // the X3 pins the wiring names (a mask of GPIOs)
    volatile bool punch_pulse_ = false;
    volatile std::uint8_t frame_phase_ = 0;  // 0: the slot's start, 1: strobe on, 2: strobe off
    volatile bool frame_clock_on_ = false;
    std::uint32_t slot_at_ = 0;

    void arm_alarm(unsigned alarm, std::uint32_t at);
    void set_pin(unsigned gpio, bool high);
    bool pin(unsigned gpio) const;
    void set_strobe(bool on);
    void watch_control_lines();
};

}  // namespace rp2040
