// Decoder for the 5-track telegraph codes (ITA2, МТК-2): a frame means what the last shift made it
// mean, so the decoding follows the register frame by frame. Kept apart from the ISO/EIA loops, which
// do not pay for it: Decoder::feed branches here once a chunk.
#include "tape/decode.hpp"
#include "tape/five_track.hpp"

namespace tape {

void Decoder::put_held_cr(DecodeResult& out) {
    for (std::uint64_t index : held_cr_) {
        out.text += '\r';
        if (options_.positions) out.frame_of.push_back(index);
    }
    held_cr_.clear();
}

void Decoder::put_text(std::string_view text, std::uint64_t index, DecodeResult& out) {
    out.text += text;
    if (options_.positions) out.frame_of.insert(out.frame_of.end(), text.size(), index);
}

// Frames with tracks 6-8 and the positions with no agreed character are reported, never guessed;
// counted past the message limit like the bad frames of the 8-track codes.
void Decoder::five_track_bad(Frame f, std::uint64_t index, const std::string& what, DecodeResult& out) {
    put_held_cr(out);
    ++other_seen_;
    last_bad_ = index;
    if (options_.max_diagnostics == 0 || other_seen_ <= options_.max_diagnostics)
        out.diagnostics.push_back(
            Diagnostic{Errc::not_in_code, Position{.frame = index + 1}, what + ", holes " + holes_picture(f)});
    if (options_.keep_going)
        put_text(bad_frame_marker, index, out);
    else
        stopped_ = true;
}

bool Decoder::feed_five_track(std::span<const Frame> frames, DecodeResult& out) {
    using Kind = FiveTrackTable::Kind;
    const FiveTrackTable& table = *code_.five_track_table();
    const std::uint64_t base = next_index_;
    for (std::size_t i = 0; i < frames.size() && !stopped_; ++i) {
        Frame f = frames[i];
        std::uint64_t index = base + i;
        if (f >= five_track_frames) {
            five_track_bad(f, index, "not a 5-track frame (tracks 6-8 punched)", out);
            continue;
        }
        const FiveTrackTable::Meaning& m = table.meaning(register_, f);
        switch (m.kind) {
            case Kind::blank:
                break;
            case Kind::shift:
                register_ = m.shift;
                break;
            case Kind::none:
                five_track_bad(f, index,
                               std::string(table.register_name(register_)) + " " + table.label(0, f) +
                                   " has no agreed character in " + (code_.code() == Code::mtk2 ? "МТК-2" : "ITA2") +
                                   " (national use)",
                               out);
                break;
            case Kind::character:
                // CR (or CR CR) before LF is the telegraph's line end: the text has LF alone. Any other
                // CR is kept; so the CRs wait until the next character says which they are.
                if (m.text == "\r") {
                    held_cr_.push_back(index);
                    break;
                }
                if (m.text == "\n")
                    held_cr_.clear();
                else
                    put_held_cr(out);
                put_text(m.text, index, out);
                if (options_.unshift_on_space && m.text == " ") register_ = 0;  // back to letters
                break;
        }
    }
    next_index_ += frames.size();
    if (!out.text.empty()) last_char_ = out.text.back();
    if (stopped_) out.complete = false;
    return !stopped_;
}

void Decoder::finish(DecodeResult& out) {
    if (!stopped_) put_held_cr(out);
}

}  // namespace tape
