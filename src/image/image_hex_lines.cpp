// hex8 and hex5: one frame a line as two hex digits, as hobby readers and archives keep tapes:
//     # read from the box in the attic
//     1F
//     03        # a comment may follow the frame
// Blank lines and '#' comments are allowed. hex8 holds any frame of 8-track tape; hex5 the frames of
// 5-track tape (00 to 1F), so that a value with tracks 6-8 is a fault of the file, not a frame. Both
// are written too: the writer puts a header comment, then one frame a line.
#include <cstdio>

#include "image_formats.hpp"
#include "line_reader.hpp"
#include "tape/error.hpp"
#include "tape/five_track.hpp"

namespace tape {
namespace {

constexpr std::string_view hex8_extensions[] = {".hex8"};
constexpr std::string_view hex5_extensions[] = {".hex5"};

int digit_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// One line: nullopt for a blank or comment line, the frame, or throws with why (no position).
struct LineFault {
    std::string why;
};
std::optional<Frame> parse_line(std::string_view line, int tracks) {
    line = trim(line);
    if (line.empty() || line[0] == '#') return std::nullopt;
    auto hash = line.find('#');
    std::string_view value = trim(line.substr(0, hash));
    if (value.size() != 2 || digit_value(value[0]) < 0 || digit_value(value[1]) < 0)
        throw LineFault{"expected one frame a line as two hex digits, such as 1F"};
    auto f = static_cast<Frame>(digit_value(value[0]) * 16 + digit_value(value[1]));
    if (tracks == 5 && f >= five_track_frames)
        throw LineFault{"'" + std::string(value) +
                        "' is no 5-track frame: tracks 6-8 punched (hex5 frames are 00 to 1F)"};
    return f;
}

// A file of such lines is one of these; hex5 only where every frame fits 5 tracks and some are punched
// (a blank leader alone says nothing). The last line may be cut by the end of the prefix.
int lines_match(std::span<const std::uint8_t> prefix, int tracks) {
    std::string_view text(reinterpret_cast<const char*>(prefix.data()), prefix.size());
    std::size_t frames = 0, punched = 0;
    bool five = true;
    while (!text.empty()) {
        auto nl = text.find('\n');
        bool cut = nl == std::string_view::npos;
        std::string_view line = text.substr(0, nl);
        text.remove_prefix(cut ? text.size() : nl + 1);
        try {
            if (auto f = parse_line(line, 8)) {
                ++frames;
                punched += *f != 0;
                five &= *f < five_track_frames;
            }
        } catch (const LineFault&) {
            if (!cut) return 0;
        }
    }
    if (frames < 4) return 0;
    if (tracks == 8) return 75;  // above hex, which reads such a file as the same frames
    return five && punched >= 4 ? 80 : 0;
}

class LinesReader : public LineReader {
public:
    explicit LinesReader(int tracks) : tracks_(tracks) {}
    std::optional<Code> declared_code() const override { return declared_; }

private:
    void take_line(std::string_view line, std::vector<Frame>& out) override {
        if (!declared_ && frames_ == 0) declared_ = header_code(line);  // the header comes before the frames
        try {
            if (auto f = parse_line(line, tracks_)) {
                out.push_back(*f);
                ++frames_;
            }
        } catch (const LineFault& fault) {
            fail(fault.why);
        }
    }

    int tracks_;
    std::uint64_t frames_ = 0;
    std::optional<Code> declared_;
};

class LinesWriter : public ImageWriter {
public:
    LinesWriter(const ImageWriteOptions& options, int tracks)
        : options_(options), tracks_(tracks), number_(options.first_number) {}
    void write(std::span<const Frame> frames, std::string& out) override {
        header(out);
        char text[4];
        for (Frame f : frames) {
            if (tracks_ == 5 && f >= five_track_frames)
                throw Error(Errc::usage, Position{.frame = number_},
                            "a frame with tracks 6-8 punched does not fit 5-track tape (hex5); write hex8");
            std::snprintf(text, sizeof text, "%02X\n", f);
            out += text;
            ++number_;
        }
    }
    void finish(std::string& out) override { header(out); }  // an empty tape still says what it is

private:
    void header(std::string& out) {
        if (!options_.header || header_written_) return;
        header_written_ = true;
        out += tracks_ == 5 ? "# tape hex5 image: one 5-track frame a line, two hex digits (bit 0 = track 1)\n"
                            : "# tape hex8 image: one frame a line, two hex digits (bit 0 = track 1)\n";
        if (options_.annotate) out += "# code: " + std::string(code_name(options_.annotate->code())) + "\n";
    }

    ImageWriteOptions options_;
    int tracks_;
    std::uint64_t number_;
    bool header_written_ = false;
};

}  // namespace

ImageFormat hex8_image_format() {
    return {.id = "hex8",
            .description = "one frame a line, two hex digits (8-track)",
            .extensions = hex8_extensions,
            .binary = false,
            .bytes_are_frames = false,
            .match = [](std::span<const std::uint8_t> prefix) { return lines_match(prefix, 8); },
            .make_reader = []() -> std::unique_ptr<ImageReader> { return std::make_unique<LinesReader>(8); },
            .make_writer = [](const ImageWriteOptions& options) -> std::unique_ptr<ImageWriter> {
                return std::make_unique<LinesWriter>(options, 8);
            },
            .tracks = 8};
}

ImageFormat hex5_image_format() {
    return {.id = "hex5",
            .description = "one 5-track frame a line, two hex digits 00 to 1F (ITA2, МТК-2)",
            .extensions = hex5_extensions,
            .binary = false,
            .bytes_are_frames = false,
            .match = [](std::span<const std::uint8_t> prefix) { return lines_match(prefix, 5); },
            .make_reader = []() -> std::unique_ptr<ImageReader> { return std::make_unique<LinesReader>(5); },
            .make_writer = [](const ImageWriteOptions& options) -> std::unique_ptr<ImageWriter> {
                return std::make_unique<LinesWriter>(options, 5);
            },
            .tracks = 5};
}

}  // namespace tape
