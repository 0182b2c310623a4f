// Pictures of a tape as reads for the commands that compare reads (tape restore): each picture read by
// tape scan alone (picture_reads.cpp).
#pragma once

#include <string>

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

}  // namespace cli
