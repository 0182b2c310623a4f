// What the adapter's protocol engine needs from a board: a clock, the USB endpoint, the reader's
// drive lines, the punch, and the status inputs. The board glue implements it for one
// microcontroller; tools/adapter_sim implements it with a simulated reader and punch.
//
// Rows come the other way: the board's sprocket interrupt samples the eight data lines
// Config::sample_delay_us after the sprocket edge and calls Engine::on_row with them as levels.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/protocol.hpp"

namespace tapefw {

enum class Drive : std::uint8_t { stop, forward, reverse };

/// What the board does in a frame slot of the emulate role (Engine::next_frame).
enum class Slot : std::uint8_t {
    frame,  ///< put the levels on the data lines and strobe them
    hold,   ///< no strobe in this slot (the host is behind): the control sees a slow reader
    stop,   ///< the control stopped (braking done) or the role ended: stop the frame clock
};

class Hardware {
public:
    /// Microseconds from any start, wrapping at 2^32 (differences are taken modulo).
    virtual std::uint32_t now_us() = 0;
    /// Queues bytes on the IN endpoint (a byte stream for CDC, one packet for HID and bulk).
    /// False when the endpoint cannot take them now; the engine tries again later.
    virtual bool send(const std::uint8_t* bytes, std::size_t n) = 0;
    /// Sets the reader's start/stop and direction lines (the board applies the polarities and the
    /// level-or-pulse form of Config; the engine only says what it wants).
    virtual void drive(Drive d) = 0;
    /// True when the punch can take a row now (its sync input, or its cycle time since the last row).
    virtual bool punch_ready() = 0;
    /// Sets the punch magnets to row for Config::punch_pulse_us and starts a cycle.
    virtual void punch(std::uint8_t row) = 0;
    /// The status inputs the board has, as status bits (tape_out, low_tape, chad_full, motor_fault, offline,
    /// punch_tape_out).
    virtual std::uint16_t status_lines() = 0;
    /// The new line settings, for the board to apply to its pins and timers.
    virtual void configure(const Config& config) = 0;

    // The emulate role (a board without it keeps these and leaves caps::emulate out). Toward the control
    // the board drives the data lines and the strobe and watches the control's drive lines; it calls
    // Engine::on_drive from the drive lines' edge interrupt and Engine::next_frame at each frame slot.

    /// The wiring and timing to apply: pins, polarities, slot timing (set-up, strobe, hold) and rate.
    virtual void configure_emulation(const Wiring& wiring) { (void)wiring; }
    /// The control's drive lines now, as drive_bit bits (polarity applied).
    virtual std::uint8_t drive_inputs() { return 0; }
    /// Starts the frame clock (a timer, or an RP2040 PIO program): a first slot first_in_us from now, then
    /// one every Wiring::period_us(), each asking Engine::next_frame, until it answers Slot::stop. A call
    /// while the clock runs re-arms it.
    virtual void frame_clock(std::uint32_t first_in_us) { (void)first_in_us; }
    /// Masks (true) and unmasks the frame clock's and drive lines' interrupts while the main loop changes
    /// the frame queue.
    virtual void critical(bool masked) { (void)masked; }

protected:
    ~Hardware() = default;
};

}  // namespace tapefw
