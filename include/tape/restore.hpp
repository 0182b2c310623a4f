// One trustworthy tape from several reads of a damaged one: the reads aligned (tape/align.hpp), a vote
// per column (how many times a frame of a run is punched decided by likelihood, with the rates of lost
// and doubled frames the reads themselves show), and a frame with a parity error repaired only where
// exactly one single-hole change fits the program's own rules (its grammar, word formats, block
// numbers, codes, arcs and values). Every frame gets a status; damage is never laundered into
// good-looking output: what stays unresolved or contested is written as read and listed.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/align.hpp"
#include "tape/code.hpp"
#include "tape/device.hpp"
#include "tape/dialect.hpp"
#include "tape/format_spec.hpp"
#include "tape/frame.hpp"

namespace tape {

enum class FrameStatus : std::uint8_t {
    clean,       ///< every read that has it agrees, and it is a character of the code
    voted,       ///< a majority (or parity, or the program's rules) decided between the reads
    inferred,    ///< repaired: the one single-hole change that fits the code and the program's rules
    guessed,     ///< RestoreOptions::guess: the likeliest of several changes that fit, the others listed
    contested,   ///< good readings disagree and nothing decides: written as read (the likeliest one when
                 ///< every reading holds parity)
    unstable,    ///< every read saw something else (three reads or more): the reader cannot read it
    unresolved,  ///< no read has it right and no repair fits: written as read
    missing,     ///< the tape's start or end that no read covers (no leader, or no trailer, in any read)
    extra,       ///< a frame only a minority of the reads has (read twice, or a splice): not written
};
/// "clean", "voted", ... as in the report.
std::string_view status_name(FrameStatus s);
inline constexpr std::size_t frame_status_count = 9;

struct MachineProfile;

struct RestoreOptions {
    /// The code the tape is in, for parity and repair; nullopt: a tape in no character code (a binary
    /// computer tape), merged by alignment and vote alone.
    std::optional<FrameCode> code{};
    Dialect dialect = Dialect::automatic;  ///< the grammar repairs must fit
    const FormatSpec* spec = nullptr;      ///< and, when given, the controller's format
    /// And, when given, the machine's profile (in place of spec): its word format as its format-changing
    /// codes set it block by block, its feed code table and prefixed S, T and M words.
    const MachineProfile* machine = nullptr;
    AlignOptions align{};
    /// Where several repairs fit, write the likeliest and mark it guessed (the others listed as its
    /// candidates). Without it nothing is guessed.
    bool guess = false;
    /// Per read (empty, or one per read): the frames the read itself doubts (a reader's flagged rows, a
    /// scan's faint holes), counted from 1 in the read. A doubted frame weighs less than a sure one in
    /// the vote: it decides only where no sure reading says otherwise.
    std::vector<FrameDoubts> doubts{};
    /// How much likelier one length of a run of equal frames must be than the next likeliest, for the
    /// vote to decide it without a doubt (the reads disagree on how many times the frame is punched).
    double run_odds = 100;
};

/// A frame that is not clean, with what each read saw and why it was decided so.
struct RestoreProblem {
    FrameStatus status = FrameStatus::clean;
    std::optional<std::uint64_t> frame{};  ///< 1-based in the restored image; none for extra frames
    std::uint64_t after = 0;               ///< extra frames: the restored frame they came after (0: first)
    std::size_t column = 0;                ///< in the alignment
    std::optional<std::uint64_t> line{};   ///< of the decoded text, where the code is known
    /// Per read: the frame it has here, or nullopt (none, or not covering: see covered).
    std::vector<std::optional<Frame>> seen;
    std::vector<bool> covered;      ///< per read: the read covers this place of the tape
    Frame written = 0;              ///< what the image holds (extra: what was dropped)
    std::vector<Frame> candidates;  ///< repairs that fit (unresolved: none or several; guessed: all, the guess first)
    std::string reason;
    bool run_length = false;  ///< decided on how many times a frame of a run is punched, the reads disagreeing
    /// run_length: how much likelier the length written is than the next likeliest; 0 where the
    /// program's rules decided (or the reads that cover the run whole agree).
    double odds = 0;
};

struct RestoreResult {
    std::vector<Frame> frames;                         ///< the restored image
    std::vector<RestoreProblem> problems;              ///< in tape order
    std::uint64_t counts[frame_status_count] = {};     ///< frames by status (extra: dropped ones)
    std::size_t reference = 0;                         ///< the read the others were aligned to
    std::vector<double> shared;                        ///< per read: frames it shares with the reference
    std::uint64_t missing_start = 0, missing_end = 0;  ///< 1 when the tape's start / end was read by no read
    std::vector<bool> related;                         ///< per read: false for a read of another tape left out
    /// Runs of equal frames whose length the reads disagreed on and the vote (or the program's rules)
    /// decided: written without a doubt, but each is a place a wrong length could hide.
    std::uint64_t run_length_votes = 0;
    /// Frames in doubt (contested) that are not written, as most reads lack them.
    std::uint64_t contested_unwritten = 0;
    /// One read of a tape in no code: nothing could be checked, so nothing is known to be right.
    bool unchecked = false;
    /// Most frames of the data fail the code given: it is not the tape's. The reads were voted as frames
    /// of no code (no parity), nothing was repaired, and the restoration is not complete.
    bool code_misfit = false;

