#include "sim_control.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace tapesim {

SimControl::SimControl(ControlOptions options)
    : o_(options),
      rng_(options.seed),
      run_(options.running),
      stops_left_(options.stops),
      period_us_(static_cast<std::uint64_t>(std::llround(1e6 / options.rate))) {
    if (stops_left_) next_stop_at_ = uniform(1, 2000);
}

std::uint64_t SimControl::uniform(std::uint64_t lo, std::uint64_t hi) {
    return std::uniform_int_distribution<std::uint64_t>(lo, hi)(rng_);
}

std::uint8_t SimControl::change(std::uint64_t t) {
    if (t < next_change_) return lines();
    next_change_ = UINT64_MAX;
    run_ = !run_;
    if (run_) {
        started_at_ = t;
        strobed_since_start_ = false;
        ++restarts_;
    } else {
        after_stop_.push_back(0);
        next_change_ = t + pending_pause_us_;
    }
    return lines();
}

void SimControl::stop_at(std::uint64_t t, std::uint64_t pause_us) {
    next_change_ = t;
    pending_pause_us_ = pause_us;
}

void SimControl::strobe(std::uint64_t t, std::uint8_t frame, std::uint64_t slot_us) {
    taken_.push_back(frame);
    if (!run_) {
        if (!after_stop_.empty()) ++after_stop_.back();
    } else if (!strobed_since_start_) {
        if (restarts_) longest_restart_us_ = std::max(longest_restart_us_, t - started_at_);
        strobed_since_start_ = true;
    } else {
        longest_gap_us_ = std::max(longest_gap_us_, t - last_strobe_);
    }
    last_strobe_ = t;
    bool program_end = program_.feed(static_cast<char>(frame & 0x7F)) == tape::ProgramEndWatch::Event::program_end;
    if (!run_ || next_change_ != UINT64_MAX) return;
    // The program's end, a planned stop on this frame, or no room yet for the next one (a control slower
    // than the reader).
    if (program_end && o_.stop_at_program_end) {
        stop_at(t + o_.reaction_us, uniform(o_.pause_min_us, o_.pause_max_us));
    } else if (next_stop_at_ && taken_.size() >= next_stop_at_) {
        --stops_left_;
        next_stop_at_ = stops_left_ ? taken_.size() + uniform(1, 2000) : 0;
        stop_at(t + o_.reaction_us, uniform(o_.pause_min_us, o_.pause_max_us));
    } else if (period_us_ > slot_us + 1) {  // not just the rounding of two equal rates
        stop_at(t + o_.reaction_us, period_us_ - o_.reaction_us);
    }
}

std::string SimControl::stats_json() const {
    nlohmann::json j = {{"frames", taken_.size()},
                        {"stops", after_stop_.size()},
                        {"frames_after_stop", after_stop_},
                        {"longest_gap_us", longest_gap_us_},
                        {"longest_restart_us", longest_restart_us_},
                        {"restarts", restarts_}};
    return j.dump();
}

}  // namespace tapesim
