// The little UTF-8 the codec needs: lengths and code points for messages and КОИ-7.
#pragma once

#include <optional>
#include <string_view>

namespace tape::utf8 {

inline bool is_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

/// Bytes of the character starting at offset (1 for ASCII or a stray byte), never past the end.
inline std::size_t length(std::string_view s, std::size_t offset) {
    std::size_t n = 1;
    while (offset + n < s.size() && n < 4 && is_continuation(s[offset + n])) ++n;
    return n;
}

/// How many bytes of s end with a whole character: a lead byte whose sequence runs past the end of
/// s is left out (for text read in pieces, where the rest comes with the next piece).
inline std::size_t whole_prefix(std::string_view s) {
    for (std::size_t back = 1; back <= 3 && back <= s.size(); ++back) {
        auto c = static_cast<unsigned char>(s[s.size() - back]);
        if ((c & 0xC0) == 0x80) continue;  // a continuation byte: look further back
        std::size_t need = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
        return need > back ? s.size() - back : s.size();
    }
    return s.size();
}

inline std::string_view char_at(std::string_view s, std::size_t offset) { return s.substr(offset, length(s, offset)); }

/// Code point of one whole UTF-8 character, or nullopt when malformed.
inline std::optional<char32_t> decode(std::string_view ch) {
    auto b = [&](std::size_t i) { return static_cast<unsigned char>(ch[i]); };
    if (ch.size() == 1 && b(0) < 0x80) return b(0);
    if (ch.size() == 2 && (b(0) & 0xE0) == 0xC0) return char32_t((b(0) & 0x1F) << 6 | (b(1) & 0x3F));
    if (ch.size() == 3 && (b(0) & 0xF0) == 0xE0)
        return char32_t((b(0) & 0x0F) << 12 | (b(1) & 0x3F) << 6 | (b(2) & 0x3F));
    if (ch.size() == 4 && (b(0) & 0xF8) == 0xF0)
        return char32_t((b(0) & 0x07) << 18 | (b(1) & 0x3F) << 12 | (b(2) & 0x3F) << 6 | (b(3) & 0x3F));
    return std::nullopt;
}

}  // namespace tape::utf8