    std::uint64_t count(FrameStatus s) const { return counts[static_cast<std::size_t>(s)]; }
    /// True when every frame is clean, voted or inferred, something could be checked, and the code fits.
    bool complete() const;
};

/// Restores one tape from reads of it (any number, one or more). Throws Error as align_reads does, and
/// Error(Errc::usage) for doubts given for a number of reads other than the reads'.
RestoreResult restore(std::span<const std::span<const Frame>> reads, const RestoreOptions& options);

/// How a restoration did against the tape its reads were made from (reads damaged by tape::damage, in
/// tests and benchmarks of restoring): the data of the output (first to last punched frame) aligned with
/// the tape's, frame by frame. A frame left out of or added to a run of equal frames is in doubt when any
/// copy of the run (or a frame left out there) is; the frames of a stretch that does not match (a misread
/// stretch) are in doubt when the report doubts any frame of it or frames left out at its ends (frames
/// only left out: when it doubts a frame beside them); a wrong inferred frame is silently wrong.
struct RestoreCheck {
    std::uint64_t right = 0;           ///< data frames of the tape the output holds as punched
    std::uint64_t silently_wrong = 0;  ///< frames wrong, added or left out where the report has no doubt
    std::uint64_t flagged_wrong = 0;   ///< wrong where the report says it is in doubt
    /// Blank frames of the leader and trailer more or fewer than the tape has: their length is nobody's
    /// concern (it follows the majority of the reads), and is not counted as wrong.
    std::uint64_t blank_ends = 0;
    bool exact = false;                      ///< the data (first to last punched frame) is the tape's
    std::vector<std::size_t> silent_at;      ///< where each silently wrong frame is, as an index of the tape (an added
                                             ///< frame: the tape frame before it)
    std::vector<std::size_t> silent_output;  ///< and as an index of the output (a left-out frame: where it would be)
    std::vector<std::size_t> flagged_at, flagged_output;  ///< the same of each frame wrong and in doubt
};
RestoreCheck check_restore(std::span<const Frame> tape, const RestoreResult& result);

/// True for the statuses that say a frame is in doubt: guessed, contested, unstable, unresolved, missing.
/// (An inferred frame is claimed right: a wrong one is silently wrong.)
bool in_doubt(FrameStatus s);

/// The distance of frame (1-based) from the first feed hole of the tape, in centimetres (2.54 mm pitch).
double frame_distance_cm(std::uint64_t frame);

}  // namespace tape
