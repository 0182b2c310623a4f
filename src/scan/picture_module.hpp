// The picture module: what needs OpenCV (picture files, grey levels, thresholds, connected blobs) is a
// shared object of its own, loaded on first use, so that no command but scan and render to a picture
// file maps OpenCV and the hundred libraries its image codecs pull in. The module is built with the
// project and shares no code with the library: this table of functions is all it offers, and it
// throws nothing across it (each function returns a Failure, empty on success).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scan/scan_geometry.hpp"
#include "tape/error.hpp"
#include "tape/picture.hpp"

namespace tape::picture_module {

/// Changes whenever the table below does: a module of another build is refused, not called.
inline constexpr std::uint32_t abi_version = 1;

struct Failure {
    Errc code = Errc::io;
    std::string message;  ///< empty: no failure
    explicit operator bool() const { return !message.empty(); }
};

/// Which pixels a threshold keeps as blobs: darker or lighter than a global (Otsu) threshold, or than
/// the mean of a square neighbourhood (side `block`, offset 8 grey levels).
enum class Threshold : std::uint8_t { otsu_darker, otsu_lighter, local_darker, local_lighter };

struct Api {
    std::uint32_t abi = abi_version;
    /// A picture file's bytes to 3 channels (blue, green, red).
    Failure (*decode)(std::span<const std::uint8_t> bytes, Picture& out);
    /// A picture to a file's bytes: format "png", "jpeg" (quality 1..100) or "tiff".
    Failure (*encode)(const Picture& picture, std::string_view format, int quality, std::vector<std::uint8_t>& out);
    /// A picture file's bytes to two grey pictures: as the eye sees it (luminance), and its darkest
    /// channel. The colours are not kept: a large photo is held once, not three times.
    Failure (*greys)(std::span<const std::uint8_t> bytes, Picture& luminance, Picture& darkest);
    /// The small, compact, round blobs of a grey picture on one side of a threshold (block: the
    /// neighbourhood of a local one), at most scan::max_blobs.
    Failure (*blobs)(const Picture& grey, Threshold how, int block, std::vector<scan::Blob>& out);
};

}  // namespace tape::picture_module

/// The module's one exported symbol.
extern "C" const tape::picture_module::Api* tape_picture_module_api();
