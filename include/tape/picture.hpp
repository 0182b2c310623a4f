// Pictures in memory, and their files (PNG, JPEG, TIFF) through OpenCV's imgcodecs: for rendering a
// tape at a true scale (tape render) and for making test pictures of tapes. In a build without OpenCV
// encoding and decoding throw Error(Errc::io) saying so (scan_available() in tape/scan.hpp is false).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

/// 8-bit pixels, row after row without padding: 1 channel (grey) or 3 (blue, green, red, as OpenCV).
struct Picture {
    int width = 0, height = 0, channels = 3;
    std::vector<std::uint8_t> pixels;

    std::uint8_t* at(int x, int y) { return &pixels[(static_cast<std::size_t>(y) * width + x) * channels]; }
    const std::uint8_t* at(int x, int y) const { return &pixels[(static_cast<std::size_t>(y) * width + x) * channels]; }
};

/// The picture as a file's bytes: format "png", "jpeg" (quality 1..100) or "tiff". Throws Error(Errc::usage)
/// for another format, Error(Errc::io) when the encoder fails or the build has no OpenCV.
std::vector<std::uint8_t> encode_picture(const Picture& picture, std::string_view format, int quality = 95);

/// A picture file's bytes decoded to 3 channels. Throws Error(Errc::bad_image) for bytes no decoder
/// takes, Error(Errc::io) in a build without OpenCV.
Picture decode_picture(std::span<const std::uint8_t> bytes);

/// "png", "jpeg" or "tiff" for a file name's extension (.png, .jpg, .jpeg, .tif, .tiff, any case); "" for others.
std::string_view picture_format_for_path(std::string_view path);

}  // namespace tape
