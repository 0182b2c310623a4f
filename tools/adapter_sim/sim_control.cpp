#include "sim_control.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace tapesim {

SimControl::SimControl(ControlOptions options)
    : o_(options),
      rng_(options.seed),
      lines_(options.running ? 1 : 0),
      stops_left_(options.stops),
      period_us_(static_cast<std::uint64_t>(std::llround(1e6 / options.rate))) {
    if (stops_left_) next_stop_at_ = uniform(1, 2000);
}

std::uint64_t SimControl::uniform(std::uint64_t lo, std::uint64_t hi) {
    return std::uniform_int_distribution<std::uint64_t>(lo, hi)(rng_);
}

std::uint8_t SimControl::change(std::uint64_t t) {
    if (t < next_change_) return lines();
    bool was_running = running();
    lines_ = next_lines_;
    next_change_ = UINT64_MAX;
    if (!steps_.empty()) {
        next_change_ = t + steps_.front().first;
        next_lines_ = steps_.front().second;
        steps_.pop_front();
    }
    if (running() && !was_running) {
        started_at_ = t;
        strobed_since_start_ = false;
        ++restarts_;
    } else if (!running() && was_running) {
        after_stop_.push_back(0);
    }
    return lines();
}

void SimControl::plan(std::uint64_t t, std::uint8_t lines, std::deque<std::pair<std::uint64_t, std::uint8_t>> steps) {
    next_change_ = t;
    next_lines_ = lines;
    steps_ = std::move(steps);
}

void SimControl::stop_at(std::uint64_t t, std::uint64_t pause_us) {
    std::uint8_t stopped = static_cast<std::uint8_t>(lines_ & ~1);
    plan(t, stopped, {{pause_us, static_cast<std::uint8_t>(stopped | 1)}});
}

bool SimControl::plan_turn(std::uint64_t t) {
    constexpr std::uint8_t run = 1, reverse = 2, rewind = 4;
    std::uint64_t n = taken_.size();
    std::uint64_t at = t + o_.reaction_us;
    if (o_.rewind_after && n >= o_.rewind_after && !rewound_) {
        rewound_ = true;
        plan(at, 0, {{1000, rewind}, {1000, 0}, {1000, run}});
    } else if (o_.reverse_after && n >= o_.reverse_after && !reversed_) {
        reversed_ = true;
        reverse_left_ = o_.reverse_frames;
        plan(at, 0, {{1000, reverse}, {1000, reverse | run}});
    } else if (reverse_left_ && --reverse_left_ == 0) {
        plan(at, reverse, {{1000, 0}, {1000, run}});
    } else {
        return false;
    }
    return true;
}

void SimControl::strobe(std::uint64_t t, std::uint8_t frame, std::uint64_t slot_us) {
    taken_.push_back(frame);
    if (!running()) {
        if (!after_stop_.empty()) ++after_stop_.back();
    } else if (!strobed_since_start_) {
        if (restarts_) longest_restart_us_ = std::max(longest_restart_us_, t - started_at_);
        strobed_since_start_ = true;
    } else {
        longest_gap_us_ = std::max(longest_gap_us_, t - last_strobe_);
    }
    last_strobe_ = t;
    bool program_end = program_.feed(static_cast<char>(frame & 0x7F)) == tape::ProgramEndWatch::Event::program_end;
    if (!running() || next_change_ != UINT64_MAX || plan_turn(t)) return;
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
