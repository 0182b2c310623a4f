// libFuzzer target: leader labels (letters of holes in a tape's leader). Any bytes as a tape's first
// frames: a label found lies within them, and its frames are those the font punches for its text (for
// ISO, track 8 aside: a label is read whatever parity rule it was punched with); a title in another font
// (tape/label.hpp) has no text and lies between blank tape. Any bytes as a label's
// text: what is punched is found again, with that text in capitals.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/label.hpp"

namespace {

// A title in another font is found, not read: no text; blank leader before it, punched frames at both of
// its ends, and at least 16 blank frames after it.
void check_title(std::span<const tape::Frame> frames, const tape::LeaderLabel& title) {
    if (!title.text.empty()) __builtin_trap();
    for (std::size_t i = 0; i < title.first; ++i)
        if (frames[i] != tape::blank_frame) __builtin_trap();
    std::size_t end = title.first + title.frames;
    if (frames[title.first] == tape::blank_frame || frames[end - 1] == tape::blank_frame) __builtin_trap();
    if (end + 16 > frames.size()) __builtin_trap();
    for (std::size_t i = end; i < end + 16; ++i)
        if (frames[i] != tape::blank_frame) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    std::span<const tape::Frame> frames(data + 1, size - 1);
    if (auto found = tape::find_label(frames)) {
        if (found->frames == 0 || found->first + found->frames > frames.size()) __builtin_trap();
        if (found->font == tape::LabelFont::title) {
            check_title(frames, *found);
            return 0;
        }
        if (found->text.empty()) __builtin_trap();
        auto code = tape::FrameCode::make(found->code, tape::Parity::even);
        auto punched = tape::label_frames(found->text, code);  // throws for a text the font lacks: a bug
        if (punched.size() != found->frames) __builtin_trap();
        // An ISO label reads whatever parity rule track 8 was punched by: the rest of each frame is the font's.
        tape::Frame care = found->code == tape::Code::iso ? 0x7F : 0xFF;
        for (std::size_t i = 0; i < punched.size(); ++i)
            if ((punched[i] & care) != (frames[found->first + i] & care)) __builtin_trap();
    }
    std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    auto code = tape::FrameCode::make((data[0] & 1) ? tape::Code::eia : tape::Code::iso, tape::Parity::even);
    std::vector<tape::Frame> tape(tape::label_blank_around, tape::blank_frame);
    try {
        auto label = tape::label_frames(text, code);
        tape.insert(tape.end(), label.begin(), label.end());
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::usage) __builtin_trap();
        return 0;
    }
    tape.insert(tape.end(), tape::label_blank_around, tape::blank_frame);
    auto again = tape::find_label(tape);
    if (!again || again->first != tape::label_blank_around || again->code != code.code()) __builtin_trap();
    if (tape::label_frames(again->text, code) !=
        std::vector<tape::Frame>(tape.begin() + tape::label_blank_around, tape.end() - tape::label_blank_around))
        __builtin_trap();
    return 0;
}
