// A frame is one row across 8-track paper tape: bit 0 = track 1 ... bit 7 = track 8.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <string>

namespace tape {

using Frame = std::uint8_t;

inline constexpr Frame blank_frame = 0x00;  ///< feed hole only: leader, trailer, tape feed (ПУС)

namespace detail {
// A table: without -mpopcnt (x86-64 baseline), std::popcount is a libgcc call, and restore asks this of
// nearly every frame it votes on.
inline constexpr auto hole_counts = [] {
    std::array<std::uint8_t, 256> t{};
    for (unsigned f = 0; f < t.size(); ++f) t[f] = static_cast<std::uint8_t>(std::popcount(f));
    return t;
}();
}  // namespace detail

/// Number of holes punched in the frame (feed hole not counted).
constexpr int hole_count(Frame f) { return detail::hole_counts[f]; }

/// True when track (1..8) is punched.
constexpr bool has_track(Frame f, int track) { return (f >> (track - 1)) & 1U; }

/// The frame drawn as on tape, tracks 8..4, the feed hole, tracks 3..1: "|o o  .o o|" for ISO '%'.
std::string holes_picture(Frame f);

/// The frames from the first to the last that is not blank: the tape without its leader and trailer
/// (empty for blank tape).
std::span<const Frame> punched_part(std::span<const Frame> frames);

/// The frame as a byte in hex: "0x25" for ISO '%' without parity.
std::string frame_hex(Frame f);

}  // namespace tape
