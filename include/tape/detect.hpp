// Telling what a tape is from its frames: ISO or EIA, an ASCII tape with another parity convention,
// a 5-track tape, a binary computer tape, or a text file given where a tape image was expected.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tape/binary_tape.hpp"
#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/frame.hpp"
#include "tape/survey.hpp"
#include "tape/utf8_text.hpp"

namespace tape {

/// What the tape is, as far as its frames tell.
enum class TapeKind {
    blank,       ///< no punched frame
    iso,         ///< ISO 7-bit, even parity on track 8
    eia,         ///< EIA RS-244, odd parity on track 5
    ascii,       ///< ISO/ASCII positions with another parity convention (DEC-era: mark, space, odd)
    telecode,    ///< a computer maker's 8-track code (the Elliott 920 telecode, parity on track 5)
    five_track,  ///< tracks 6-8 never punched: a 5-track telegraph tape (ITA2, МТК-2)
    binary,      ///< most frames fail every character code: a computer's binary tape (tape/binary_tape.hpp)
    text,        ///< the bytes are a text program, not frames
    unknown,     ///< none of the above fits well enough
};
std::string_view tape_kind_name(TapeKind k);

/// One way of reading the frames as characters.
struct Reading {
    Code code = Code::iso;
    Parity parity = Parity::even;  ///< odd for EIA
    bool operator==(const Reading&) const = default;
};
/// "ISO with even parity", "EIA", "ASCII with mark parity", "Elliott 920 telecode".
std::string reading_name(Reading r);

/// The frames decoded one way: what went wrong, what came out.
struct ReadingFit {
    Reading reading;
    std::uint64_t bad_frames = 0;     ///< parity errors and frames that are no character of the code
    std::uint64_t controls = 0;       ///< characters no text holds (BEL, ESC, ...): a tape of text has few
    std::uint64_t end_of_blocks = 0;  ///< LF (EIA: EOB)
    std::uint64_t program_starts = 0;
};

/// The counts a verdict is drawn from.
struct TapeEvidence {
    std::uint64_t frames = 0;            ///< all frames looked at
    std::uint64_t punched = 0;           ///< not blank
    std::uint64_t significant = 0;       ///< punched and not all-holes (DEL in ISO, 0xFF; EIA DEL, 0x7F)
    ParityCounts parity;                 ///< of the punched frames
    std::uint64_t five_track = 0;        ///< punched frames with tracks 6-8 clear (all a 5-track tape has)
    std::uint64_t longest_0x80_run = 0;  ///< track 8 alone, in a row: leader of DEC binary and mark-parity tapes
    std::uint64_t iso_lf = 0;            ///< 0x0A, the ISO end of block
    std::uint64_t eia_eob = 0;           ///< 0x80, the EIA end of block
    bool text = false;                   ///< the frames, taken as the bytes of a file, are clean UTF-8 text with lines
    /// ISO even, EIA, then ASCII mark, space and odd, then the Elliott 920 telecode: each decoded over
    /// the frames looked at.
    std::array<ReadingFit, 6> fits{};
    std::uint64_t koi7_letters = 0;  ///< ISO letters between SO and SI: КОИ-7 Cyrillic
    /// A binary loader format that explains the tape (PDP-8 RIM or BIN, PDP-11 absolute loader).
    std::optional<BinaryTape> binary;
    bool whole_tape = true;  ///< false when only the start of the tape was looked at
};

struct CodeDetection {
    TapeKind kind = TapeKind::unknown;
    std::optional<Code> code;        ///< set for ISO (and blank tape), EIA and a telecode: the code to decode with
    std::optional<Reading> reading;  ///< the reading the tape fits best, when one fits
    bool clean = false;              ///< decoding with `reading` gives no bad frames (or almost none)
    std::string reason;              ///< the verdict with its evidence, in words a machinist understands
    Hint hint{};                     ///< only when following it reads the tape cleanly
    TapeEvidence evidence;
    /// Set for a tape no code fits (kind unknown) when one reading fails fewer frames than every other,
    /// and fewer than a quarter of them:
    /// the one to decode with when the user asks for the text all the same (decode -k), saying so.
    std::optional<Reading> closest;
};

/// True when the ISO reading of the evidence holds КОИ-7 text (letters shifted by SO ... SI), which
/// reads as Latin letters without --charset koi7.
bool looks_like_koi7(const TapeEvidence& e);

/// The tape's frames looked at a chunk at a time, in bounded memory, every reading tried at once; the
/// verdict is the same however the tape is cut.
class Detector {
public:
    /// bytes_are_frames: the image's bytes are its frames (raw), so a text file can be recognised.
    explicit Detector(const CodeTable* eia_table = nullptr, bool bytes_are_frames = true);
    void feed(std::span<const Frame> frames);
    /// Marks the verdict as drawn from the start of the tape only.
    void partial() { evidence_.whole_tape = false; }
    /// The whole tape was fed: what waits for the tape's end (a binary section without its trailer) counts.
    void finish() { binary_.finish(); }
    CodeDetection result() const;
    /// The counts of the tape read one of the ways of TapeEvidence::fits.
    TapeSurvey survey(Reading r) const;

private:
    void note_0x80_runs(std::span<const Frame> frames, const FrameTally& t);
    void note_koi7(std::span<const Frame> frames, const FrameTally& t);

    TapeEvidence evidence_;
    std::vector<Surveyor> surveyors_;  // one for each of evidence_.fits
    std::array<std::uint64_t, 6> controls_{};
    BinaryDetector binary_;
    std::uint64_t run_0x80_ = 0;
    bool shifted_ = false;  // after an SO, before its SI
    bool bytes_are_frames_;
    bool text_ok_;
    TextChecker text_checker_;
};

/// The verdict on frames (the whole tape, or as much of it as was read).
CodeDetection detect_code(std::span<const Frame> frames, const CodeTable* eia_table = nullptr);

/// Several reads of one tape: the verdict of the reading most reads fit (ISO, EIA or ASCII), so that a
/// read of junk, however long, does not outvote the others; a tie goes to the reads with more frames.
struct ReadsDetection {
    CodeDetection detection;   ///< the verdict on read `from`, the longest read of the winning reading
    std::size_t from = 0;      ///< the read it was drawn from (the longest read when none fits a code)
    std::size_t agreeing = 0;  ///< how many reads fit that reading
};
ReadsDetection detect_code_of_reads(std::span<const std::span<const Frame>> reads,
                                    const CodeTable* eia_table = nullptr);

/// For a tape decoded with its closest reading (CodeDetection::closest): what that is and why it is only
/// the closest, in words.
std::string closest_reading_note(const CodeDetection& d);

/// When a tape forced to one reading fails it but reads cleanly another way: a note saying so, with
/// the hint to read it that way.
std::optional<Diagnostic> other_reading(const CodeDetection& d, Reading forced);

}  // namespace tape
