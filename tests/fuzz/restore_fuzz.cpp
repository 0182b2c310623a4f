// libFuzzer target: restoration of several reads of one tape. The first byte picks how many reads (1 to
// 4) and the code (none, ISO, EIA); the rest, cut into that many reads, are their frames, bounded (a
// few hundred frames a read) so that every input runs in a moment. Every frame written and every
// problem is accounted for: the counts add up, problems lie within the tape, in tape order.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/restore.hpp"

namespace {

constexpr std::size_t most_frames = 768;  // of all reads together

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    std::uint8_t pick = data[0];
    std::size_t reads = 1 + (pick & 3);
    std::span<const tape::Frame> all(data + 1, std::min(size - 1, most_frames));
    std::vector<std::span<const tape::Frame>> spans;
    std::size_t each = all.size() / reads;
    if (each == 0) return 0;
    for (std::size_t r = 0; r < reads; ++r) spans.push_back(all.subspan(r * each, each));
    tape::RestoreOptions o;
    int code = (pick >> 2) % 3;
    if (code == 1) o.code = tape::FrameCode::iso(tape::Parity::even);
    if (code == 2) o.code = tape::FrameCode::eia();
    tape::RestoreResult result;
    try {
        result = tape::restore(spans, o);
    } catch (const tape::Error& e) {
        // Reads of different tapes are refused, as data; nothing else may be thrown.
        if (!tape::is_data_error(e.code()) && e.code() != tape::Errc::usage) __builtin_trap();
        return 0;
    }
    if (result.reference >= reads || result.shared.size() > reads) __builtin_trap();
    std::uint64_t written = 0;
    for (std::size_t s = 0; s < tape::frame_status_count; ++s)
        if (static_cast<tape::FrameStatus>(s) != tape::FrameStatus::extra) written += result.counts[s];
    if (written < result.frames.size()) __builtin_trap();
    std::uint64_t last = 0;
    for (const auto& p : result.problems) {
        if (p.frame && (*p.frame == 0 || *p.frame > result.frames.size() + 1)) __builtin_trap();
        if (p.seen.size() > reads || p.covered.size() > reads) __builtin_trap();
        if (p.frame) {
            if (*p.frame < last) __builtin_trap();
            last = *p.frame;
        }
    }
    return 0;
}
