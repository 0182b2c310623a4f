#include "core/crc16.hpp"

namespace tapefw {

std::uint16_t crc16(const std::uint8_t* data, std::size_t n, std::uint16_t crc) {
    for (std::size_t i = 0; i < n; ++i) {
        crc = static_cast<std::uint16_t>(crc ^ (data[i] << 8));
        for (int bit = 0; bit < 8; ++bit)
            crc = static_cast<std::uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
    }
    return crc;
}

}  // namespace tapefw
