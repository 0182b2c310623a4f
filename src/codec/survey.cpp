#include "tape/survey.hpp"

namespace tape {

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
        if (c == '%' && !after_percent_) ++s_.program_starts;
        if (c == '\n') ++s_.end_of_blocks;
        if (c != ' ') after_percent_ = c == '%';
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
