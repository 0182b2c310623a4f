// The reads of tape restore, tape diff and tape-damage: each read whole (cli/inputs.hpp's read_tape, which
// refuses what no paper tape holds before it is held in memory), and what is said of one unrelated.
#pragma once

#include <string>
#include <vector>

#include "cli/inputs.hpp"
#include "tape/align.hpp"

namespace cli {

/// Every read, in order, each read whole by read_tape (refused beyond tape::max_tape_frames).
std::vector<TapeInput> read_all_bounded(const std::vector<std::string>& paths);

/// "shares runs of frames with r1.ptp over only 3% of the runs that occur as often in each: a read of
/// another tape, or too damaged to align": the library's refusal, naming files instead of numbers.
std::string unrelated_text(const tape::UnrelatedRead& e, const std::vector<TapeInput>& reads);

}  // namespace cli
