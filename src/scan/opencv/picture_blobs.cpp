// Round blobs of a picture (picture_blobs.hpp): the connected parts of one side of a threshold that are
// small, compact and about as wide as high. Holes show the backing through the paper, so they are the
// blobs of the backing's side; which side that is, and which threshold, is tried.
#include "scan/opencv/picture_blobs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "scan/strip_reading.hpp"

namespace tape::scan {
namespace {

constexpr int min_area = 4;  // pixels: a hole at 6 px across has about 28

std::vector<Blob> blobs_of(const cv::Mat& binary) {
    cv::Mat labels, stats, centroids;
    int n = cv::connectedComponentsWithStats(binary, labels, stats, centroids, 8, CV_32S);
    labels.release();
    const int largest = std::max(8, std::min(binary.cols, binary.rows) / 3);
    std::vector<Blob> out;
    for (int l = 1; l < n && out.size() < max_blobs; ++l) {
        int x = stats.at<int>(l, cv::CC_STAT_LEFT), y = stats.at<int>(l, cv::CC_STAT_TOP);
        int w = stats.at<int>(l, cv::CC_STAT_WIDTH), h = stats.at<int>(l, cv::CC_STAT_HEIGHT);
        int area = stats.at<int>(l, cv::CC_STAT_AREA);
        if (area < min_area || w > largest || h > largest) continue;
        if (x == 0 || y == 0 || x + w == binary.cols || y + h == binary.rows) continue;  // cut by the edge
        if (std::max(w, h) > 2 * std::min(w, h) || area < 0.45 * w * h) continue;        // not round
        out.push_back(Blob{static_cast<float>(centroids.at<double>(l, 0)),
                           static_cast<float>(centroids.at<double>(l, 1)),
                           static_cast<float>(2 * std::sqrt(area / std::numbers::pi))});
    }
    return out;
}

std::size_t longest_feed(std::span<const FeedChain> chains) {
    std::size_t best = 0;
    for (const auto& c : chains)
        if (feed_like(c)) best = std::max(best, c.frames());
    return best;
}

void consider(const cv::Mat& binary, std::size_t grey, BlobSet& best) {
    BlobSet s;
    s.blobs = blobs_of(binary);
    s.chains = follow_chains(s.blobs, 4);  // short parts too: a strip's row of feed holes may be broken
    s.grey = grey;
    s.longest_feed = longest_feed(s.chains);
    if (best.blobs.empty() || s.longest_feed > best.longest_feed) best = std::move(s);
}

}  // namespace

BlobSet find_blobs(std::span<const cv::Mat> greys) {
    BlobSet best;
    cv::Mat binary;
    for (std::size_t g = 0; g < greys.size() && best.longest_feed < min_strip_frames; ++g) {
        double t = cv::threshold(greys[g], binary, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
        consider(binary, g, best);  // holes darker than the threshold
        cv::threshold(greys[g], binary, t, 255, cv::THRESH_BINARY);
        consider(binary, g, best);  // and lighter
    }
    // Light that falls unevenly: thresholds of the neighbourhood, from small holes to large.
    for (std::size_t g = 0; g < greys.size() && best.longest_feed < min_strip_frames; ++g)
        for (int block : {15, 41, 121})
            for (int type : {cv::THRESH_BINARY_INV, cv::THRESH_BINARY}) {
                if (best.longest_feed >= min_strip_frames) break;
                cv::adaptiveThreshold(greys[g], binary, 255, cv::ADAPTIVE_THRESH_MEAN_C, type, block,
                                      type == cv::THRESH_BINARY ? -8 : 8);
                consider(binary, g, best);
            }
    return best;
}

}  // namespace tape::scan
