// Tape image formats: each is a module in one table (raw, holes).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/code.hpp"
#include "tape/frame.hpp"

namespace tape {

/// How the holes writer annotates frames: decoded character and frame number, by this code.
struct ImageWriteOptions {
    const FrameCode* annotate = nullptr;  ///< nullptr: frame numbers only
    std::uint64_t first_number = 1;       ///< number of the first frame (when appending to an image)
    bool header = true;                   ///< write the format's header, if it has one
};

/// One image format. Adding a format = one file, one line in image.cpp's table, one CMake line.
struct ImageFormat {
    std::string_view id;  ///< "raw", "holes"
    std::string_view description;
    std::span<const std::string_view> extensions;  ///< with the dot: ".ptp"
    bool binary;                                   ///< not for a terminal
    /// How sure the format is that bytes (a prefix of the file) are its own: 0 (no) to 100.
    int (*match)(std::span<const std::uint8_t> prefix);
    /// Frames from the whole file. Throws Error(Errc::bad_image) with the line or offset.
    std::vector<Frame> (*read)(std::span<const std::uint8_t> bytes);
    /// The file for frames.
    std::string (*write)(std::span<const Frame> frames, const ImageWriteOptions& options);
};

/// All formats, in the order detection tries them.
std::span<const ImageFormat> image_formats();
/// By id, or nullptr.
const ImageFormat* find_image_format(std::string_view id);
/// By the file name's extension (case-insensitive), or nullptr.
const ImageFormat* image_format_for_path(std::string_view path);
/// True for a name whose extension says nothing sure (".txt": a holes picture as often as a text
/// program): there the content decides, where an image extension (".ptp", ".holes") otherwise does.
bool extension_is_ambiguous(std::string_view path);
/// The format whose match is most confident for this prefix (raw when nothing else fits).
const ImageFormat& detect_image_format(std::span<const std::uint8_t> prefix);

}  // namespace tape
