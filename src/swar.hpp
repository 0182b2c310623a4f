// Eight frames in one 64-bit word: byte-wise tests without a loop (SIMD within a register).
#pragma once

#include <cstdint>

namespace tape::swar {

constexpr std::uint64_t repeat(std::uint8_t b) { return 0x0101010101010101ULL * b; }

/// Bit 0 of each byte is that byte's parity (1 = odd number of set bits); other bits clear.
/// Shifts pull bits in from the next byte only above bit 3, 1 and 0 in turn, so bit 0 stays exact.
constexpr std::uint64_t odd_parity_bytes(std::uint64_t x) {
    x ^= x >> 4;
    x ^= x >> 2;
    x ^= x >> 1;
    return x & repeat(0x01);
}

/// True when any byte of x is zero (exact, no false positives).
constexpr bool has_zero_byte(std::uint64_t x) { return ((x - repeat(0x01)) & ~x & repeat(0x80)) != 0; }

/// True when any byte of x has bit 7 set.
constexpr bool has_high_byte(std::uint64_t x) { return (x & repeat(0x80)) != 0; }

}  // namespace tape::swar
