#include "tape/survey.hpp"

namespace tape {

TapeSurvey survey(std::span<const Frame> frames, const FrameCode& code) {
    TapeSurvey s;
    s.frames = frames.size();
    s.parity = count_parity(frames);
    std::size_t first = 0, last = frames.size();
    while (first < last && frames[first] == blank_frame) ++first;
    while (last > first && frames[last - 1] == blank_frame) --last;
    s.leader = first;
    s.trailer = frames.size() - last;
    bool after_percent = false;
    for (std::size_t i = first; i < last; ++i) {
        Frame f = frames[i];
        switch (code.kind(f)) {
        case FrameKind::blank: ++s.blank_inside; continue;
        case FrameKind::rubout: ++s.rubouts; continue;
        case FrameKind::parity_error: ++s.parity_errors; continue;
        case FrameKind::not_in_code: ++s.not_in_code; continue;
        case FrameKind::character: break;
        }
        ++s.data;
        char c = code.character(f);
        if (c == '%' && !after_percent) ++s.program_starts;
        if (c == '\n') ++s.end_of_blocks;
        if (c != ' ') after_percent = c == '%';
    }
    return s;
}

}  // namespace tape
