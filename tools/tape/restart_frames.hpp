// tape feed --from-block: a program restarted at a block after a tool break.
#pragma once

#include <string>
#include <vector>

#include "send.hpp"
#include "tape/frame.hpp"

namespace cli {

/// The frames to send to restart IN at block (tape/restart.hpp), encoded with the profile. With show,
/// the restart's header (program start, the rebuilt modal state, the approach) is printed on stdout instead and
/// nothing is returned. A restart refused ends the program with status 2, saying why; bad frames in an
/// image with status 1.
std::vector<tape::Frame> restart_frames(const std::string& path, const FeedProfile& p, const std::string& block,
                                        bool show, bool lathe);

}  // namespace cli
