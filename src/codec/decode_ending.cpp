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
    if (!last_punched_ || stopped_) return {};
    bool mid_block = false;
    if (last_char_ && last_bad_ != last_punched_) {  // a bad last frame: what it was is not known
        auto c = static_cast<unsigned char>(*last_char_);
        std::string_view wide = code_.wide_character(c);
        // A telecode's controls are pictures (U+2400...) or its halt code (U+23F9).
        mid_block = !(c < 0x20 || c == '%' || wide.starts_with("\xE2\x90") || wide == "\xE2\x8F\xB9");
    }
    std::string message;
    if (mid_block && trailer_ == 0)
        message =
            "the tape ends inside a block, at a punched frame without a blank trailer: it was probably cut "
            "here, and the end of the program is missing";
    else if (mid_block)
        message =
            "the tape ends inside a block: its last character is no end of block or line, so the end of the "
            "program may be missing";
    else if (trailer_ == 0)
        message = "the tape ends at a punched frame, without a blank trailer: it may have been cut here";
    if (message.empty()) return {};
    return {Diagnostic{.code = Errc::bad_program,
                       .where = Position{.frame = *last_punched_ + 1},
                       .message = message,
                       .severity = Severity::warning}};
}

}  // namespace tape
