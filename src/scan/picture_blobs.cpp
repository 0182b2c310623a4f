// Round blobs of a picture (picture_blobs.hpp): each threshold's blobs come from the picture module;
// which threshold shows the strip best is decided here, by the rows of feed holes its blobs make.
#include "scan/picture_blobs.hpp"

#include <algorithm>

#include "scan/picture_module_loader.hpp"
#include "scan/strip_reading.hpp"

namespace tape::scan {
namespace {

using picture_module::Threshold;

std::size_t longest_feed(std::span<const FeedChain> chains) {
    std::size_t best = 0;
    for (const auto& c : chains)
        if (feed_like(c)) best = std::max(best, c.frames());
    return best;
}

void consider(const Picture& grey, Threshold how, int block, std::size_t g, BlobSet& best) {
    BlobSet s;
    picture_module::call(picture_module::api().blobs, grey, how, block, s.blobs);
    s.chains = follow_chains(s.blobs, 4);  // short parts too: a strip's row of feed holes may be broken
    s.grey = g;
    s.longest_feed = longest_feed(s.chains);
    if (best.blobs.empty() || s.longest_feed > best.longest_feed) best = std::move(s);
}

}  // namespace

BlobSet find_blobs(std::span<const Picture> greys) {
    BlobSet best;
    for (std::size_t g = 0; g < greys.size() && best.longest_feed < min_strip_frames; ++g) {
        consider(greys[g], Threshold::otsu_darker, 0, g, best);
        consider(greys[g], Threshold::otsu_lighter, 0, g, best);
    }
    // Light that falls unevenly: thresholds of the neighbourhood, from small holes to large.
    for (std::size_t g = 0; g < greys.size() && best.longest_feed < min_strip_frames; ++g)
        for (int block : {15, 41, 121})
            for (Threshold how : {Threshold::local_darker, Threshold::local_lighter}) {
                if (best.longest_feed >= min_strip_frames) break;
                consider(greys[g], how, block, g, best);
            }
    return best;
}

}  // namespace tape::scan
