// The picture module's blobs (picture_module.hpp): the connected parts of one side of a threshold that
// are small, compact and about as wide as high. Holes show the backing through the paper, so they are
// the blobs of the backing's side; which side that is, and which threshold, the library tries in turn.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "scan/opencv/module_parts.hpp"

namespace tape::picture_module {
namespace {

constexpr int min_area = 4;  // pixels: a hole at 6 px across has about 28

std::vector<scan::Blob> blobs_of(const cv::Mat& binary) {
    cv::Mat labels, stats, centroids;
    int n = cv::connectedComponentsWithStats(binary, labels, stats, centroids, 8, CV_32S);
    labels.release();
    const int largest = std::max(8, std::min(binary.cols, binary.rows) / 3);
    std::vector<scan::Blob> out;
    for (int l = 1; l < n && out.size() < scan::max_blobs; ++l) {
        int x = stats.at<int>(l, cv::CC_STAT_LEFT), y = stats.at<int>(l, cv::CC_STAT_TOP);
        int w = stats.at<int>(l, cv::CC_STAT_WIDTH), h = stats.at<int>(l, cv::CC_STAT_HEIGHT);
        int area = stats.at<int>(l, cv::CC_STAT_AREA);
        if (area < min_area || w > largest || h > largest) continue;
        if (x == 0 || y == 0 || x + w == binary.cols || y + h == binary.rows) continue;  // cut by the edge
        if (std::max(w, h) > 2 * std::min(w, h) || area < 0.45 * w * h) continue;        // not round
        out.push_back(scan::Blob{static_cast<float>(centroids.at<double>(l, 0)),
                                 static_cast<float>(centroids.at<double>(l, 1)),
                                 static_cast<float>(2 * std::sqrt(area / std::numbers::pi))});
    }
    return out;
}

}  // namespace

Failure blobs(const Picture& grey, Threshold how, int block, std::vector<scan::Blob>& out) {
    if (grey.channels != 1) return {Errc::usage, "blobs are found in a grey picture"};
    cv::Mat g(grey.height, grey.width, CV_8UC1, const_cast<std::uint8_t*>(grey.pixels.data())), binary;
    try {
        switch (how) {
            case Threshold::otsu_darker:
                cv::threshold(g, binary, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
                break;
            case Threshold::otsu_lighter:
                cv::threshold(g, binary, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
                break;
            case Threshold::local_darker:
                cv::adaptiveThreshold(g, binary, 255, cv::ADAPTIVE_THRESH_MEAN_C, cv::THRESH_BINARY_INV, block, 8);
                break;
            case Threshold::local_lighter:
                cv::adaptiveThreshold(g, binary, 255, cv::ADAPTIVE_THRESH_MEAN_C, cv::THRESH_BINARY, block, -8);
                break;
        }
        out = blobs_of(binary);
    } catch (const cv::Exception& e) {
        return {Errc::io, "cannot find the holes in the picture: " + e.msg};
    }
    return {};
}

}  // namespace tape::picture_module
