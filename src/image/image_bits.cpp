// bits: a hand transcription of a tape, one frame a line as eight binary digits, a 1 for a hole:
//     10001101
//     00001010
// Track 8 is the leftmost digit, as the code tables write a frame (track 8 ... track 1) and as such
// transcriptions are made: read so, a real one (a Teletype tape) is even-parity ASCII, read the other
// way round it is no code at all. An empty line between frames is blank tape: transcribers leave one
// where the tape had a stretch without holes (between repeats of a message); it is read as one blank
// frame. '#' starts a comment. Read only: raw is the exact format to write, holes the one to look at.
#include "image_formats.hpp"
#include "line_reader.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

constexpr std::string_view bits_extensions[] = {".bits"};
constexpr std::size_t digits = 8;

// One line: a frame, nothing (an empty or comment line: `empty` says which), or false for a line that
// is not eight binary digits.
bool parse_bits(std::string_view line, std::optional<Frame>& frame, bool& empty) {
    auto hash = line.find('#');
    bool comment = hash != std::string_view::npos;
    line = line.substr(0, hash);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.remove_suffix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    frame.reset();
    empty = line.empty() && !comment;
    if (line.empty()) return true;
    if (line.size() != digits) return false;
    unsigned v = 0;
    for (char c : line) {
        if (c != '0' && c != '1') return false;
        v = v * 2 + static_cast<unsigned>(c - '0');
    }
    frame = static_cast<Frame>(v);
    return true;
}

// Only a file of such lines is one: a hex dump's 8-digit offsets hold other digits than 0 and 1.
int bits_match(std::span<const std::uint8_t> prefix) {
    std::string_view text(reinterpret_cast<const char*>(prefix.data()), prefix.size());
    std::size_t frames = 0;
    while (!text.empty()) {
        auto nl = text.find('\n');
        bool cut = nl == std::string_view::npos;
        std::optional<Frame> f;
        bool empty = false;
        if (!parse_bits(text.substr(0, nl), f, empty) && !cut) return 0;
        frames += f.has_value();
        text.remove_prefix(cut ? text.size() : nl + 1);
    }
    return frames >= 4 ? 90 : 0;  // above dump, which takes a line of 8 digits for an offset
}

class BitsReader : public LineReader {
private:
    // Empty lines after the last frame are no tape: blank frames wait for the frame after them.
    void take_line(std::string_view line, std::vector<Frame>& out) override {
        std::optional<Frame> f;
        bool empty = false;
        if (!parse_bits(line, f, empty))
            fail("expected one frame a line as eight binary digits (0 or 1), track 8 first");
        if (empty && seen_frame_) ++blanks_;
        if (!f) return;
        out.insert(out.end(), blanks_, blank_frame);
        blanks_ = 0;
        out.push_back(*f);
        seen_frame_ = true;
    }

    std::uint64_t blanks_ = 0;
    bool seen_frame_ = false;
};

}  // namespace

ImageFormat bits_image_format() {
    return {.id = "bits",
            .description = "one frame a line as 8 binary digits, track 8 first (hand transcriptions; read only)",
            .extensions = bits_extensions,
            .binary = false,
            .bytes_are_frames = false,
            .match = bits_match,
            .make_reader = []() -> std::unique_ptr<ImageReader> { return std::make_unique<BitsReader>(); },
            .make_writer = nullptr};
}

}  // namespace tape
