// Consistent Overhead Byte Stuffing (Cheshire and Baker, 1999): a packet of n bytes becomes at most
// n + n/254 + 1 bytes with no zero in them, so a zero byte can end every packet on a byte stream. A
// receiver that joins in the middle, or meets garbage, is back in step at the next zero.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tapefw {

/// Bytes COBS needs for n bytes of input (without the terminating zero).
constexpr std::size_t cobs_max_encoded(std::size_t n) { return n + n / 254 + 1; }

/// Encodes n bytes into out (room for cobs_max_encoded(n)); no terminating zero. Returns the bytes written.
std::size_t cobs_encode(const std::uint8_t* in, std::size_t n, std::uint8_t* out);

/// Decodes n encoded bytes (without the terminating zero) into out (room for n bytes; out may equal
/// in). Returns the decoded length, or -1 when the input is no COBS encoding (a zero inside, or a
/// code byte pointing past the end).
int cobs_decode(const std::uint8_t* in, std::size_t n, std::uint8_t* out);

}  // namespace tapefw
