// What repair knows of the restored image as a whole (repair.cpp, run_rules.cpp): whether it is an NC
// program, in which dialect, and, if so, its own rules learned from the blocks no damage touches.
#pragma once

#include <memory>
#include <set>
#include <span>

#include "block_judge.hpp"

namespace tape::detail {

struct RepairWorld {
    RepairSetup setup;
    std::set<std::uint64_t> damaged_lines;
    std::set<std::uint64_t> numbers_damaged;  ///< damaged lines whose damage may touch the block number
    std::unique_ptr<TapeRules> rules;
    CharModel chars;  ///< how the text goes, for guesses
    /// The undamaged lines hold blank tape between characters, or DEL: only then is either a repair
    /// inside a line (a reader skips both, so either would make any block fit).
    bool blank_inside_lines = false, rubouts = false;
    std::string text;  ///< the image's text, a bad frame as U+FFFD

    /// The line (from 1) of each frame's character, counted by the ends of block before it.
    std::uint64_t line_of(std::size_t frame) const;
    std::vector<std::size_t> block_starts;  ///< the first frame of each line
};

/// Learns the world of image; damaged: frames in doubt, whose lines are left out of what is learned.
std::unique_ptr<RepairWorld> learn_world(std::span<const Frame> image, std::span<const std::size_t> damaged,
                                         const FrameCode& code, const RestoreOptions& options);

/// The frames [from, to) of the line that frame at stands in, its end of block included; where that
/// is longer than most, nullopt (a block that long is no block: the code does not fit, or the ends of
/// block are lost).
std::optional<std::pair<std::size_t, std::size_t>> block_around(const FrameCode& code, std::span<const Frame> image,
                                                                std::size_t at);

}  // namespace tape::detail
