#include "core/cobs.hpp"

namespace tapefw {

std::size_t cobs_encode(const std::uint8_t* in, std::size_t n, std::uint8_t* out) {
    std::size_t code_at = 0, o = 1;
    std::uint8_t code = 1;
    for (std::size_t i = 0; i < n; ++i) {
        if (in[i] != 0) {
            out[o++] = in[i];
            ++code;
        }
        if (in[i] == 0 || code == 0xFF) {
            out[code_at] = code;
            code = 1;
            code_at = o++;
        }
    }
    out[code_at] = code;
    return o;
}

int cobs_decode(const std::uint8_t* in, std::size_t n, std::uint8_t* out) {
    std::size_t i = 0, o = 0;
    while (i < n) {
        std::uint8_t code = in[i++];
        if (code == 0 || i + code - 1 > n) return -1;
        for (std::uint8_t k = 1; k < code; ++k) {
            if (in[i] == 0) return -1;
            out[o++] = in[i++];
        }
        // A block of 254 data bytes has no zero after it; neither has the last block.
        if (code != 0xFF && i < n) out[o++] = 0;
    }
    return static_cast<int>(o);
}

}  // namespace tapefw
