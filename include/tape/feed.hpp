// The frames a reader, a punch or a controller is sent for what the user gave: a tape image as it
// is, or a text program encoded as a tape.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/dialect.hpp"
#include "tape/encode.hpp"
#include "tape/frame.hpp"
#include "tape/input.hpp"

namespace tape {

struct FeedOptions {
    EncodeOptions encode{};  ///< how a text program is encoded (code, leader, trailer, CR LF)
    /// An image's own blank leader and trailer are replaced with encode.leader / encode.trailer
    /// blank frames only when these are set; otherwise the frames go exactly as on the tape.
    bool replace_leader = false, replace_trailer = false;
    /// A text program is sent as written unless asked: then a '%' block first when it has none and
    /// a '%' after it (the rewind stop) when it does not end with one. Never doubled.
    bool percent = false;
    /// How a text program is read: Fanuc's ';' ends of block (as manuals print them) become the
    /// code's end of block; automatic chooses from the text (guess_dialect).
    Dialect dialect = Dialect::automatic;
};

/// All frames to send for input (images by its frames, exactly as on the tape unless the leader or
/// trailer is replaced; text programs encoded). chosen, when given, receives the dialect a text
/// program was read in. Throws Error as Input and encode() do.
std::vector<Frame> frames_to_send(Input& input, const FeedOptions& options, DialectChoice* chosen = nullptr);

/// Fanuc's ';' outside comments is the end of block: dropped at the end of a line, a line break
/// within one. The text of a program as a Fanuc controller receives it.
std::string semicolons_to_line_ends(std::string_view text);

}  // namespace tape
