// Is a file a text program (as opposed to a tape image)?
#pragma once

#include <cstdint>
#include <span>

namespace tape {

/// True when bytes are well-formed UTF-8 with no control characters but HT, LF, CR, SO and SI:
/// what a text program is and a raw tape image (blank leader, parity on track 8) is not.
bool is_program_text(std::span<const std::uint8_t> bytes);

}  // namespace tape
