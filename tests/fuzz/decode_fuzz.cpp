// libFuzzer target: any bytes as a tape image, decoded every way the CLI can.
// The first byte picks the options, the rest is the image.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

#include "tape/decode.hpp"
#include "tape/detect.hpp"
#include "tape/error.hpp"
#include "tape/image.hpp"
#include "tape/survey.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    std::uint8_t pick = data[0];
    std::span<const std::uint8_t> bytes(data + 1, size - 1);
    const tape::ImageFormat& format = tape::detect_image_format(bytes.first(std::min<std::size_t>(bytes.size(), 4096)));
    std::vector<tape::Frame> frames;
    try {
        frames = format.read(bytes);
    } catch (const tape::Error&) {
        return 0;
    }
    tape::DecodeOptions o;
    o.code = (pick & 1) ? tape::Code::eia : tape::Code::iso;
    o.parity = static_cast<tape::Parity>((pick >> 1) % 5);
    o.keep_going = pick & 0x10;
    o.positions = pick & 0x20;
    o.charset = (pick & 0x40) ? tape::Charset::koi7 : tape::Charset::ascii;
    auto r = tape::decode(frames, o);
    if (o.positions && r.frame_of.size() != r.text.size()) __builtin_trap();
    // Decoding stops at a bad frame only; blank tape inside a block is a warning and goes on.
    bool bad = std::any_of(r.diagnostics.begin(), r.diagnostics.end(),
                           [](const tape::Diagnostic& d) { return tape::is_bad_frame(d.code); });
    if (r.complete != (o.keep_going || !bad)) __builtin_trap();
    tape::detect_code(frames);
    tape::survey(frames, tape::FrameCode::make(o.code, o.parity));
    return 0;
}
