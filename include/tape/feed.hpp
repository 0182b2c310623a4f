// The frames a reader, a punch or a controller is sent for what the user gave: a tape image as it
// is, or a text program encoded as a tape.
#pragma once

#include <optional>
#include <vector>

#include "tape/encode.hpp"
#include "tape/frame.hpp"
#include "tape/input.hpp"

namespace tape {

struct FeedOptions {
    EncodeOptions encode{};  ///< how a text program is encoded (code, leader, trailer, CR LF)
    /// An image's own blank leader and trailer are replaced with encode.leader / encode.trailer
    /// blank frames only when these are set; otherwise the frames go exactly as on the tape.
    bool replace_leader = false, replace_trailer = false;
    bool percent_first = true;  ///< a text program without '%' first gets a '%' block
    bool percent_end = true;    ///< a '%' after the program (the rewind stop)
};

/// All frames to send for input (images by its frames, text programs encoded). Throws Error as
/// Input and encode() do.
std::vector<Frame> frames_to_send(Input& input, const FeedOptions& options);

}  // namespace tape
