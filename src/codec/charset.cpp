// КОИ-7 Н1: the Cyrillic half of the 7-bit code, positions 4/0 to 7/14 (spec section 4a).
#include "tape/charset.hpp"

#include <array>

#include "utf8.hpp"

namespace tape {
namespace {

// Positions 4/0..5/15 lower case, 6/0..7/14 upper case; 7/15 stays DEL.
constexpr std::array<std::string_view, 63> n1 = {
    "ю", "а", "б", "ц", "д", "е", "ф", "г", "х", "и", "й", "к", "л", "м", "н", "о", "п", "я", "р", "с", "т",
    "у", "ж", "в", "ь", "ы", "з", "ш", "э", "щ", "ч", "ъ", "Ю", "А", "Б", "Ц", "Д", "Е", "Ф", "Г", "Х", "И",
    "Й", "К", "Л", "М", "Н", "О", "П", "Я", "Р", "С", "Т", "У", "Ж", "В", "Ь", "Ы", "З", "Ш", "Э", "Щ", "Ч"};

}  // namespace

std::string_view charset_name(Charset c) { return c == Charset::ascii ? "ascii" : "koi7"; }

std::optional<Charset> parse_charset(std::string_view name) {
    if (name == "ascii") return Charset::ascii;
    if (name == "koi7") return Charset::koi7;
    return std::nullopt;
}

std::string_view koi7_cyrillic(unsigned char position) {
    if (position < 0x40 || position > 0x7E) return {};
    return n1[position - 0x40];
}

std::optional<unsigned char> koi7_position(char32_t code_point) {
    for (std::size_t i = 0; i < n1.size(); ++i)
        if (utf8::decode(n1[i]) == code_point) return static_cast<unsigned char>(0x40 + i);
    return std::nullopt;
}

}  // namespace tape
