// raw: one byte per frame in tape order, bit 0 = track 1 ... bit 7 = track 8.
// The same as the raw paper-tape images of the SIMH simulators (attach ptr/ptp).
#include "image_formats.hpp"

namespace tape {
namespace {

// .ptap is DEC's paper-tape image; .rim and .bn hold PDP-8 RIM and BIN loader tapes.
constexpr std::string_view raw_extensions[] = {".ptp", ".bin", ".tape", ".raw", ".ptr", ".ptap", ".rim", ".bn"};

int raw_match(std::span<const std::uint8_t>) { return 1; }  // any bytes are a raw tape

class RawReader : public ImageReader {
public:
    void read(std::span<const std::uint8_t> bytes, std::vector<Frame>& out) override {
        out.insert(out.end(), bytes.begin(), bytes.end());
    }
    void finish(std::vector<Frame>&) override {}
};

class RawWriter : public ImageWriter {
public:
    void write(std::span<const Frame> frames, std::string& out) override {
        out.append(reinterpret_cast<const char*>(frames.data()), frames.size());
    }
};

}  // namespace

ImageFormat raw_image_format() {
    return {.id = "raw",
            .description = "one byte per frame, bit 0 = track 1 (SIMH paper-tape images)",
            .extensions = raw_extensions,
            .binary = true,
            .bytes_are_frames = true,
            .match = raw_match,
            .make_reader = []() -> std::unique_ptr<ImageReader> { return std::make_unique<RawReader>(); },
            .make_writer = [](const ImageWriteOptions&) -> std::unique_ptr<ImageWriter> {
                return std::make_unique<RawWriter>();
            }};
}

}  // namespace tape
