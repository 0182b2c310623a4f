// What is left out of the reads before they are aligned (restore.cpp): stretches one read has and the
// others lack, longer than a margin. Aligned, each of their frames would be a column, voted and listed as
// a frame only a minority has (about 1.4 KB each: 8.6 M frames of leader took 12 GB); left out, the
// restoration holds memory for the tape's length, not for what one read adds to it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tape/restore.hpp"

namespace tape::detail {

/// The reads as they are aligned, and what was left out of them.
struct CutReads {
    std::vector<std::span<const Frame>> reads;
    /// The frames of the reads a stretch was cut from inside of (reads points into them).
    std::vector<std::vector<Frame>> kept;
    /// Punched frames left out as a stretch only one read has: frames a minority has, not written.
    std::uint64_t unmatched = 0;
};

/// The reads with their long blank ends (past the other reads' longest and a margin) and their long
/// stretches that match no other read (where every other read goes on past them within a margin) left
/// out, a margin of each kept, and doubts moved with the frames (doubts: one per read, or refused
/// later as given).
CutReads cut_reads(std::span<const std::span<const Frame>> reads, std::vector<FrameDoubts>& doubts,
                   const AlignOptions& o);

}  // namespace tape::detail
