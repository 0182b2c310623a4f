// tape-adapter-sim's command-line options: the adapter as built, and the faults it injects.
#include <CLI/CLI.hpp>

#include "adapter_sim/sim_args.hpp"
#include "cli/numbers.hpp"

namespace tapesim {

// The adapter as built: what it holds, its line and its clock.
void add_unit_options(CLI::App& app, SimArgs& a) {
    using cli::real_number;
    using cli::whole_number;
    app.add_option("--reader", a.reader, "Tape image in the reader (any format); without it the reader has no tape");
    app.add_option("--punch", a.punch, "Raw image file the punch punches into (rows appended as punched)");
    app.add_option("--serial", a.serial, "The adapter's serial string")->capture_default_str();
    app.add_option("--link", a.link, "Also make a symbolic link PATH to the pseudo-terminal");
    app.add_option("--speed", a.speed, "Run the simulated clock this many times faster than real time")
        ->check(real_number(0.01, 1000))
        ->capture_default_str();
    app.add_option("--read-rate", a.read_rate, "Frames per second the reader reads")
        ->check(real_number(1, 60000))
        ->capture_default_str();
    app.add_option("--punch-rate", a.punch_rate, "Rows per second the punch punches")
        ->check(real_number(1, 60000))
        ->capture_default_str();
    app.add_option("--stop-frames", a.stop_frames, "Frames that pass the head while the reader brakes")
        ->check(whole_number(0, 100))
        ->capture_default_str();
    app.add_flag(
           "--loop", a.loop,
           "The punched tape goes on into the reader, which reads it back (tape punch --verify); not with --reader")
        ->excludes("--reader");
    app.add_option("--control", a.control,
                   "A control reads through the adapter standing in for its tape reader (tape emulate); every "
                   "frame it takes is appended to this raw image file");
    app.add_option("--control-rate", a.control_rate,
                   "Frames per second the control can take; slower than the reader's rate, it stops the reader "
                   "after each frame")
        ->check(real_number(1, 60000))
        ->capture_default_str();
    app.add_option("--control-stops", a.control_stops,
                   "The control stops the reader N times at random frames (1 to 2000 frames apart) and starts it "
                   "again after a random 2 to 30 ms")
        ->check(whole_number(0, 1'000'000'000));
    app.add_option("--control-seed", a.control_seed, "Seed of the control's random stops")
        ->check(whole_number(0, 4'294'967'295))
        ->capture_default_str();
    app.add_option("--control-rewind-after", a.control_rewind_after,
                   "Once, after taking N frames, the control stops, rewinds (its rewind line on and off) and starts "
                   "again")
        ->check(whole_number(1, 1'000'000'000));
    app.add_option("--control-reverse-after", a.control_reverse_after,
                   "Once, after taking N frames, the control reads backwards for --control-reverse-frames frames, "
                   "then forwards again")
        ->check(whole_number(1, 1'000'000'000));
    app.add_option("--control-reverse-frames", a.control_reverse_frames, "Frames the control reads backwards")
        ->check(whole_number(1, 1'000'000'000))
        ->capture_default_str();
    app.add_flag("--no-reader", a.no_reader, "An adapter with a punch only");
    app.add_flag("--no-punch", a.no_punch, "An adapter with a reader only");
    app.add_flag("--no-reverse", a.no_reverse, "A reader that cannot read backwards");
    app.add_flag("--at-end", a.at_end,
                 "The tape is loaded with its end at the head, as after reading it through: read it back with "
                 "direction=reverse");
}

// Faults of the tape, the units and the line, each at a frame or packet named.
void add_fault_options(CLI::App& app, SimArgs& a) {
    using cli::whole_number;
    constexpr std::uint64_t most = 1'000'000'000;
    app.add_option("--no-sprocket-at", a.no_sprocket_at,
                   "Frame N (from 1) is read without its sprocket hole, sampled by time, and flagged so "
                   "(repeatable)")
        ->check(whole_number(1, most));
    app.add_option("--mistimed-at", a.mistimed_at,
                   "Frame N's sprocket hole comes early or late, and the row is flagged so (repeatable)")
        ->check(whole_number(1, most));
    app.add_option("--marginal-at", a.marginal_at,
                   "A track of frame N reads near its threshold, and the row is flagged so (repeatable)")
        ->check(whole_number(1, most));
    app.add_option("--unplug-after", a.unplug_after,
                   "Unplug (hang the line up and end) after N frames read, or taken by the control")
        ->check(whole_number(1, most));
    app.add_option("--torn-at", a.torn_at, "The tape is torn after N frames: no sprocket hole from there")
        ->check(whole_number(0, most))
        ->each([&a](const std::string&) { a.torn = true; });
    app.add_option("--chad-full-after", a.chad_full_after, "The chad box is full after N rows punched")
        ->check(whole_number(1, most));
    app.add_option("--miss-hole-at", a.miss_hole_at,
                   "Row N (from 1) is punched with its lowest hole missing (repeatable: several rows)")
        ->check(whole_number(1, most));
    app.add_option("--active-low", a.active_low,
                   "The unit's data lines that are low for a hole (a mask, bit n for track n+1): tape adapter "
                   "config --invert must say the same for true rows")
        ->check(whole_number(0, 255));
    app.add_option("--garbage-every", a.faults.garbage_every,
                   "Before every K-th ROWS packet, a desync on the line: noise, or half a packet, in turn")
        ->check(whole_number(1, most));
    app.add_flag(
        "--stats", a.stats,
        "At the end, print on stderr the tape's position, rows punched, punch underruns and late cycles, desyncs "
        "injected, bad packets from the host and the line settings in force; with --control, then a JSON line: "
        "frames taken, frames_after_stop (for each stop), longest_gap_us, longest_restart_us, restarts");
    app.add_option("--drop-taken-every", a.faults.drop_taken_every,
                   "Lose every K-th TAKEN packet on the way to the host (emulating)")
        ->check(whole_number(1, most));
    app.add_option("--drop-packet", a.faults.drop_rows_packet, "Do not send the K-th ROWS packet (from 1)")
        ->check(whole_number(1, most));
    app.add_option("--drop-times", a.faults.drop_times,
                   "...nor its resends: N sendings dropped in all (a large N: frames lost for good)")
        ->check(whole_number(1, most))
        ->capture_default_str();
    app.add_option("--duplicate-packet", a.faults.duplicate_rows_packet, "Send the K-th ROWS packet twice")
        ->check(whole_number(1, most));
    app.add_option("--corrupt-packet", a.faults.corrupt_rows_packet,
                   "Damage a byte of the K-th ROWS packet (the host sees a CRC failure)")
        ->check(whole_number(1, most));
    app.add_option("--corrupt-times", a.faults.corrupt_times, "...and of its resends: N sendings damaged in all")
        ->check(whole_number(1, most))
        ->capture_default_str();
    app.add_option("--protocol", a.faults.protocol, "Claim this protocol version in INFO (to try a mismatch)")
        ->check(whole_number(0, 255));
}

}  // namespace tapesim
