// tape/scan.hpp with OpenCV: each picture decoded (imgcodecs), its blobs found (imgproc), its strip
// read and the pieces made one read by the stages of scan_geometry.hpp.
#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "scan/opencv/picture_blobs.hpp"
#include "scan/scan_result.hpp"
#include "scan/strip_reading.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"
#include "tape/scan.hpp"

namespace tape {
namespace {

// The picture as grey levels two ways: as the eye sees it (luminance), and as its darkest channel,
// which tells coloured paper (orange, red, yellow) from a grey or white backing far better.
std::vector<cv::Mat> grey_pictures(const std::string& path, int& width, int& height) {
    std::vector<std::uint8_t> bytes = read_file(path);
    cv::Mat colour;
    try {
        colour = cv::imdecode(bytes, cv::IMREAD_COLOR);
    } catch (const cv::Exception& e) {
        throw Error(Errc::io, "cannot decode the picture: " + e.msg);
    }
    bytes = {};
    if (colour.empty()) throw Error(Errc::io, "not a picture OpenCV can read (PNG, JPEG, TIFF, ...)");
    width = colour.cols, height = colour.rows;
    std::vector<cv::Mat> out(2);
    cv::cvtColor(colour, out[0], cv::COLOR_BGR2GRAY);
    out[1].create(colour.rows, colour.cols, CV_8UC1);  // row by row: no copy of the colours on the side
    for (int y = 0; y < colour.rows; ++y) {
        const std::uint8_t* c = colour.ptr<std::uint8_t>(y);
        std::uint8_t* m = out[1].ptr<std::uint8_t>(y);
        for (int x = 0; x < colour.cols; ++x, c += 3) m[x] = std::min({c[0], c[1], c[2]});
    }
    return out;
}

// The grey in which holes and paper differ most, at the blobs found: the holes are sampled in it.
std::size_t sampling_grey(const std::vector<cv::Mat>& greys, const scan::BlobSet& set) {
    std::size_t best = set.grey;
    double most = -1;
    for (std::size_t k = 0; k < greys.size(); ++k) {
        const cv::Mat& g = greys[k];
        scan::GreyView v{g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step[0])};
        std::vector<float> d;
        for (std::size_t i = 0; i < set.blobs.size(); i += std::max<std::size_t>(1, set.blobs.size() / 500)) {
            const auto& b = set.blobs[i];
            d.push_back(std::abs(v.at(b.x, b.y) - v.at(b.x + b.diameter, b.y)));
        }
        if (d.empty()) continue;
        std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
        if (d[d.size() / 2] > most) most = d[d.size() / 2], best = k;
    }
    return best;
}

void check(const ScanOptions& o) {
    if (o.tracks != 5 && o.tracks != 8)
        throw Error(Errc::usage, "tape has 5 or 8 tracks, not " + std::to_string(o.tracks));
    if (o.dpi_hint != 0 && !(o.dpi_hint >= 10 && o.dpi_hint <= 20000))
        throw Error(Errc::usage, "a resolution of 10 to 20000 dpi, not " + std::to_string(o.dpi_hint));
}

}  // namespace

bool scan_available() { return true; }

std::string_view scan_unavailable_message() { return ""; }

ScanResult scan_images(std::span<const std::string> paths, const ScanOptions& options) {
    check(options);
    if (paths.empty()) throw Error(Errc::usage, "no pictures to read");
    std::vector<ImageScan> images;
    std::vector<scan::Piece> pieces;
    for (std::size_t m = 0; m < paths.size(); ++m) {
        ImageScan im;
        im.name = paths[m];
        std::vector<cv::Mat> greys;
        try {
            greys = grey_pictures(paths[m], im.width, im.height);
        } catch (const Error& e) {
            throw Error(e.code(), paths[m] + ": " + e.what(), e.hint());
        }
        scan::BlobSet set = scan::find_blobs(greys);
        const cv::Mat& g = greys[sampling_grey(greys, set)];
        scan::GreyView view{g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step[0])};
        for (auto& other : greys)
            if (&other != &g) other.release();
        auto piece = scan::read_strip(view, set.blobs, set.chains, options, static_cast<std::uint32_t>(m), im);
        for (const auto& b : set.blobs) im.blobs.push_back({b.x, b.y});
        if (piece) pieces.push_back(std::move(*piece));
        images.push_back(std::move(im));
    }
    if (pieces.empty()) {
        std::string why;
        for (const auto& im : images) why += (why.empty() ? "" : "; ") + im.name + ": " + im.refusal;
        throw Error(Errc::bad_image, why);
    }
    return scan::assemble(std::move(images), std::move(pieces), options);
}

}  // namespace tape
