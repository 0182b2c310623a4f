// libFuzzer target: any bytes as the frames of a binary loader tape (src/codec/binary_pdp8.cpp,
// binary_pdp11.cpp). Both families must read it, cut anywhere, to the same blocks and memory; every
// checksum span must lie inside the tape, and a span said to hold must hold when asked again.
#include <cstddef>
#include <cstdint>
#include <span>

#include "tape/binary_tape.hpp"

namespace {

tape::BinaryReader read(tape::BinaryReader::Family family, std::span<const tape::Frame> frames, std::size_t cut) {
    tape::BinaryReader r(family, true);
    r.feed(frames.first(cut));
    r.feed(frames.subspan(cut));
    r.finish();
    return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::span<const tape::Frame> frames(data, size);
    std::size_t cut = size ? data[0] % (size + 1) : 0;
    for (auto family : {tape::BinaryReader::Family::pdp8, tape::BinaryReader::Family::pdp11}) {
        tape::BinaryReader whole = read(family, frames, size), pieces = read(family, frames, cut);
        const tape::BinaryTape& t = whole.tape();
        if (t.summary() != pieces.tape().summary() || t.block_count != pieces.tape().block_count) __builtin_trap();
        if (tape::memory_image_bytes(whole.image()) != tape::memory_image_bytes(pieces.image())) __builtin_trap();
        if (t.blocks.size() > t.block_count ||
            t.checksums_held + t.checksums_failed + t.checksums_missing > t.block_count)
            __builtin_trap();
        for (const auto& b : t.blocks) {
            if (b.first + b.frames > size) __builtin_trap();
            if (!b.checksum) continue;
            const auto& c = *b.checksum;
            if (c.first + c.frames > size) __builtin_trap();
            if (c.state == tape::ChecksumSpan::State::holds && b.format == tape::BinaryFormat::pdp11_absolute &&
                !tape::checksum_holds(b.format, frames.subspan(c.first, c.frames)))
                __builtin_trap();
        }
        (void)tape::memory_image_octal(whole.image());
        (void)t.recognised();
    }
    return 0;
}
