// libFuzzer target: a picture file given to tape scan, up to its decoding. Its header is read for its
// size (PNG, JPEG, TIFF, BMP) and the picture refused above the pixel bound before any decoder runs;
// one that passes, and is small enough for a fuzzer's memory (a megapixel), is decoded by the picture
// module as scan decodes it. Whatever comes in: the header is read within the bytes, a refusal is an
// Error in words, and a picture decoded is no larger than its header declared: the bound holds.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "scan/picture_header.hpp"
#include "tape/error.hpp"
#include "tape/picture.hpp"
#include "tape/scan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::span<const std::uint8_t> bytes(data, size);
    tape::scan::PictureHeader h;
    try {
        h = tape::scan::check_picture(bytes);
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::bad_image || std::string_view(e.what()).empty()) __builtin_trap();
        return 0;
    }
    if (h.width * h.height > tape::scan::max_picture_pixels) __builtin_trap();
    constexpr std::uint64_t fuzzer_pixels = 1 << 20;
    if (h.width * h.height > fuzzer_pixels || !tape::scan_available()) return 0;
    try {
        tape::Picture p = tape::decode_picture(bytes);
        // No larger than its header says (OpenCV reads the same header; a JPEG's orientation may turn it).
        if (static_cast<std::uint64_t>(p.width) * static_cast<std::uint64_t>(p.height) > h.width * h.height)
            __builtin_trap();
    } catch (const tape::Error& e) {
        if (std::string_view(e.what()).find("OpenCV(") != std::string_view::npos) __builtin_trap();
    }
    return 0;
}
