// libFuzzer target: any bytes as a holes picture (src/image/image_holes.cpp). What the reader accepts must
// come back unchanged through the writer, annotated or not; match() must answer for any prefix.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const tape::ImageFormat* holes = tape::find_image_format("holes");
    static const tape::FrameCode iso = tape::FrameCode::iso();
    std::span<const std::uint8_t> bytes(data, size);
    int score = holes->match(bytes);
    if (score < 0 || score > 100) __builtin_trap();
    std::vector<tape::Frame> frames;
    try {
        frames = holes->read(bytes);
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::bad_image || !e.where().line) __builtin_trap();
        return 0;
    }
    for (const tape::FrameCode* annotate : {static_cast<const tape::FrameCode*>(nullptr), &iso}) {
        std::string text = holes->write(frames, tape::ImageWriteOptions{annotate});
        std::span<const std::uint8_t> written(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
        if (holes->read(written) != frames) __builtin_trap();
        if (!frames.empty() && holes->match(written) != 100) __builtin_trap();
    }
    return 0;
}
