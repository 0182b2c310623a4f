// dump: what hex dump programs print, read back: xxd ("00000010: 250a 4730  %.G0"), hexdump -C
// ("00000010  25 0a 47 30  |%.G0|") and od -t x1 ("0000020 25 0a 47 30", octal offsets). A line '*'
// stands for the line before it repeated up to the next offset (hexdump and od without -v print it);
// the offsets are checked, so nothing is lost or doubled. od's and hexdump's default dumps of 2-byte
// words are refused: which byte of a word came first on tape they do not show. Read only.
#include <algorithm>
#include <cctype>

#include "image_formats.hpp"
#include "line_reader.hpp"
#include "tape/error.hpp"
#include "tape/limits.hpp"

namespace tape {
namespace {

constexpr std::string_view dump_extensions[] = {".xxd"};  // else the content says it is a dump

enum class Style { none, xxd, hexdump, od, words };

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

std::size_t digits_at_start(std::string_view s, int radix) {
    std::size_t n = 0;
    while (n < s.size() && hex_value(s[n]) >= 0 && hex_value(s[n]) < radix) ++n;
    return n;
}

// The groups of hex digits in s, separated by blanks; false when something else is there or a group
// has an odd number of digits (or, with width, not that many).
bool hex_groups(std::string_view s, std::size_t width, std::vector<std::uint8_t>* bytes) {
    std::size_t i = 0;
    while (i < s.size()) {
        if (s[i] == ' ' || s[i] == '\t') {
            ++i;
            continue;
        }
        std::size_t n = digits_at_start(s.substr(i), 16);
        if (n == 0 || n % 2 || (width && n != width)) return false;
        for (std::size_t k = i; k < i + n; k += 2)
            if (bytes) bytes->push_back(static_cast<std::uint8_t>(hex_value(s[k]) * 16 + hex_value(s[k + 1])));
        i += n;
    }
    return true;
}

// One line of a dump: its offset (nullopt for '*'), its bytes, and the style it is in.
struct DumpLine {
    Style style = Style::none;
    bool repeat = false;  // '*'
    std::uint64_t offset = 0;
    std::vector<std::uint8_t> bytes;
};

DumpLine parse_dump_line(std::string_view line) {
    DumpLine d;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    if (line == "*") {
        d.repeat = true;
        d.style = Style::od;  // any style: the reader keeps the one it has
        return d;
    }
    std::size_t hex = digits_at_start(line, 16), oct = digits_at_start(line, 8);
    std::string_view rest = line.substr(hex);
    std::uint64_t value = 0;
    auto offset_in = [&](int radix, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) value = value * static_cast<unsigned>(radix) + hex_value(line[i]);
        d.offset = value;
    };
    if (hex >= 6 && rest.starts_with(": ")) {  // xxd
        auto gap = rest.find("  ", 2);         // two spaces end the hex area
        std::string_view area = rest.substr(2, gap == std::string_view::npos ? rest.npos : gap - 2);
        if (!hex_groups(area, 0, &d.bytes)) return d;
        offset_in(16, hex);
        d.style = Style::xxd;
    } else if (hex == 8 && (rest.empty() || rest.starts_with("  "))) {  // hexdump -C
        std::string_view area = rest.substr(0, rest.find('|'));
        if (!hex_groups(area, 2, &d.bytes)) return d;
        offset_in(16, hex);
        d.style = Style::hexdump;
    } else if (oct == 7 && hex == 7 && (rest.empty() || rest[0] == ' ')) {  // od, octal offsets
        offset_in(8, oct);
        if (hex_groups(rest, 2, &d.bytes))
            d.style = Style::od;
        else if (hex_groups(rest, 4, nullptr) || hex_groups(rest, 6, nullptr))
            d.style = Style::words;
    }
    return d;
}

int dump_match(std::span<const std::uint8_t> prefix) {
    std::string_view text(reinterpret_cast<const char*>(prefix.data()), prefix.size());
    std::size_t lines = 0;
    Style style = Style::none;
    while (!text.empty() && lines < 8) {
        auto nl = text.find('\n');
        if (nl == std::string_view::npos) break;  // the last line may be cut by the prefix's end
        DumpLine d = parse_dump_line(text.substr(0, nl));
        text.remove_prefix(nl + 1);
        if (d.style == Style::none) return 0;
        if (!d.repeat) {
            if (style != Style::none && d.style != style) return 0;
            style = d.style;
        }
        ++lines;
    }
    return lines >= 2 && style != Style::none ? 85 : 0;
}

class DumpReader : public LineReader {
private:
    void lines_done(std::vector<Frame>&) override {
        if (repeat_) fail("the dump ends with '*' and no offset after it: how often the line repeats is not known");
    }
    void take_line(std::string_view line, std::vector<Frame>& out) override {
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) return;
        DumpLine d = parse_dump_line(line);
        if (d.style == Style::none)
            fail("neither a line of xxd, hexdump -C nor od -t x1 output; dump the tape with od -An -tx1 -v FILE");
        if (d.style == Style::words)
            fail(
                "a dump of 2-byte words (od's or hexdump's default): which byte came first on tape it does not "
                "show; dump the bytes with od -An -tx1 -v FILE");
        if (d.repeat) {
            if (last_.empty()) fail("'*' with no line before it to repeat");
            repeat_ = true;
            return;
        }
        // The offset says how long the tape is so far: '*' fills up to it, so it is checked first.
        if (d.offset > max_tape_frames)
            fail("the offset " + std::to_string(d.offset) + " says the tape " + std::string(too_long_text));
        if (repeat_) fill_repeats(d.offset, out);
        if (d.offset != next_offset_)
            fail("the offset says " + std::to_string(d.offset) + " where " + std::to_string(next_offset_) +
                 " bytes came before: a line is missing or doubled");
        out.insert(out.end(), d.bytes.begin(), d.bytes.end());
        next_offset_ += d.bytes.size();
        if (!d.bytes.empty()) last_ = std::move(d.bytes);
    }

    // The line before '*' again, as often as the offset of the line after it says.
    void fill_repeats(std::uint64_t offset, std::vector<Frame>& out) {
        repeat_ = false;
        if (offset < next_offset_ || (offset - next_offset_) % last_.size())
            fail("after '*' the offset " + std::to_string(offset) + " is no whole number of repeated lines");
        // Up to 10^8 frames: written by doubling what is filled, not a line at a time (a 1-byte line
        // repeated to the limit took 10^8 inserts).
        std::size_t from = out.size(), total = static_cast<std::size_t>(offset - next_offset_);
        out.resize(from + total);
        if (total > 0) std::copy(last_.begin(), last_.end(), out.begin() + static_cast<std::ptrdiff_t>(from));
        for (std::size_t done = last_.size(); done < total; done *= 2) {
            std::size_t n = std::min(done, total - done);
            std::copy_n(out.begin() + static_cast<std::ptrdiff_t>(from), n,
                        out.begin() + static_cast<std::ptrdiff_t>(from + done));
        }
        next_offset_ = offset;
    }

    std::uint64_t next_offset_ = 0;
    std::vector<std::uint8_t> last_;  // the last line's bytes, for '*'
    bool repeat_ = false;
};

}  // namespace

ImageFormat dump_image_format() {
    return {.id = "dump",
            .description = "a hex dump by xxd, hexdump -C or od -t x1, '*' lines included (read only)",
            .extensions = dump_extensions,
            .binary = false,
            .bytes_are_frames = false,
            .match = dump_match,
            .make_reader = []() -> std::unique_ptr<ImageReader> { return std::make_unique<DumpReader>(); },
            .make_writer = nullptr};
}

}  // namespace tape
