// Character sets carried by the 7-bit code: plain ISO 646 / ASCII, or КОИ-7 with SO/SI shifts.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tape {

enum class Charset {
    ascii,  ///< ISO 646 positions only; anything else in text is an error
    koi7,   ///< КОИ-7: SO switches to the Cyrillic set Н1, SI back to Н0 (ГОСТ 13052-74)
};

std::string_view charset_name(Charset c);
std::optional<Charset> parse_charset(std::string_view name);

/// Cyrillic letter (UTF-8) at Н1 position p (0x40..0x7E), or "" for none.
std::string_view koi7_cyrillic(unsigned char position);
/// Н1 position of a Cyrillic code point, or nullopt (Ё, ё and capital Ъ have none).
std::optional<unsigned char> koi7_position(char32_t code_point);

}  // namespace tape
