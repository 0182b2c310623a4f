// What is on a tape, counted: the figures behind `tape info`.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "tape/code.hpp"
#include "tape/frame.hpp"

namespace tape {

/// How many punched frames fit each parity convention.
struct ParityCounts {
    std::uint64_t frames = 0;  ///< punched frames (blank tape not counted)
    std::uint64_t even = 0;    ///< an even number of holes
    std::uint64_t odd = 0;
    std::uint64_t mark = 0;   ///< track 8 punched
    std::uint64_t space = 0;  ///< track 8 not punched

    /// The convention most frames fit (even, odd, mark, space in that order on a tie), or
    /// nullopt when there are no punched frames or fewer than 90% of them fit any one ("mixed").
    std::optional<Parity> dominant() const;
    /// Frames that do not fit p.
    std::uint64_t misfits(Parity p) const;
    /// The counts of another stretch of tape added.
    ParityCounts& operator+=(const ParityCounts& o);
};

ParityCounts count_parity(std::span<const Frame> frames);

/// A piece of tape counted once for all the readings tried on it: how many frames of each value, and
/// where its punched frames begin and end. Every count a Surveyor keeps but the program starts follows
/// from it, so that six readings of a long tape cost one pass over it, not six.
struct FrameTally {
    explicit FrameTally(std::span<const Frame> frames);

    std::array<std::uint64_t, 256> count{};  ///< frames of each value
    std::size_t size = 0;                    ///< frames in all
    std::size_t first_punched = 0;           ///< index of the first punched frame; size when there is none
    std::size_t last_punched = 0;            ///< index of the last punched frame
    ParityCounts parity;                     ///< of the punched frames
};

struct TapeSurvey {
    std::uint64_t frames = 0;          ///< all frames
    std::uint64_t leader = 0;          ///< blank frames before the first punched one
    std::uint64_t trailer = 0;         ///< blank frames after the last punched one
    std::uint64_t data = 0;            ///< characters between leader and trailer
    std::uint64_t rubouts = 0;         ///< DEL frames
    std::uint64_t blank_inside = 0;    ///< blank frames between leader and trailer
    std::uint64_t parity_errors = 0;   ///< frames failing the code's parity rule
    std::uint64_t not_in_code = 0;     ///< frames with good parity that are no character of the code
    std::uint64_t program_starts = 0;  ///< '%' marks that a program follows (not the closing one; "%%" once)
    std::uint64_t end_of_blocks = 0;   ///< LF (EIA: EOB)
    ParityCounts parity;               ///< what the punched frames fit
};

/// The same counts a chunk at a time, in bounded memory; the result is the same however the tape is cut.
class Surveyor {
public:
    explicit Surveyor(const FrameCode& code);
    void feed(std::span<const Frame> frames);
    /// The same, with the frames' tally already made (FrameTally(frames)).
    void feed(std::span<const Frame> frames, const FrameTally& tally);
    /// What a frame is in the code surveyed by.
    FrameKind kind(Frame f) const { return code_.kind(f); }
    /// The counts so far, the blank frames at the end taken as trailer.
    TapeSurvey result() const;

private:
    void count_blank_tape(const FrameTally& t);
    void count_program_starts(std::span<const Frame> frames);
    std::size_t next_percent(std::span<const Frame> frames, std::size_t from) const;

    FrameCode code_;
    int percent_frame_ = -1;  // the one frame that is '%' in the code, -2 for several, -1 for none
    TapeSurvey s_;
    std::uint64_t blank_run_ = 0;  // blank frames since the last punched one
    bool punched_ = false;         // a punched frame seen: blanks from now on are inside or trailer
    bool percent_ = false;         // a '%' with no program after it yet
};

/// Counts the tape's frames as read with code. Never throws on bad frames: they are counted.
TapeSurvey survey(std::span<const Frame> frames, const FrameCode& code);

}  // namespace tape
