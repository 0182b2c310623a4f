// libFuzzer target: any bytes as a hex dump (src/image/image_dump.cpp). The reader accepts or refuses
// with a bad_image error and its line; cut anywhere it gives the same frames; match() answers 0 to 100.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tape/error.hpp"
#include "tape/image.hpp"

namespace {

std::vector<tape::Frame> read_in_two(const tape::ImageFormat& f, std::span<const std::uint8_t> bytes, std::size_t cut) {
    auto reader = f.make_reader();
    std::vector<tape::Frame> frames;
    reader->read(bytes.first(cut), frames);
    reader->read(bytes.subspan(cut), frames);
    reader->finish(frames);
    return frames;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const tape::ImageFormat* dump = tape::find_image_format("dump");
    std::span<const std::uint8_t> bytes(data, size);
    int score = dump->match(bytes);
    if (score < 0 || score > 100) __builtin_trap();
    std::vector<tape::Frame> whole;
    try {
        whole = dump->read(bytes);
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::bad_image || !e.where().line) __builtin_trap();
        return 0;
    }
    if (read_in_two(*dump, bytes, size ? data[0] % (size + 1) : 0) != whole) __builtin_trap();
    return 0;
}
