// Pictures of a tape as reads for the commands that compare reads (tape restore): each picture read by
// tape scan alone, its doubtful frames kept for the vote to weigh (picture_reads.cpp).
#pragma once

#include <string>
#include <vector>

#include "cli/inputs.hpp"
#include "tape/device.hpp"

namespace cli {

/// True when path names a picture by its extension (.png, .jpg, .jpeg, .tif, .tiff).
bool is_picture(const std::string& path);

/// A picture read as a tape, with the frames the scan doubts; what the scan says (pictures refused, the
/// doubtful frames) is said on the way. A picture that cannot be read ends the program as tape scan does.
struct PictureRead {
    TapeInput read;
    tape::FrameDoubts doubts;
};
PictureRead read_picture(const std::string& path);

/// Reads of one tape, each a tape image (read_tape, bounded) or a picture (read_picture), with the frames
/// each doubts (none for a tape image): one entry per path, in order.
struct ReadsAndDoubts {
    std::vector<TapeInput> reads;
    std::vector<tape::FrameDoubts> doubts;
};
ReadsAndDoubts read_tapes_or_pictures(const std::vector<std::string>& paths);

}  // namespace cli
