// Encoding: a text program -> frames, with blank leader and trailer.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/charset.hpp"
#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/frame.hpp"

namespace tape {

inline constexpr std::size_t default_leader = 100;  ///< blank frames, 254 mm of tape
inline constexpr std::size_t default_trailer = 100;
/// The longest blank leader or trailer: 100 000 frames, 254 m of tape. A larger count is a mistake
/// (a negative number wrapped round, say), not a tape.
inline constexpr std::size_t max_blank_frames = 100000;

struct EncodeOptions {
    Code code = Code::iso;
    Parity parity = Parity::even;      ///< ISO only
    Charset charset = Charset::ascii;  ///< ISO only: МТК-2 has its own Russian register
    std::size_t leader = default_leader;
    std::size_t trailer = default_trailer;
    bool crlf = false;                     ///< CR LF on tape at the end of each block (ISO; 5-track always)
    const CodeTable* eia_table = nullptr;  ///< a corrected EIA table; nullptr = built-in
    /// Punched into the leader as letters of holes (tape/label.hpp), label_blank_around frames from its
    /// start; empty: none. The leader keeps its length, so the program starts at the same frame.
    std::string label{};
};

/// Each text line is a block: LF or CR LF in the text, LF (EIA: EOB) on tape. A UTF-8 byte-order
/// mark at the start of the text is skipped, and so are DOS end-of-file marks (Ctrl-Z) at its end;
/// one with text after it is the character SUB.
/// Throws Error(Errc::bad_text) naming line and column of the first character the code cannot carry,
/// Error(Errc::usage) for a leader or trailer over max_blank_frames, for a label the font cannot draw or
/// a leader too short to hold it with label_blank_around blank frames each side (the message says how long).
/// 5-track codes (ITA2, МТК-2): a line ends with CR LF on tape, as teleprinters need; a shift frame
/// stands before the first character that needs a register and wherever the register changes, so a
/// reader in any state reads the tape right. The codes have no case: lower-case letters are punched as
/// capitals (and read back so). Error(Errc::usage) for a parity or character set with a 5-track code.
/// The Elliott telecodes punch each character at its value, a table's alias at the value it stands for.
std::vector<Frame> encode(std::string_view text, const EncodeOptions& options);

/// The same, a chunk at a time, in bounded memory: the text may be cut anywhere (inside a UTF-8
/// character or between CR and LF); the КОИ-7 shift and line/column for messages carry over, so the
/// frames are the same however the text is cut. The leader comes with the first frames, the trailer
/// from finish(). Throws as encode() does.
class Encoder {
public:
    explicit Encoder(const EncodeOptions& options);
    /// Appends the frames for the next piece of text to out.
    void feed(std::string_view text, std::vector<Frame>& out);
    /// Appends what was held back, the closing SI of КОИ-7 text, and the trailer.
    void finish(std::vector<Frame>& out);
    /// True once a UTF-8 byte-order mark at the start of the text was skipped.
    bool skipped_byte_order_mark() const { return skipped_bom_; }
    /// After finish(): where the DOS end-of-file marks (Ctrl-Z) that ended the text stood, unpunched.
    const std::optional<Position>& skipped_end_of_file_mark() const { return skipped_marks_; }

private:
    void encode_piece(std::string_view text, std::vector<Frame>& out);
    void to_seven_bit(std::string_view text);
    void encode_five_track(std::string_view text, std::vector<Frame>& out);  // encode_five_track.cpp
    void encode_telecode(std::string_view text, std::vector<Frame>& out);    // encode_telecode.cpp

    EncodeOptions options_;
    FrameCode code_;
    bool plain_iso_;  ///< ISO, even parity, ASCII, no CR LF on tape: the one-pass path applies
    bool leader_done_ = false;
    bool cyrillic_ = false;
    int register_ = -1;     ///< 5-track: the register the last shift frame chose; -1 before the first
    bool at_start_ = true;  ///< nothing of the text taken yet: a byte-order mark may come
    bool skipped_bom_ = false;
    std::string held_;            ///< an unfinished character or CR from the end of the last chunk
    std::size_t held_marks_ = 0;  ///< DOS end-of-file marks that ended the text so far
    std::optional<Position> skipped_marks_;
    Position position_{.line = 1, .column = 1};  ///< of the next byte, for messages
    std::string converted_;
    std::vector<std::size_t> origin_;
    std::vector<Frame> label_;  ///< the label's frames, punched into the leader
};

/// The hot loop: 7-bit characters -> frames into out (room for chars.size() frames).
/// Returns the index of the first character the code cannot carry, or chars.size().
std::size_t encode_run(const FrameCode& code, std::string_view chars, Frame* out);

}  // namespace tape
