// The frames a reader, a punch or a controller is sent for what the user gave: a tape image as it
// is, or a text program encoded as a tape.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/dialect.hpp"
#include "tape/dnc.hpp"
#include "tape/encode.hpp"
#include "tape/frame.hpp"
#include "tape/input.hpp"
#include "tape/limits.hpp"

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

/// The frames to send for input, a chunk at a time: an image's frames as they are read, exactly as on
/// the tape unless the leader or trailer is replaced (only a run of blank frames is held back, to see
/// whether it is the trailer), so a tape of any length is sent in bounded memory; a text program read
/// whole (it is a program, not a tape: max_text_bytes at most) and encoded. chosen, when given, receives
/// the dialect a text program was read in. input must outlive the source. Throws Error as Input and
/// encode() do, and Error(Errc::bad_text) for a text longer than max_text_bytes.
std::unique_ptr<FrameSource> feed_source(Input& input, const FeedOptions& options, DialectChoice* chosen = nullptr);

/// The most text a program sent as text may have: as many characters as the longest tape has frames.
inline constexpr std::uint64_t max_text_bytes = max_tape_frames;

/// All frames of feed_source, in memory.
std::vector<Frame> frames_to_send(Input& input, const FeedOptions& options, DialectChoice* chosen = nullptr);

/// Fanuc's ';' outside comments is the end of block: dropped at the end of a line, a line break
/// within one. The text of a program as a Fanuc controller receives it.
std::string semicolons_to_line_ends(std::string_view text);

}  // namespace tape
