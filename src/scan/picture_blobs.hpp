// Round blobs of a picture at the threshold that shows its feed holes best (picture_blobs.cpp).
#pragma once

#include "scan/scan_geometry.hpp"
#include "tape/picture.hpp"

namespace tape::scan {

struct BlobSet {
    std::vector<Blob> blobs;
    std::vector<FeedChain> chains;  ///< follow_chains of blobs
    std::size_t grey = 0;           ///< which of the grey pictures they came from
    std::size_t longest_feed = 0;   ///< frames of the longest row of feed holes
};

/// The blobs of the grey pictures (alternative conversions of one picture) at a global (Otsu) threshold,
/// holes darker and lighter than the paper; where that shows no strip, at local thresholds of a few
/// sizes. The set whose longest row of feed holes is longest wins. Thresholds and blobs come from the
/// picture module.
BlobSet find_blobs(std::span<const Picture> greys);

}  // namespace tape::scan
