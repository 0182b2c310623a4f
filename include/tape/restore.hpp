// One trustworthy tape from several reads of a damaged one: the reads aligned (tape/align.hpp), a vote
// per column, and a frame with a parity error repaired only where exactly one single-hole change makes
// it a character that fits the block's grammar. Every frame gets a status; damage is never laundered
// into good-looking output: what stays unresolved is written as read and listed.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/align.hpp"
#include "tape/code.hpp"
#include "tape/dialect.hpp"
#include "tape/format_spec.hpp"
#include "tape/frame.hpp"

namespace tape {

enum class FrameStatus : std::uint8_t {
    clean,       ///< every read that has it agrees, and it is a character of the code
    voted,       ///< a majority (or parity) decided between the reads
    inferred,    ///< repaired: the one single-hole change that fits the code and the block
    contested,   ///< two or more good readings disagree and nothing decides (the reference's is written)
    unstable,    ///< every read saw something else (three reads or more): the reader cannot read it
    unresolved,  ///< no read has it right and no repair fits: written as read
    missing,     ///< the tape's start or end that no read covers (no leader, or no trailer, in any read)
    extra,       ///< a frame only a minority of the reads has (read twice, or a splice): not written
};
/// "clean", "voted", ... as in the report.
std::string_view status_name(FrameStatus s);
inline constexpr std::size_t frame_status_count = 8;

struct RestoreOptions {
    /// The code the tape is in, for parity and repair; nullopt: a tape in no character code (a binary
    /// computer tape), merged by alignment and vote alone.
    std::optional<FrameCode> code{};
    Dialect dialect = Dialect::automatic;  ///< the grammar repairs must fit
    const FormatSpec* spec = nullptr;      ///< and, when given, the controller's format
    AlignOptions align{};
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
    std::vector<Frame> candidates;  ///< repair candidates that fit (unresolved: none or several)
    std::string reason;
};

struct RestoreResult {
    std::vector<Frame> frames;                         ///< the restored image
    std::vector<RestoreProblem> problems;              ///< in tape order
    std::uint64_t counts[frame_status_count] = {};     ///< frames by status (extra: dropped ones)
    std::size_t reference = 0;                         ///< the read the others were aligned to
    std::vector<double> shared;                        ///< per read: frames it shares with the reference
    std::uint64_t missing_start = 0, missing_end = 0;  ///< 1 when the tape's start / end was read by no read

    std::uint64_t count(FrameStatus s) const { return counts[static_cast<std::size_t>(s)]; }
    /// True when every frame is clean, voted or inferred.
    bool complete() const;
};

/// Restores one tape from reads of it (any number, one or more). Throws Error as align_reads does.
RestoreResult restore(std::span<const std::span<const Frame>> reads, const RestoreOptions& options);

/// How a restoration did against the tape its reads were made from (reads damaged by tape::damage, in
/// tests and benchmarks of restoring): the output aligned with the tape, frame by frame.
struct RestoreCheck {
    std::uint64_t right = 0;           ///< tape frames the output holds as punched
    std::uint64_t silently_wrong = 0;  ///< frames wrong, added or left out where the report has no doubt
    std::uint64_t flagged_wrong = 0;   ///< wrong where the report says it is in doubt
    /// Blank frames of the leader or trailer added or left out: their length is voted like any run of
    /// equal frames, and a run of a hundred has a hundred times the drops and doubles of one frame.
    std::uint64_t blank_ends = 0;
    bool exact = false;  ///< the punched part (first to last punched frame) is the tape's
};
RestoreCheck check_restore(std::span<const Frame> tape, const RestoreResult& result);

/// True for the statuses that say a frame is in doubt: inferred, contested, unstable, unresolved, missing.
bool in_doubt(FrameStatus s);

/// The distance of frame (1-based) from the first feed hole of the tape, in centimetres (2.54 mm pitch).
double frame_distance_cm(std::uint64_t frame);

}  // namespace tape
