// A simulated control reading through its tape-reader input, for the adapter's emulate role: it drives
// the start/stop line, takes a frame at every strobe, and stops the reader now and then (at random
// frames, or whenever it cannot keep up with the reader's rate), restarting after a pause. It keeps
// every frame it took and what a user of the role must be able to trust: the frames that came after
// each stop, the longest gap between strobes while it wanted frames, and the time from each restart to
// its first strobe.
#pragma once

#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include "tape/line_state.hpp"

namespace tapesim {

struct ControlOptions {
    double rate = 1500;                  ///< frames per second it can take; slower than the reader: start-stop
    std::uint64_t stops = 0;             ///< stops at random frames (1 to 2000 frames apart), then none
    std::uint32_t pause_min_us = 2000;   ///< a stop lasts from this...
    std::uint32_t pause_max_us = 30000;  ///< ...to this
    std::uint32_t reaction_us = 20;      ///< from the strobe of the frame it stops on to its stop line
    std::uint32_t seed = 1;
    bool running = true;  ///< asks for frames from the start
    /// Stops at the end of a program (the block with M02/M30, read as ISO 7-bit) and starts again after a
    /// pause, as a machinist's next cycle start: the program is read again from its '%'.
    bool stop_at_program_end = true;
    /// Once, after taking this many frames (0: never): stops, rewinds (its rewind line on and off) and
    /// starts again.
    std::uint64_t rewind_after = 0;
    /// Once, after taking this many frames (0: never): stops, turns the reader backwards for
    /// reverse_frames frames, stops, and reads forwards again.
    std::uint64_t reverse_after = 0;
    std::uint64_t reverse_frames = 10;
};

class SimControl {
public:
    explicit SimControl(ControlOptions options);

    /// Its drive lines now (tapefw::drive_bit: run when it wants frames, reverse, rewind).
    std::uint8_t lines() const { return lines_; }
    /// When its lines change next on their own (a stop or a restart due), or UINT64_MAX.
    std::uint64_t next_change() const { return next_change_; }
    /// Changes its lines as due at time t; the new lines.
    std::uint8_t change(std::uint64_t t);
    /// A strobe at time t with the frame on the data lines; the reader's slots come every slot_us.
    void strobe(std::uint64_t t, std::uint8_t frame, std::uint64_t slot_us);

    const std::vector<std::uint8_t>& taken() const { return taken_; }
    /// The frames strobed after each stop, before the next start.
    const std::vector<std::uint32_t>& frames_after_stop() const { return after_stop_; }
    std::uint64_t longest_gap_us() const { return longest_gap_us_; }
    std::uint64_t longest_restart_us() const { return longest_restart_us_; }
    std::uint64_t restarts() const { return restarts_; }
    /// Its findings as one JSON object.
    std::string stats_json() const;

private:
    ControlOptions o_;
    std::mt19937 rng_;
    std::uint8_t lines_;
    std::uint64_t next_change_ = UINT64_MAX;
    /// Line changes to come after the next one: each its delay after the one before, and the lines.
    std::deque<std::pair<std::uint64_t, std::uint8_t>> steps_;
    std::uint8_t next_lines_ = 0;              ///< the lines at next_change_
    std::uint64_t reverse_left_ = 0;           ///< frames still to read backwards
    bool rewound_ = false, reversed_ = false;  ///< the planned turns done
    std::uint64_t stops_left_;
    std::uint64_t next_stop_at_ = 0;  ///< stops after taking this many frames (0: no planned stop)
    std::uint64_t period_us_;
    std::vector<std::uint8_t> taken_;
    std::vector<std::uint32_t> after_stop_;
    std::uint64_t last_strobe_ = 0, started_at_ = 0, longest_gap_us_ = 0, longest_restart_us_ = 0, restarts_ = 0;
    bool strobed_since_start_ = false;
    tape::ProgramEndWatch program_;
    std::uint64_t uniform(std::uint64_t lo, std::uint64_t hi);
    bool running() const { return (lines_ & 1) != 0; }
    /// Lines at t, then the steps after it.
    void plan(std::uint64_t t, std::uint8_t lines, std::deque<std::pair<std::uint64_t, std::uint8_t>> steps);
    void stop_at(std::uint64_t t, std::uint64_t pause_us);
    /// A planned turn (rewind or reverse) due after this frame, planned; false when none.
    bool plan_turn(std::uint64_t t);
};

}  // namespace tapesim
