// tape/scan.hpp: each picture decoded to grey levels and its blobs found (the picture module), its
// strip read and the pieces made one read by the stages of scan_geometry.hpp.
#include <algorithm>

#include "scan/picture_blobs.hpp"
#include "scan/picture_header.hpp"
#include "scan/picture_module_loader.hpp"
#include "scan/scan_result.hpp"
#include "scan/strip_reading.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"
#include "tape/scan.hpp"

namespace tape {
namespace {

// The picture as grey levels two ways: as the eye sees it (luminance), and as its darkest channel,
// which tells coloured paper (orange, red, yellow) from a grey or white backing far better.
std::vector<Picture> grey_pictures(const std::string& path, int& width, int& height) {
    std::vector<Picture> out(2);
    std::vector<std::uint8_t> bytes = scan::read_picture_file(path);
    scan::check_picture(bytes);  // its size from its header, before a decoder allocates it
    picture_module::call(picture_module::api().greys, std::span<const std::uint8_t>(bytes), out[0], out[1]);
    width = out[0].width, height = out[0].height;
    return out;
}

scan::GreyView view_of(const Picture& g) { return scan::GreyView{g.pixels.data(), g.width, g.height, g.width}; }

// The grey in which holes and paper differ most, at the blobs found: the holes are sampled in it.
std::size_t sampling_grey(const std::vector<Picture>& greys, const scan::BlobSet& set) {
    std::size_t best = set.grey;
    double most = -1;
    for (std::size_t k = 0; k < greys.size(); ++k) {
        scan::GreyView v = view_of(greys[k]);
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

ScanResult scan_images(std::span<const std::string> paths, const ScanOptions& options) {
    check(options);
    if (paths.empty()) throw Error(Errc::usage, "no pictures to read");
    std::vector<ImageScan> images;
    std::vector<scan::Piece> pieces;
    for (std::size_t m = 0; m < paths.size(); ++m) {
        ImageScan im;
        im.name = paths[m];
        std::vector<Picture> greys;
        try {
            greys = grey_pictures(paths[m], im.width, im.height);
        } catch (const Error& e) {
            throw Error(e.code(), paths[m] + ": " + e.what(), e.hint());
        }
        scan::BlobSet set = scan::find_blobs(greys);
        const Picture& g = greys[sampling_grey(greys, set)];
        scan::GreyView view = view_of(g);
        for (auto& other : greys)
            if (&other != &g) other.pixels = {};
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
