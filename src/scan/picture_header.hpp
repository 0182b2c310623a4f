// The size a picture file declares, read from its header before anything is decoded: OpenCV's decoders
// allocate what the header says (a 48 KB PNG declaring 20000 x 20000 took 3.2 GB and five minutes to be
// found empty), so a picture too large for scan is refused on its header's word, and a file that begins
// no picture format scan reads (/dev/zero) after its first bytes, not once memory runs out.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tape::scan {

/// The most pixels scan decodes: a 66 Mpx scan of a long strip takes 587 MB and 7 s; this bound, some
/// 9 bytes a pixel, about 1.4 GB.
inline constexpr std::uint64_t max_picture_pixels = 150'000'000;
/// The most bytes of a picture file read: an uncompressed 8-bit colour TIFF of max_picture_pixels.
inline constexpr std::uint64_t max_picture_bytes = 3 * max_picture_pixels;
/// Bytes enough for the signature of every format read.
inline constexpr std::size_t picture_signature_bytes = 8;

struct PictureHeader {
    std::string_view format;  ///< "PNG", "JPEG", "TIFF", "BMP"
    std::uint64_t width = 0, height = 0;
};

/// The format whose signature the bytes begin with ("PNG", ...), or empty.
std::string_view picture_signature(std::span<const std::uint8_t> bytes);
/// The format and size the header declares; nullopt when the bytes hold no size of a format read.
std::optional<PictureHeader> read_picture_header(std::span<const std::uint8_t> bytes);
/// Throws Error(Errc::bad_image), in a machinist's words, for bytes of no format read, a header that
/// declares no size, and a picture of more than max_picture_pixels; else the header.
PictureHeader check_picture(std::span<const std::uint8_t> bytes);
/// A picture file's bytes, refused (Error(Errc::bad_image)) once its first bytes are of no format read,
/// and when it holds more than max_picture_bytes: a regular file before it is read, anything else (a
/// pipe, /dev/zero) once that many came. Error(Errc::io) when it cannot be read.
std::vector<std::uint8_t> read_picture_file(const std::string& path);

}  // namespace tape::scan
