// hex: a hex dump of the frames, as hobby tape readers and serial terminals save it: two hex digits a
// frame, separated by blanks, any number a line; '#' starts a comment to the end of the line. Read
// only: raw is the exact format to write, holes the one to look at.
#include <cctype>

#include "image_formats.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

constexpr std::string_view hex_extensions[] = {".hex"};

int digit_value(std::uint8_t c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<std::uint8_t>(std::tolower(c));
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

// Only a file of hex pairs, blanks and comments is a dump; anything else (a text program) is not.
int hex_match(std::span<const std::uint8_t> prefix) {
    std::size_t pairs = 0, run = 0;
    bool comment = false;
    for (std::uint8_t c : prefix) {
        if (comment) {
            comment = c != '\n';
            continue;
        }
        if (digit_value(c) >= 0) {
            if (++run > 2) return 0;
            continue;
        }
        if (run == 1 || (c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != '#')) return 0;
        pairs += run == 2;
        run = 0;
        comment = c == '#';
    }
    return pairs >= 4 ? 70 : 0;
}

class HexReader : public ImageReader {
public:
    void read(std::span<const std::uint8_t> bytes, std::vector<Frame>& out) override {
        for (std::uint8_t c : bytes) take(c, out);
    }
    void finish(std::vector<Frame>& out) override { take('\n', out); }  // the last line may lack its LF

private:
    void take(std::uint8_t c, std::vector<Frame>& out) {
        ++offset_;
        if (comment_) {
            comment_ = c != '\n';
            if (c == '\n') ++line_;
            return;
        }
        int v = digit_value(c);
        if (v >= 0) {
            if (digits_ == 2) fail("more than two hex digits in a frame");
            value_ = value_ * 16 + v;
            ++digits_;
            return;
        }
        if (digits_ == 1) fail("a frame needs two hex digits");
        if (digits_ == 2) out.push_back(static_cast<Frame>(value_));
        digits_ = value_ = 0;
        if (c == '#')
            comment_ = true;
        else if (c == '\n')
            ++line_;
        else if (c != ' ' && c != '\t' && c != '\r')
            fail(std::string("'") + static_cast<char>(c) + "' is no hex digit");
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw Error(Errc::bad_image, Position{.line = line_, .byte = offset_ - 1}, why);
    }

    std::uint64_t line_ = 1, offset_ = 0;
    int digits_ = 0, value_ = 0;
    bool comment_ = false;
};

}  // namespace

ImageFormat hex_image_format() {
    return {.id = "hex",
            .description = "hex dump, two digits a frame (read only)",
            .extensions = hex_extensions,
            .binary = false,
            .bytes_are_frames = false,
            .match = hex_match,
            .make_reader = []() -> std::unique_ptr<ImageReader> { return std::make_unique<HexReader>(); },
            .make_writer = nullptr};
}

}  // namespace tape
