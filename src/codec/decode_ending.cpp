// How a tape ends: a program cut inside a block, or a tape without its blank trailer, is said, not
// passed over (the decoded text cannot show it).
#include "tape/decode.hpp"

namespace tape {

void Decoder::note_trailer(std::span<const Frame> frames) {
    std::size_t i = frames.size();
    while (i > 0 && frames[i - 1] == blank_frame) --i;
    if (i == 0) {
        trailer_ += frames.size();
        return;
    }
    last_punched_ = next_index_ + i - 1;
    trailer_ = frames.size() - i;
}

std::vector<Diagnostic> Decoder::ending() const {
    std::vector<Diagnostic> found;
    if (!last_punched_ || stopped_) return found;
    Position at{.frame = *last_punched_ + 1};
    if (last_char_) {
        auto c = static_cast<unsigned char>(*last_char_);
        std::string_view wide = code_.wide_character(c);
        // A telecode's controls are pictures (U+2400...) or its halt code (U+23F9).
        bool control = c < 0x20 || c == '%' || wide.starts_with("\xE2\x90") || wide == "\xE2\x8F\xB9";
        if (!control)
            found.push_back(Diagnostic{.code = Errc::bad_program,
                                       .where = at,
                                       .message = "the tape ends inside a block: its last character is no end of "
                                                  "block or line, so the end of the program may be missing",
                                       .severity = Severity::warning});
    }
    if (trailer_ == 0)
        found.push_back(Diagnostic{.code = Errc::bad_program,
                                   .where = at,
                                   .message = "the tape ends at a punched frame, without a blank trailer: it may "
                                              "have been cut here",
                                   .severity = Severity::warning});
    return found;
}

}  // namespace tape
