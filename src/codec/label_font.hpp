// The leader label font: 5 frames by 6 tracks a glyph (tape/label.hpp says how it lies on tape).
#pragma once

#include <array>
#include <span>

namespace tape::label_font {

/// One glyph: rows top first, '#' a hole, '.' none, 5 columns each.
struct Glyph {
    char32_t ch;
    std::array<const char*, 6> rows;
};

/// Latin capitals, digits, then space and punctuation: drawn with a plain marker.
std::span<const Glyph> plain();
/// Cyrillic capitals: those drawn like a plain glyph get the Cyrillic marker.
std::span<const Glyph> cyrillic();

}  // namespace tape::label_font
