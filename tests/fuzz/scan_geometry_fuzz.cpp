// libFuzzer target: the geometry stage of tape scan (src/scan/), not the image decoders. The first byte
// chooses what the rest is:
//   even: a grey pixel array (width 16 + byte 1, height 16 + byte 2, then the pixels row by row, the
//         bytes repeated to fill it), read as a picture: blobs, chains, feed line, tracks, frames;
//   odd:  a field of holes (x, y, diameter from 6 bytes each) for the chains, the joining of parts, the
//         feed line and its shape, sampled over a picture of the same bytes.
// Whatever comes in, the stage ends: a strip read or refused, every frame with its confidence in 0..1.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "scan/picture_blobs.hpp"
#include "scan/scan_result.hpp"
#include "scan/strip_reading.hpp"
#include "tape/error.hpp"
#include "tape/scan.hpp"

namespace {

void check(const std::optional<tape::scan::Piece>& piece, const tape::ImageScan& im) {
    if (!piece) {
        if (im.refusal.empty()) __builtin_trap();
        return;
    }
    if (piece->frames.size() != piece->confidence.size() || piece->frames.size() != im.strip->frames.size())
        __builtin_trap();
    for (float c : piece->confidence)
        if (!(c >= 0 && c <= 1)) __builtin_trap();
    std::vector<tape::scan::Piece> pieces{*piece};
    auto r = tape::scan::assemble({im}, pieces, {});
    if (r.frames.size() != piece->frames.size()) __builtin_trap();
    for (const auto& d : r.doubts.runs)
        if (d.first < 1 || d.last < d.first || d.last > r.frames.size()) __builtin_trap();
}

void read(const tape::Picture& grey, std::span<const tape::scan::Blob> blobs,
          std::span<const tape::scan::FeedChain> chains) {
    tape::scan::GreyView view{grey.pixels.data(), grey.width, grey.height, grey.width};
    tape::ImageScan im;
    im.width = grey.width, im.height = grey.height;
    check(tape::scan::read_strip(view, blobs, chains, {}, 0, im), im);
}

tape::Picture picture_of(std::span<const std::uint8_t> bytes, int width, int height) {
    tape::Picture m{width, height, 1, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height)};
    for (std::size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = bytes.empty() ? 0 : bytes[i % bytes.size()];
    return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 3) return 0;
    std::span<const std::uint8_t> rest(data + 3, size - 3);
    if (data[0] % 2 == 0) {
        if (!tape::scan_available()) return 0;  // the picture module finds the blobs: a build without OpenCV has none
        std::vector<tape::Picture> greys{picture_of(rest, 16 + data[1], 16 + data[2])};
        tape::scan::BlobSet set = tape::scan::find_blobs(greys);
        const tape::Picture& grey = greys.front();
        read(grey, set.blobs, set.chains);
        return 0;
    }
    std::vector<tape::scan::Blob> blobs;
    for (std::size_t i = 0; i + 6 <= rest.size(); i += 6) {
        auto word = [&](std::size_t k) { return static_cast<float>(rest[i + k] | rest[i + k + 1] << 8); };
        blobs.push_back({word(0) / 16, word(2) / 16, 1 + word(4) / 2048});
    }
    auto chains = tape::scan::follow_chains(blobs, 4);
    for (const auto& c : chains) {
        if (c.blobs.size() != c.missing_before.size()) __builtin_trap();
        auto line = tape::scan::feed_line(blobs, c);
        if (line.centre.size() != c.frames()) __builtin_trap();
        auto [first, last] = tape::scan::straight_run(line, 10);
        if (first > last || last > line.centre.size()) __builtin_trap();
    }
    read(picture_of(rest, 16 + data[1], 16 + data[2]), blobs, chains);
    return 0;
}
