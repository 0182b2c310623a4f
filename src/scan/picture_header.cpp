// Picture headers (picture_header.hpp): PNG's IHDR, JPEG's start of frame, TIFF's first directory,
// BMP's info header; each read within the bytes given, never past them.
#include "scan/picture_header.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "tape/error.hpp"
#include "tape/file_io.hpp"

namespace tape::scan {
namespace {

constexpr std::string_view formats_read = "PNG, JPEG, TIFF or BMP";

// Bytes as numbers, big- or little-endian; 0 past the end (the callers check the length first).
std::uint32_t number(std::span<const std::uint8_t> b, std::size_t at, std::size_t n, bool big) {
    if (at > b.size() || n > b.size() - at) return 0;
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < n; ++i) v |= std::uint32_t{b[at + i]} << (8 * (big ? n - 1 - i : i));
    return v;
}

bool begins(std::span<const std::uint8_t> b, std::string_view s) {
    return b.size() >= s.size() && std::memcmp(b.data(), s.data(), s.size()) == 0;
}

std::optional<PictureHeader> png(std::span<const std::uint8_t> b) {
    if (b.size() < 24 || !std::equal(b.begin() + 12, b.begin() + 16, "IHDR")) return std::nullopt;
    return PictureHeader{"PNG", number(b, 16, 4, true), number(b, 20, 4, true)};
}

// Markers up to the first start of frame (SOF0-SOF15, not DHT, JPG or DAC), as libjpeg reads them.
std::optional<PictureHeader> jpeg(std::span<const std::uint8_t> b) {
    std::size_t at = 2;
    while (at + 1 < b.size()) {
        if (b[at] != 0xFF) return std::nullopt;
        std::uint8_t m = b[at + 1];
        if (m == 0xFF) {  // fill byte
            ++at;
            continue;
        }
        if (m == 0x01 || (m >= 0xD0 && m <= 0xD8)) {  // no length
            at += 2;
            continue;
        }
        if (m == 0xD9 || m == 0xDA) return std::nullopt;  // image end or data before any frame
        if (m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC) {
            if (at + 9 > b.size()) return std::nullopt;
            return PictureHeader{"JPEG", number(b, at + 7, 2, true), number(b, at + 5, 2, true)};
        }
        at += 2 + number(b, at + 2, 2, true);
    }
    return std::nullopt;
}

// The first directory's ImageWidth (256) and ImageLength (257), SHORT or LONG.
std::optional<PictureHeader> tiff(std::span<const std::uint8_t> b) {
    bool big = b[0] == 'M';
    std::size_t dir = number(b, 4, 4, big);
    if (dir < 8 || dir > b.size() || b.size() - dir < 2) return std::nullopt;
    std::size_t entries = number(b, dir, 2, big);
    std::uint64_t width = 0, height = 0;
    for (std::size_t i = 0; i < entries; ++i) {
        std::size_t e = dir + 2 + 12 * i;
        if (e + 12 > b.size()) return std::nullopt;
        std::uint32_t tag = number(b, e, 2, big), type = number(b, e + 2, 2, big);
        if (tag != 256 && tag != 257) continue;
        if (type != 3 && type != 4) return std::nullopt;
        // A tag written twice: libtiff keeps the first, another reader may keep the last; the bound
        // holds for either when the larger counts.
        auto& side = tag == 256 ? width : height;
        side = std::max<std::uint64_t>(side, number(b, e + 8, type == 3 ? 2 : 4, big));
    }
    if (!width || !height) return std::nullopt;
    return PictureHeader{"TIFF", width, height};
}

// BITMAPCOREHEADER (OS/2, 16-bit sizes) or a later info header (32-bit, a negative height top-down).
std::optional<PictureHeader> bmp(std::span<const std::uint8_t> b) {
    if (b.size() < 26) return std::nullopt;
    if (number(b, 14, 4, false) == 12) return PictureHeader{"BMP", number(b, 18, 2, false), number(b, 20, 2, false)};
    auto height = static_cast<std::int32_t>(number(b, 22, 4, false));
    auto width = static_cast<std::int32_t>(number(b, 18, 4, false));
    auto size = [](std::int32_t v) { return static_cast<std::uint64_t>(v < 0 ? -static_cast<std::int64_t>(v) : v); };
    return PictureHeader{"BMP", size(width), size(height)};
}

Error refusal(const std::string& why) { return Error(Errc::bad_image, why); }

}  // namespace

std::string_view picture_signature(std::span<const std::uint8_t> b) {
    if (begins(b, "\x89PNG\r\n\x1A\n")) return "PNG";
    if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return "JPEG";
    if (begins(b, std::string_view("II*\0", 4)) || begins(b, std::string_view("MM\0*", 4))) return "TIFF";
    if (begins(b, "BM")) return "BMP";
    return "";
}

std::optional<PictureHeader> read_picture_header(std::span<const std::uint8_t> b) {
    std::string_view f = picture_signature(b);
    if (f == "PNG") return png(b);
    if (f == "JPEG") return jpeg(b);
    if (f == "TIFF") return tiff(b);
    if (f == "BMP") return bmp(b);
    return std::nullopt;
}

PictureHeader check_picture(std::span<const std::uint8_t> bytes) {
    std::string_view f = picture_signature(bytes);
    if (f.empty())
        throw refusal("not a picture scan reads: it does not begin as a " + std::string(formats_read) + " file");
    auto h = read_picture_header(bytes);
    if (!h) throw refusal("a " + std::string(f) + " file whose header does not say its size: damaged or cut short");
    if (h->width == 0 || h->height == 0) throw refusal("a " + std::string(f) + " picture with no pixels");
    std::uint64_t pixels = h->width * h->height;  // each below 2^32: no overflow
    if (pixels > max_picture_pixels)
        throw refusal("a picture of " + std::to_string(h->width) + " x " + std::to_string(h->height) + " pixels (" +
                      std::to_string(pixels / 1'000'000) + " Mpx): scan reads at most " +
                      std::to_string(max_picture_pixels / 1'000'000) +
                      " Mpx; scan the tape in pieces, or at a lower resolution");
    return *h;
}

std::vector<std::uint8_t> read_picture_file(const std::string& path) {
    const std::string too_big =
        "more than " + std::to_string(max_picture_bytes >> 20) + " MiB: larger than any picture scan reads";
    struct stat st {};
    if (path != "-" && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        static_cast<std::uint64_t>(st.st_size) > max_picture_bytes)
        throw refusal(too_big);
    FileSource source(path);
    std::vector<std::uint8_t> out(picture_signature_bytes);
    out.resize(source.read_full(out));
    if (picture_signature(out).empty())
        throw refusal("not a picture scan reads: it does not begin as a " + std::string(formats_read) + " file");
    std::array<std::uint8_t, 64 << 10> chunk;
    while (std::size_t n = source.read(chunk)) {
        if (out.size() + n > max_picture_bytes) throw refusal(too_big);
        out.insert(out.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
    }
    return out;
}

}  // namespace tape::scan
