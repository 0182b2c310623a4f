// One picture's strip read into a piece (strip_reading.cpp).
#pragma once

#include <optional>

#include "scan/scan_geometry.hpp"

namespace tape::scan {

/// A strip shorter than this is not read: too little to tell its feed holes from a row of code holes.
inline constexpr std::size_t min_strip_frames = 20;

/// Reads the longest straight strip of feed holes among chains (follow_chains of blobs) in picture,
/// filling image.strip and image.notes; nullopt with image.refusal set when there is none to read.
std::optional<Piece> read_strip(const GreyView& picture, std::span<const Blob> blobs, std::span<const FeedChain> chains,
                                const ScanOptions& options, std::uint32_t image_number, ImageScan& image);

}  // namespace tape::scan
