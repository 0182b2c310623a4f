// Decoding: frames -> characters, with every bad frame reported by its frame number.
#pragma once

#include <array>
#include <cstdint>
#include <map>
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

/// Put in the text, with --keep-going, where a frame could not be read: U+FFFD REPLACEMENT CHARACTER.
/// It is no ISO character, so a marked text cannot be punched again by mistake.
inline constexpr std::string_view bad_frame_marker = "\xEF\xBF\xBD";

/// The line ends of decoded text, taken a piece at a time: its LFs, and how many of them follow a CR
/// (a tape punched with CR LF, which `encode --crlf` punches again).
struct LineEnds {
    std::uint64_t lines = 0, crlf = 0;
    bool after_cr = false;  ///< the last piece ended with a CR

    void take(std::string_view text);
    /// The same for a piece whose LFs were counted already.
    void take(std::string_view text, std::uint64_t newlines);
};

struct DecodeOptions {
    Code code = Code::iso;
    Parity parity = Parity::even;          ///< ISO only; EIA parity is fixed (odd, track 5), 5-track has none
    Charset charset = Charset::ascii;      ///< ISO only: МТК-2 has its own Russian register
    bool keep_going = false;               ///< report every bad frame instead of stopping at the first
    bool unshift_on_space = false;         ///< ITA2: a space returns the reader to letters, as on many teleprinters
    bool positions = false;                ///< fill DecodeResult::frame_of
    std::size_t max_diagnostics = 0;       ///< keep at most this many of each kind, count the rest (0: all)
    const CodeTable* eia_table = nullptr;  ///< a corrected EIA table; nullptr = built-in
};

struct DecodeResult {
    std::string text;                        ///< the characters, UTF-8; LF ends a block
    std::vector<std::uint64_t> frame_of;     ///< with positions: 0-based frame index of each byte of text
    std::vector<Diagnostic> diagnostics;     ///< one per bad frame, and a warning (Errc::blank_frame) per run of
                                             ///< blank frames inside a block, in tape order, up to
                                             ///< max_diagnostics a kind
    std::map<Errc, std::uint64_t> unlisted;  ///< bad frames beyond max_diagnostics, by kind
    bool complete = true;                    ///< false when decoding stopped at the first bad frame

    bool ok() const { return diagnostics.empty(); }
};

/// Decodes a whole tape. Blank frames and DEL are skipped; blank frames between a printable character
/// and the next character of the same block (not after a control), and more blank frames at a block's
/// start than the tape's habit after its ends of block (when 9 in 10 of at least 8 agree), give a
/// warning Diagnostic (Errc::blank_frame) at the first of them: a character whose holes were all lost
/// reads as blank tape (EIA's one-hole 0 1 2 4 8 - and space). Each frame that fails the parity rule
/// or is no character of the code gives a Diagnostic (Errc::parity / Errc::not_in_code) with its
/// frame and its line (= block: LFs decoded before it, plus one) and stops
/// the decoding unless keep_going, in which case the frame is marked in the text.
/// 5-track codes follow their shifts (the letters register first): CR LF (CR CR LF) reads as one LF,
/// any other CR as CR; a frame with tracks 6-8 punched, or one with no agreed character in its
/// register (ITA2's national figures), is Errc::not_in_code. The Elliott telecodes give their own
/// characters (£, º, ⑩). Throws Error(Errc::usage) for a parity or character set given with a 5-track
/// code or a telecode, and for unshift_on_space with another code than ITA2.
DecodeResult decode(std::span<const Frame> frames, const DecodeOptions& options);

/// The same, a chunk at a time, in bounded memory: frame numbers, the КОИ-7 shift, the 5-track
/// register and the message limit carry over between chunks, so the result is the same however the tape
/// is cut. Call finish() after the last frames.
class Decoder {
public:
    /// Throws Error(Errc::usage) for options that do not go together (a parity with a 5-track code).
    explicit Decoder(const DecodeOptions& options);

    /// Decodes the next frames, appending to out.text (and out.frame_of with positions, counted from
    /// the start of the tape) and out.diagnostics. The caller may empty out between calls. Returns
    /// false once decoding has stopped at a bad frame (without keep_going); later calls take nothing.
    bool feed(std::span<const Frame> frames, DecodeResult& out);
    /// The tape has ended: appends what was held back (a 5-track CR that an LF might have followed).
    void finish(DecodeResult& out);

    /// How the tape ended, after finish(): one warning when its last character is no line or block end
    /// (LF, CR, another control, '%', a telecode's halt), so that it may have been cut inside a block,
    /// or when its last frame is punched (no blank trailer), or both. Empty for a tape that ends well.
    std::vector<Diagnostic> ending() const;

