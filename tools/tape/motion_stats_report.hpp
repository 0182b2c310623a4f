// tape blocks --stats: the figures of a program (tape/motion_stats.hpp) in words or as JSON.
#pragma once

#include <string>

#include "cli/programs.hpp"
#include "motion_input.hpp"

namespace cli {

struct StatsArgs {
    double rapid_mm_per_min = 0;  ///< --rapid; 0: rapid time not given
    bool json = false;
};

/// Interprets IN and prints its figures per tool and in all.
void run_motion_stats(const std::string& input, const ProgramSource& source, const MotionArgs& motion,
                      const StatsArgs& args);

}  // namespace cli
