// The runs of frames that anchor reads to each other (align.cpp), shared with what is cut from reads
// before they are aligned (read_cuts.cpp).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tape/align.hpp"

namespace tape::detail {

/// (hash, place of the run's first frame), sorted by hash, then by place.
using Runs = std::vector<std::pair<std::uint64_t, std::int32_t>>;

/// The rolling hash of runs of k frames that are not mostly blank (a run of leader anchors nothing),
/// with where each starts: one run in about four, chosen by its hash, so the same runs in every read.
Runs hashed_runs(std::span<const Frame> s, std::size_t k);

/// The frames in an anchor (AlignOptions::anchor_length, at least 4).
std::size_t anchor_length(const AlignOptions& o);

}  // namespace tape::detail
