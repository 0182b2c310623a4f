// The reads of tape restore, tape diff and tape-damage: each read whole, named by its file, and refused above the
// frames any paper tape holds (tape::max_read_frames) before it is held in memory.
#pragma once

#include <string>
#include <vector>

#include "cli/inputs.hpp"
#include "tape/align.hpp"

namespace cli {

/// READ read whole as a tape image ("-": standard input), in format_id (empty: by extension or content).
/// A file of more than tape::max_read_frames frames is refused (bad data) with a message saying the
/// limit: a raw image by its size before it is read, any other as soon as it passes the limit.
TapeInput read_bounded(const std::string& path, const std::string& format_id = "");

/// Every read, in order.
std::vector<TapeInput> read_all_bounded(const std::vector<std::string>& paths);

/// "shares runs of frames with r1.ptp over only 3% of the runs that occur as often in each: a read of
/// another tape, or too damaged to align": the library's refusal, naming files instead of numbers.
std::string unrelated_text(const tape::UnrelatedRead& e, const std::vector<TapeInput>& reads);

}  // namespace cli
