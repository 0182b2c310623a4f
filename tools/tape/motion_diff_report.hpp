// tape diff --motion: two programs (text or tape, any dialects) compared by their toolpaths
// (tape/motion_diff.hpp).
#pragma once

#include <string>

#include "cli/programs.hpp"
#include "motion_input.hpp"

namespace cli {

/// Prints "same toolpath" (return) or the first piece that differs with its block in each (exit 1).
void run_motion_diff(const std::string& first, const std::string& second, const ProgramSource& source,
                     const MotionArgs& motion, double tolerance_mm);

}  // namespace cli
