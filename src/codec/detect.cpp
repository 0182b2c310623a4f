// Code and parity detection.
#include "tape/detect.hpp"

namespace tape {
namespace {

constexpr Frame iso_lf = 0x0A, eia_eob = 0x80, iso_percent = 0xA5, eia_rewind_stop = 0x0B;
constexpr std::size_t look_limit = 4096;  // significant frames looked at when no end of block comes

bool significant(Frame f) { return f != 0x00 && f != 0xFF && f != 0x7F; }

std::string count_text(std::uint64_t n, const char* what) { return std::to_string(n) + " " + what; }

}  // namespace

CodeDetection detect_code(std::span<const Frame> frames) {
    std::uint64_t seen = 0, even = 0;
    std::optional<Frame> end_of_block;
    bool iso_start = false, eia_start = false;
    for (Frame f : frames) {
        if (!significant(f)) continue;
        ++seen;
        if (hole_count(f) % 2 == 0) ++even;
        iso_start |= f == iso_percent;
        eia_start |= f == eia_rewind_stop;
        if (f == iso_lf || f == eia_eob) {
            end_of_block = f;
            break;
        }
        if (seen == look_limit) break;
    }
    if (seen == 0) return {Code::iso, "no punched frames: blank tape, read as ISO"};
    std::uint64_t odd = seen - even;
    std::string where = end_of_block ? "before the first end of block" : "at the start of the tape";
    std::string counts =
        count_text(even, "even") + ", " + count_text(odd, "odd") + " of " + count_text(seen, "frames") + " " + where;
    bool mostly_even = even * 10 >= seen * 9, mostly_odd = odd * 10 >= seen * 9;
    if (end_of_block == iso_lf && mostly_even) return {Code::iso, "ISO: end of block LF, " + counts};
    if (end_of_block == eia_eob && mostly_odd) return {Code::eia, "EIA: end of block on track 8, " + counts};
    if (!end_of_block && mostly_even && !eia_start) return {Code::iso, "ISO: " + counts};
    if (!end_of_block && mostly_odd && !iso_start) return {Code::eia, "EIA: " + counts};
    auto parity = count_parity(frames.first(std::min(frames.size(), look_limit * 4))).dominant();
    if (parity == Parity::mark || parity == Parity::space || parity == Parity::odd)
        return {std::nullopt,
                "neither ISO nor EIA: the frames look like an ASCII tape with " + std::string(parity_name(*parity)) +
                    " parity on track 8; " + counts,
                Hint{Hint::Action::use_iso_parity, parity_name(*parity)}};
    return {std::nullopt, "neither ISO nor EIA: " + counts + (end_of_block ? "" : ", and no end of block")};
}

ParityCounts count_parity(std::span<const Frame> frames) {
    ParityCounts c;
    for (Frame f : frames) {
        if (f == 0) continue;
        ++c.frames;
        if (hole_count(f) % 2 == 0) ++c.even;
        if (f & 0x80) ++c.mark;
    }
    c.odd = c.frames - c.even;
    c.space = c.frames - c.mark;
    return c;
}

std::uint64_t ParityCounts::misfits(Parity p) const {
    switch (p) {
        case Parity::even:
            return frames - even;
        case Parity::odd:
            return frames - odd;
        case Parity::mark:
            return frames - mark;
        case Parity::space:
            return frames - space;
        case Parity::none:
            return 0;
    }
    return frames;
}

std::optional<Parity> ParityCounts::dominant() const {
    if (frames == 0) return std::nullopt;
    Parity best = Parity::even;
    for (Parity p : {Parity::odd, Parity::mark, Parity::space})
        if (misfits(p) < misfits(best)) best = p;
    if (misfits(best) * 10 > frames) return std::nullopt;
    return best;
}

}  // namespace tape
