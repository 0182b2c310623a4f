#include "tape/utf8_text.hpp"

#include <string_view>

#include "utf8.hpp"

namespace tape {

bool is_program_text(std::span<const std::uint8_t> bytes) {
    std::string_view s(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    for (std::size_t i = 0; i < s.size();) {
        auto c = static_cast<unsigned char>(s[i]);
        if (c < 0x80) {
            if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != 0x0E && c != 0x0F) || c == 0x7F) return false;
            ++i;
            continue;
        }
        std::size_t n = utf8::length(s, i);
        if (n == 1 || !utf8::decode(s.substr(i, n))) return false;
        i += n;
    }
    return true;
}

}  // namespace tape
