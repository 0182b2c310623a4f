// Sizes no paper tape reaches. What must hold a whole tape at once (the reader emulator, restore and
// diff, tape-damage, a table or an image read whole) refuses an input beyond them as no tape, with a
// message, before asking for the memory.
#pragma once

#include <cstdint>
#include <string_view>

namespace tape {

/// 10^8 frames: 254 km of tape at 2.54 mm a frame (a reel holds about 300 m).
inline constexpr std::uint64_t max_tape_frames = 100'000'000;

/// What is said of an input beyond max_tape_frames.
inline constexpr std::string_view too_long_text =
    "holds more than 100000000 frames (254 km of tape): no paper tape is so long";

}  // namespace tape
