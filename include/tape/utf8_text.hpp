// Is a file a text program (as opposed to a tape image)? And text made safe to show in a message.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "tape/error.hpp"

namespace tape {

/// True when bytes are well-formed UTF-8 with no control characters but HT, LF, CR, SO and SI:
/// what a text program is and a raw tape image (blank leader, parity on track 8) is not.
bool is_program_text(std::span<const std::uint8_t> bytes);

/// The first byte that keeps bytes from being a text program: where it is (line, column in
/// characters, byte offset) and what it is ("a NUL byte", "byte 0xD0, which is not UTF-8").
struct TextFault {
    Position where;
    std::uint64_t offset = 0;
    std::string what;
};
std::optional<TextFault> find_text_fault(std::span<const std::uint8_t> bytes);

/// True when bytes read as a text file in which a few bytes are wrong (a NUL, a stray byte of another
/// encoding), rather than as a tape image: almost all printable, with lines, no blank leader.
bool looks_like_damaged_text(std::span<const std::uint8_t> bytes);

/// s with what a terminal would hide or act on spelled out: control bytes as \x07, bytes that are
/// not UTF-8 as \xD0, invisible characters as U+FEFF. Other UTF-8 (Cyrillic) is kept.
std::string visible(std::string_view s);

}  // namespace tape
