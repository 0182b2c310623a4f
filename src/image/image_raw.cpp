// raw: one byte per frame in tape order, bit 0 = track 1 ... bit 7 = track 8.
// The same as the raw paper-tape images of the SIMH simulators (attach ptr/ptp).
#include "image_formats.hpp"

namespace tape {
namespace {

constexpr std::string_view raw_extensions[] = {".ptp", ".bin", ".tape", ".raw", ".ptr"};

int raw_match(std::span<const std::uint8_t>) { return 1; }  // any bytes are a raw tape

std::vector<Frame> raw_read(std::span<const std::uint8_t> bytes) { return {bytes.begin(), bytes.end()}; }

std::string raw_write(std::span<const Frame> frames, const ImageWriteOptions&) {
    return {reinterpret_cast<const char*>(frames.data()), frames.size()};
}

}  // namespace

ImageFormat raw_image_format() {
    return {"raw", "one byte per frame, bit 0 = track 1 (SIMH paper-tape images)", raw_extensions, true,
            raw_match, raw_read, raw_write};
}

}  // namespace tape
