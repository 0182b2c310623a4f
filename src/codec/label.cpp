// Leader labels: letters of holes in the leader (the layout is in tape/label.hpp).
#include "tape/label.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <stdexcept>

#include "codec/label_font.hpp"
#include "codec/utf8.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

using Pixels = unsigned;         // one glyph column: bit r = row r (0 = top) punched
using GlyphKey = std::uint32_t;  // five columns of 6 bits, left column lowest

constexpr Pixels cyrillic_marker = 1;  // the top row: the letter after it is Cyrillic

// Where a glyph's rows, the rail and the parity hole lie in a code's frames.
struct Layout {
    Code code;
    std::array<int, label_glyph_rows> row_track;  // top row first
    int rail;
};
constexpr Layout iso_layout{Code::iso, {6, 5, 4, 3, 2, 1}, 7};
constexpr Layout eia_layout{Code::eia, {8, 7, 6, 4, 3, 2}, 1};

Frame bit(int track) { return static_cast<Frame>(1U << (track - 1)); }

GlyphKey key_of(const label_font::Glyph& g) {
    GlyphKey key = 0;
    for (std::size_t col = 0; col < 5; ++col)
        for (std::size_t r = 0; r < label_glyph_rows; ++r)
            if (g.rows[r][col] == '#') key |= GlyphKey{1} << (col * label_glyph_rows + r);
    return key;
}

Pixels column_of(GlyphKey key, std::size_t col) { return (key >> (col * label_glyph_rows)) & 0x3F; }

std::string utf8_of(char32_t c) {
    std::string s;
    if (c < 0x80) {
        s += static_cast<char>(c);
    } else if (c < 0x800) {
        s += static_cast<char>(0xC0 | (c >> 6));
        s += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        s += static_cast<char>(0xE0 | (c >> 12));
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (c & 0x3F));
    }
    return s;
}

char32_t capital(char32_t c) {
    if (c >= U'a' && c <= U'z') return c - 32;
    if (c >= U'а' && c <= U'я') return c - 32;
    if (c == U'ё') return U'Ё';
    return c;
}

// The font as lookups both ways, built once.
struct Font {
    struct Entry {
        GlyphKey key;
        bool marked;  // drawn after the Cyrillic marker
    };
    std::map<char32_t, Entry> by_char;
    std::map<GlyphKey, char32_t> plain, cyrillic_marked, cyrillic_unmarked;

    Font() {
        for (const auto& g : label_font::plain()) {
            by_char[g.ch] = {key_of(g), false};
            plain[key_of(g)] = g.ch;
        }
        for (const auto& g : label_font::cyrillic()) {
            GlyphKey k = key_of(g);
            bool marked = plain.contains(k);
            by_char[g.ch] = {k, marked};
            (marked ? cyrillic_marked : cyrillic_unmarked)[k] = g.ch;
        }
    }
};

const Font& font() {
    static const Font f;
    return f;
}

// The frame of one label column: the rail, the pixels, the parity the code wants.
Frame frame_of(const Layout& layout, Pixels p, const FrameCode& code) {
    if (layout.code == Code::iso) {
        unsigned c = 0x40;  // the rail, track 7
        for (std::size_t r = 0; r < label_glyph_rows; ++r)
            if (p >> r & 1) c |= bit(layout.row_track[r]);
        return *code.frame_for(static_cast<unsigned char>(c));
    }
    Frame f = bit(layout.rail);
    for (std::size_t r = 0; r < label_glyph_rows; ++r)
        if (p >> r & 1) f |= bit(layout.row_track[r]);
    if (hole_count(f) % 2 == 0) f |= bit(5);
    return f;
}

// True when a reader or controller could act on the frame before the program starts.
bool acted_on(Frame f, const FrameCode& code) {
    if (code.kind(f) == FrameKind::parity_error) return true;
    if (code.code() == Code::eia) return f == 0x80 || code.frame_for('%') == f;
    if (code.kind(f) != FrameKind::character) return false;
    char c = code.character(f);
    return c == '%' || c == '\n' || c == '\r' || c == ':' || (c >= 0x11 && c <= 0x14);
}

std::optional<Pixels> pixels_of(const Layout& layout, Frame f) {
    if (!(f & bit(layout.rail))) return std::nullopt;
    if (layout.code == Code::eia && hole_count(f) % 2 == 0) return std::nullopt;
    Pixels p = 0;
    for (std::size_t r = 0; r < label_glyph_rows; ++r)
        if (f & bit(layout.row_track[r])) p |= 1U << r;
    return p;
}

