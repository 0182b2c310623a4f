// A simulated ФС-1501-class reader and ПЛ-150-class punch behind the adapter core's Hardware
// interface, on a virtual clock: the simulator (tape_adapter_sim.cpp) and the engine tests drive it.
//
// The reader moves tape at its rate while driven; told to stop it brakes, and the rows that pass the
// head while it brakes (the stopping distance) are still read. Driven in reverse it reads the frames
// before the head, last first. When the tape's end (or, in reverse, its start) has passed the head the
// tape-out input goes on. A torn tape is one whose sprocket holes stop at a frame: no more
// rows come, and tape-out stays off. The punch takes one row per cycle at its rate. With a control
// (SimOptions::control) the board also stands in for a reader toward it: its frame clock asks the
// engine for a frame each slot and strobes it to the control, whose start/stop line it watches.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "adapter_sim/sim_control.hpp"
#include "core/engine.hpp"
#include "core/hardware.hpp"

namespace tapesim {

struct SimOptions {
    double read_rate = 1500;                 ///< frames per second while the reader runs
    double punch_rate = 150;                 ///< rows per second the punch takes
    std::uint32_t stop_frames = 1;           ///< rows read after a stop before the tape stands
    std::uint32_t start_us = 2000;           ///< from a start to the first row (the clutch engaging)
    std::optional<std::uint64_t> torn_at{};  ///< no sprocket from this frame (0-based) on
    std::uint8_t active_low = 0;             ///< the unit's data lines that read a hole as a low level (its wiring)
    bool loop = false;                       ///< the tape the punch punches goes on into the reader (to read it back)
    bool head_at_end = false;                ///< the tape loaded with its end at the head, as after reading it through
    /// Frames (0-based) the board flags as it samples them (row_flag bits: no sprocket, timing, marginal).
    std::vector<std::pair<std::uint64_t, std::uint8_t>> row_flags{};
    std::vector<std::uint64_t> miss_hole_at{};  ///< rows N (from 1) punched with their lowest hole missing (a worn pin)
    std::optional<ControlOptions> control{};    ///< a control reading from the adapter (the emulate role)
};

class SimHardware final : public tapefw::Hardware {
public:
    SimHardware(std::vector<std::uint8_t> tape, SimOptions options);

    /// Where the engine's packets go; false means the endpoint is busy now.
    std::function<bool(const std::uint8_t*, std::size_t)> on_send{};

    /// Moves the virtual clock to t microseconds, giving the engine every row read until then.
    void advance_to(std::uint64_t t, tapefw::Engine& engine);
    /// The next moment something happens on its own (a row, a punch cycle), for a caller that sleeps.
    std::uint64_t next_event() const;
    std::uint64_t now() const { return now_; }

    /// Status inputs set from outside (chad box full, off-line, ...), as status bits.
    std::uint16_t forced_status = 0;

    const std::vector<std::uint8_t>& punched() const { return punched_; }
    std::uint64_t position() const { return position_; }
    tapefw::Drive drive_state() const { return drive_; }
    const tapefw::Config& config() const { return config_; }
    std::uint64_t starts() const { return starts_; }
    /// Rows punched more than one and a half punch cycles after the row before: the punch stood idle
    /// for want of a row (the queue ran dry), and the longest such wait, on the virtual clock.
    std::uint64_t late_punches() const { return late_punches_; }
    /// Called after each Engine::poll: a punch still ready then had no row queued (the engine punches
    /// whenever it is ready and has one). A row punched after such a poll counts as an underrun: the
    /// punch waited for the host, not for the simulator's clock.
    void after_poll();
    std::uint64_t underruns() const { return underruns_; }
    std::uint64_t longest_punch_gap_us() const { return longest_punch_gap_us_; }

    std::uint32_t now_us() override { return static_cast<std::uint32_t>(now_); }
    bool send(const std::uint8_t* bytes, std::size_t n) override { return on_send ? on_send(bytes, n) : true; }
    void drive(tapefw::Drive d) override;
    bool punch_ready() override;
    void punch(std::uint8_t row) override;
    std::uint16_t status_lines() override;
    void configure(const tapefw::Config& config) override { config_ = config; }
    void configure_emulation(const tapefw::Wiring& wiring) override { wiring_ = wiring; }
    std::uint8_t drive_inputs() override { return control_ ? control_->lines() : 0; }
    void frame_clock(std::uint32_t first_in_us) override;

    /// The control reading from the adapter, when there is one.
    const SimControl* control() const { return control_ ? &*control_ : nullptr; }
    const tapefw::Wiring& wiring() const { return wiring_; }

private:
    std::vector<std::uint8_t> tape_;
    SimOptions o_;
    std::uint64_t now_ = 0;
    std::uint64_t period_us_, punch_period_us_;
    tapefw::Drive drive_ = tapefw::Drive::stop;
    std::uint64_t position_ = 0;      ///< the next frame to pass the head
    std::uint64_t next_row_at_ = 0;   ///< when it passes, while moving
    std::uint32_t braking_left_ = 0;  ///< rows still to pass while braking
    bool moving_ = false;
    bool backwards_ = false;  ///< the way the tape moves (or last moved)
    std::uint64_t last_punch_ = 0;
    bool punched_once_ = false;
    std::vector<std::uint8_t> punched_;
    tapefw::Config config_{};
    std::uint64_t starts_ = 0;
    std::uint64_t late_punches_ = 0, longest_punch_gap_us_ = 0, underruns_ = 0;
    bool punch_idle_ = false;
    std::optional<SimControl> control_;
    tapefw::Wiring wiring_{};
    bool clock_on_ = false;
    std::uint64_t next_slot_at_ = 0;
    /// The control's line changes and the frame slots due by t, in time order.
    void run_control(std::uint64_t t, tapefw::Engine& engine);
    void read_rows(std::uint64_t t, tapefw::Engine& engine);
    std::map<std::uint64_t, std::uint8_t> row_flags_;  ///< o_.row_flags by frame, ORed: looked up every row
    const std::vector<std::uint8_t>& reader_tape() const { return o_.loop ? punched_ : tape_; }
};

}  // namespace tapesim