    std::uint64_t frames_seen() const { return next_index_; }
    /// The line ends of the text decoded so far, however the caller cut or emptied it.
    const LineEnds& line_ends() const { return line_ends_; }
    /// The line (= block) the next character stands in: LFs decoded so far, plus one; nullopt for the
    /// 5-track codes, whose lines are not counted.
    std::optional<std::uint64_t> line() const {
        return code_.five_track_table() ? std::nullopt : std::optional<std::uint64_t>(lines_ + 1);
    }
    /// Bad frames in all, listed or not.
    std::uint64_t bad_frames() const { return parity_seen_ + other_seen_; }
    /// Bad frames beyond max_diagnostics, by kind.
    std::map<Errc, std::uint64_t> unlisted() const;

private:
    void note_bad(Frame f, std::uint64_t index, std::uint64_t line, DecodeResult& out);
    void finish_text(DecodeResult& out, std::size_t from, std::size_t positions_from);
    struct ChunkStart {  // where a chunk's text, positions and findings begin in the result
        std::size_t text = 0, positions = 0, diagnostics = 0;
    };
    void settle_chunk(DecodeResult& out, ChunkStart at, bool marked);
    std::size_t decode_with_positions(std::span<const Frame> frames, DecodeResult& out, bool& marked);
    std::size_t decode_runs(std::span<const Frame> frames, DecodeResult& out, bool& marked);
    bool feed_five_track(std::span<const Frame> frames, DecodeResult& out);  // decode_five_track.cpp
    void put_held_cr(DecodeResult& out);
    void put_text(std::string_view text, std::uint64_t index, DecodeResult& out);
    void five_track_bad(Frame f, std::uint64_t index, const std::string& what, DecodeResult& out);
    void note_trailer(std::span<const Frame> frames);  // decode_ending.cpp
    void note_blanks(std::span<const Frame> frames, std::uint64_t base, DecodeResult& out);
    void punched_stretch(std::span<const Frame> stretch, DecodeResult& out);
    std::size_t next_end_of_block(std::span<const Frame> stretch, std::size_t from) const;
    void after_blanks(Frame f, FrameKind kind, DecodeResult& out);
    bool habit_is_no_blank() const;
    std::optional<std::uint8_t> habit() const;
    void block_start_blanks(DecodeResult& out);
    void blank_run(std::uint64_t from, std::uint64_t n, const std::string& where, DecodeResult& out);

    DecodeOptions options_;
    FrameCode code_;
    std::uint64_t next_index_ = 0;
    std::uint64_t parity_seen_ = 0, other_seen_ = 0, blank_runs_seen_ = 0;
    // Blank tape after a printable character or an end of block, waiting for the frame after it; the
    // blank frames this tape put after its last 16 ends of block, its habit; and a run longer than the
    // habit, waiting for two more blocks to keep it.
    enum class Before { nothing, printable, end_of_block } before_blanks_ = Before::nothing;
    Before state_after(Frame f) const;  // what a frame leaves before the blank tape after it
    std::array<bool, 256> rubout_{};    // per frame value: DEL, which the blank-in-block report skips
    int end_of_block_frame_ = -1;       // the one frame that ends a block, or < 0
    std::uint64_t blank_from_ = 0, blank_frames_ = 0;
    std::array<std::uint8_t, 16> habit_{};
    std::size_t habit_seen_ = 0;
    struct Suspect {
        std::uint64_t from = 0, frames = 0, usual = 0;
        int kept = 0;
    } suspect_;
    std::uint64_t lines_ = 0;  // LFs decoded so far: a bad frame stands in line lines_ + 1
    LineEnds line_ends_;
    bool cyrillic_ = false;
    bool stopped_ = false;
    std::uint64_t trailer_ = 0;                  // blank frames since the last punched one
    std::optional<std::uint64_t> last_punched_;  // 0-based index of the last punched frame
    std::optional<char> last_char_;              // the last character decoded
    std::optional<std::uint64_t> last_bad_;      // 0-based index of the last bad frame
    int register_ = 0;                           // 5-track: the register the last shift chose
    std::vector<std::uint64_t> held_cr_;         // 5-track: frames of CRs not yet known to end a line
};

/// The hot loop, for callers that bring their own buffer. Decodes frames into out (room for
/// frames.size() bytes, 7-bit characters, no positions) until the first frame that is neither a
/// character, blank nor DEL. Returns that frame's index, or frames.size(); *written = bytes stored.
std::size_t decode_run(const FrameCode& code, std::span<const Frame> frames, char* out, std::size_t* written);

/// The diagnostic for a bad frame at 0-based index, in line (and block) line when it is known (not 0).
Diagnostic bad_frame_diagnostic(const FrameCode& code, Frame f, std::uint64_t index, std::uint64_t line = 0);

}  // namespace tape
