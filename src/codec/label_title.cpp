// Titles of letters of holes in another font than this tool's: the Elliott 900 archive's tapes carry them
// in the leader (the name of the tape, drawn a column a frame, seven holes high). They are found by their
// shape, not read: glyphs a few frames wide with blank frames between, blank leader after.
#include "tape/label.hpp"

namespace tape {
namespace {

constexpr std::size_t min_glyphs = 3, widest_glyph = 8, widest_gap = 15, leader_after = 16;

// Columns of a picture: they fit no parity rule, and some are control characters no text holds.
bool pictures(std::span<const Frame> frames, const std::vector<std::pair<std::size_t, std::size_t>>& glyphs) {
    std::size_t columns = 0, even = 0, controls = 0;
    for (auto [at, width] : glyphs)
        for (std::size_t i = at; i < at + width; ++i) {
            Frame f = frames[i];
            ++columns;
            even += hole_count(f) % 2 == 0;
            int c = f & 0x7F;
            controls += (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F;
        }
    return even * 5 >= columns && (columns - even) * 5 >= columns && controls > 0;
}

}  // namespace

std::optional<LeaderLabel> find_title(std::span<const Frame> frames) {
    std::size_t at = 0;
    while (at < frames.size() && frames[at] == blank_frame) ++at;
    std::vector<std::pair<std::size_t, std::size_t>> glyphs;  // first frame, width
    while (at < frames.size()) {
        std::size_t width = 0;
        // Counted no further than a glyph can be wide: a text tape's first "glyph" is the whole tape.
        while (at + width < frames.size() && frames[at + width] != blank_frame && width <= widest_glyph) ++width;
        if (width > widest_glyph) return std::nullopt;
        glyphs.emplace_back(at, width);
        std::size_t gap = 0;
        while (at + width + gap < frames.size() && frames[at + width + gap] == blank_frame) ++gap;
        if (gap >= leader_after) break;
        if (gap > widest_gap || at + width + gap == frames.size()) return std::nullopt;
        at += width + gap;
    }
    if (glyphs.size() < min_glyphs || !pictures(frames, glyphs)) return std::nullopt;
    std::uint64_t first = glyphs.front().first;
    std::uint64_t end = glyphs.back().first + glyphs.back().second;
    return LeaderLabel{.text = {}, .first = first, .frames = end - first, .code = Code::iso, .font = LabelFont::title};
}

}  // namespace tape
