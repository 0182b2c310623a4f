// CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection, no final XOR
// (check value 0x29B1 for the ASCII string "123456789"). It guards every packet of the adapter protocol.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tapefw {

/// The CRC of n bytes, continuing from crc (start with crc16_init). Bitwise: no table in flash.
std::uint16_t crc16(const std::uint8_t* data, std::size_t n, std::uint16_t crc = 0xFFFF);

inline constexpr std::uint16_t crc16_init = 0xFFFF;

}  // namespace tapefw
