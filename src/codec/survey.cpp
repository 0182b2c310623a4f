#include "tape/survey.hpp"

namespace tape {

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

void Surveyor::feed(std::span<const Frame> frames) {
    s_.frames += frames.size();
    ParityCounts p = count_parity(frames);
    s_.parity.frames += p.frames;
    s_.parity.even += p.even;
    s_.parity.odd += p.odd;
    s_.parity.mark += p.mark;
    s_.parity.space += p.space;
    for (Frame f : frames) {
        if (f == blank_frame) {
            ++blank_run_;
            continue;
        }
        // Blanks before the first punched frame are leader; between punched frames, inside.
        (punched_ ? s_.blank_inside : s_.leader) += blank_run_;
        blank_run_ = 0;
        punched_ = true;
        switch (code_.kind(f)) {
            case FrameKind::blank:
                ++s_.blank_inside;
                continue;
            case FrameKind::rubout:
                ++s_.rubouts;
                continue;
            case FrameKind::parity_error:
                ++s_.parity_errors;
                continue;
            case FrameKind::not_in_code:
                ++s_.not_in_code;
                continue;
            case FrameKind::character:
                break;
        }
        ++s_.data;
        char c = code_.character(f);
        // A '%' starts a program only when one follows it: the '%' that closes the last program (the
        // rewind stop) is followed by nothing but line ends and blank tape. A run such as "%%" counts once.
        if (c == '%') {
            percent_ = true;
        } else if (c != ' ' && c != '\n' && c != '\r') {
            s_.program_starts += percent_;
            percent_ = false;
        }
        if (c == '\n') ++s_.end_of_blocks;
    }
}

TapeSurvey Surveyor::result() const {
    TapeSurvey s = s_;
    (punched_ ? s.trailer : s.leader) += blank_run_;
    return s;
}

TapeSurvey survey(std::span<const Frame> frames, const FrameCode& code) {
    Surveyor surveyor(code);
    surveyor.feed(frames);
    return surveyor.result();
}

}  // namespace tape