std::optional<LeaderLabel> read_label(const Layout& layout, std::span<const Frame> frames, std::size_t first) {
    std::size_t end = first;
    while (end < frames.size() && pixels_of(layout, frames[end])) ++end;
    if (end == frames.size() || frames[end] != blank_frame) return std::nullopt;  // blank tape follows a label
    std::size_t n = end - first;
    if (n < label_frame_count(1) || (n - 1) % label_glyph_frames != 0) return std::nullopt;
    const Font& f = font();
    LeaderLabel label{.text = {}, .first = first, .frames = n, .code = layout.code};
    for (std::size_t at = first; at + 1 < end; at += label_glyph_frames) {
        Pixels marker = *pixels_of(layout, frames[at]);
        GlyphKey key = 0;
        for (std::size_t col = 0; col < 5; ++col)
            key |= GlyphKey{*pixels_of(layout, frames[at + 1 + col])} << (col * label_glyph_rows);
        const std::map<GlyphKey, char32_t>* set = nullptr;
        if (marker == cyrillic_marker)
            set = &f.cyrillic_marked;
        else if (marker == 0)
            set = f.plain.contains(key) ? &f.plain : &f.cyrillic_unmarked;
        else
            return std::nullopt;
        auto it = set->find(key);
        if (it == set->end()) return std::nullopt;
        label.text += utf8_of(it->second);
    }
    if (*pixels_of(layout, frames[end - 1]) != 0) return std::nullopt;  // the closing marker is plain
    return label;
}

}  // namespace

std::string label_alphabet() {
    std::string s;
    for (const auto& g : label_font::plain()) s += utf8_of(g.ch);
    for (const auto& g : label_font::cyrillic()) s += utf8_of(g.ch);
    return s;
}

std::vector<std::string> label_glyph(char32_t c) {
    for (auto set : {label_font::plain(), label_font::cyrillic()})
        for (const auto& g : set)
            if (g.ch == c) return {g.rows.begin(), g.rows.end()};
    return {};
}

std::vector<Frame> label_frames(std::string_view text, const FrameCode& code) {
    if (code.code() != Code::iso && code.code() != Code::eia)
        throw Error(Errc::usage, "a label is punched on 8-track tape, in ISO or EIA");
    const Layout& layout = code.code() == Code::iso ? iso_layout : eia_layout;
    const Font& f = font();
    std::vector<Frame> out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < text.size();) {
        std::size_t n = utf8::length(text, i);
        auto c = utf8::decode(text.substr(i, n));
        auto it = c ? f.by_char.find(capital(*c)) : f.by_char.end();
        if (it == f.by_char.end())
            throw Error(Errc::usage, "the label font has no '" + std::string(text.substr(i, n)) +
                                         "': it has Latin and Cyrillic capitals, digits, space, '-', '.' and '/'");
        i += n;
        if (++chars > label_max_chars)
            throw Error(Errc::usage, "a label is at most " + std::to_string(label_max_chars) + " characters");
        out.push_back(frame_of(layout, it->second.marked ? cyrillic_marker : 0, code));
        for (std::size_t col = 0; col < 5; ++col) out.push_back(frame_of(layout, column_of(it->second.key, col), code));
    }
    if (chars == 0) throw Error(Errc::usage, "a label needs at least one character");
    out.push_back(frame_of(layout, 0, code));
    // The font is drawn so that this never happens; a glyph added carelessly must not reach a tape.
    for (Frame fr : out)
        if (acted_on(fr, code)) throw std::logic_error("label font: a glyph column is a character readers act on");
    return out;
}

std::span<const Frame> without_label(std::span<const Frame> frames, std::uint64_t at,
                                     const std::optional<LeaderLabel>& label, std::vector<Frame>& scratch) {
    if (!label || at >= label->first + label->frames || at + frames.size() <= label->first) return frames;
    scratch.assign(frames.begin(), frames.end());
    std::uint64_t from = label->first > at ? label->first - at : 0;
    std::uint64_t to = std::min<std::uint64_t>(label->first + label->frames - at, frames.size());
    std::fill(scratch.begin() + static_cast<std::ptrdiff_t>(from), scratch.begin() + static_cast<std::ptrdiff_t>(to),
              blank_frame);
    return scratch;
}

std::optional<LeaderLabel> find_label(std::span<const Frame> frames) {
    std::size_t first = 0;
    while (first < frames.size() && frames[first] == blank_frame) ++first;
    if (first == frames.size()) return std::nullopt;
    for (const Layout* layout : {&iso_layout, &eia_layout})
        if (auto label = read_label(*layout, frames, first)) return label;
    return find_title(frames);
}

}  // namespace tape
