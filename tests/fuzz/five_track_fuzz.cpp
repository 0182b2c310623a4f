// libFuzzer target: any bytes as the frames of a 5-track telegraph tape (ITA2 or МТК-2). The first byte
// picks the code, the options and where the tape is cut into chunks; the rest are the frames. The text
// is the same however the tape is cut, has a frame for each of its bytes (with positions), and a
// clean tape's text punched again in the same code reads back the same.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tape/decode.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"

namespace {

tape::DecodeResult in_chunks(std::span<const tape::Frame> frames, const tape::DecodeOptions& o, std::size_t chunk) {
    tape::Decoder decoder(o);
    tape::DecodeResult r;
    for (std::size_t at = 0; at < frames.size(); at += chunk)
        if (!decoder.feed(frames.subspan(at, std::min(chunk, frames.size() - at)), r)) break;
    decoder.finish(r);
    return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    std::uint8_t pick = data[0];
    std::span<const tape::Frame> frames(data + 1, std::min<std::size_t>(size - 1, 1 << 16));
    tape::DecodeOptions o;
    o.code = (pick & 1) ? tape::Code::mtk2 : tape::Code::ita2;
    o.keep_going = pick & 2;
    o.positions = pick & 4;
    tape::DecodeResult whole = tape::decode(frames, o);
    tape::DecodeResult cut = in_chunks(frames, o, 1 + (pick >> 3));
    if (whole.text != cut.text || whole.frame_of != cut.frame_of || whole.complete != cut.complete ||
        whole.diagnostics.size() != cut.diagnostics.size())
        __builtin_trap();
    if (o.positions && whole.frame_of.size() != whole.text.size()) __builtin_trap();
    for (auto f : whole.frame_of)
        if (f >= frames.size()) __builtin_trap();
    if (!whole.ok() || whole.text.empty()) return 0;
    tape::EncodeOptions eo;
    eo.code = o.code;
    eo.leader = eo.trailer = 0;
    std::vector<tape::Frame> again;
    try {
        again = tape::encode(whole.text, eo);
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::bad_text) __builtin_trap();
        return 0;
    }
    tape::DecodeOptions plain{.code = o.code};
    if (tape::decode(again, plain).text != whole.text) __builtin_trap();
    return 0;
}
