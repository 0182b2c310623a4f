// Is a file a text program (as opposed to a tape image)? And text made safe to show in a message.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/error.hpp"

namespace tape {

/// The UTF-8 byte-order mark (U+FEFF) some editors put at the start of a text file.
inline constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";
/// The note for a byte-order mark skipped at the start of a text program (line 1).
Diagnostic byte_order_mark_note();

/// The DOS end-of-file mark, Ctrl-Z (SUB): MS-DOS and CP/M editors put it, or a run of it, after the
/// last line. At the end of a text it ends the text; anywhere else it is a control character.
inline constexpr std::uint8_t dos_end_of_file = 0x1A;
/// Where the run of DOS end-of-file marks that ends bytes starts; bytes.size() when they end otherwise.
std::size_t dos_end_of_file_at(std::span<const std::uint8_t> bytes);
/// The note for a text that ends with DOS end-of-file marks, where the first of them is.
Diagnostic dos_end_of_file_note(const Position& where);

/// True when bytes are well-formed UTF-8 with no control characters but HT, LF, CR, SO and SI (and the
/// DOS end-of-file marks that may end it): what a text program is and a raw tape image (blank leader,
/// parity on track 8) is not.
bool is_program_text(std::span<const std::uint8_t> bytes);

/// The first byte that keeps bytes from being a text program: where it is (line, column in
/// characters, byte offset) and what it is ("a NUL byte", "byte 0xD0, which is not UTF-8"). DOS
/// end-of-file marks that end bytes are no fault.
struct TextFault {
    Position where;
    std::uint64_t offset = 0;
    std::string what;
};
std::optional<TextFault> find_text_fault(std::span<const std::uint8_t> bytes);

/// find_text_fault over a text read in pieces, with positions counted from the start of the text.
class TextChecker {
public:
    /// The first fault in this piece; a character cut by the piece's end is checked with the next, and
    /// DOS end-of-file marks at its end are a fault only once text follows them.
    std::optional<TextFault> check(std::span<const std::uint8_t> piece);
    /// The text has ended: a character left unfinished is a fault.
    std::optional<TextFault> finish();
    /// Where the DOS end-of-file marks that end the text so far start (a byte offset and its line);
    /// nullopt when it does not end with one.
    std::optional<TextFault> end_of_file_mark() const { return marks_ ? std::optional(mark_) : std::nullopt; }

private:
    std::optional<TextFault> check_whole(std::span<const std::uint8_t> bytes);

    std::vector<std::uint8_t> carry_;  // the start of a character cut by a piece's end
    std::uint64_t lines_before_ = 0, columns_before_ = 0, bytes_before_ = 0;
    std::uint64_t marks_ = 0;  // DOS end-of-file marks not yet known to end the text
    TextFault mark_;           // where the first of them is
};

/// True when bytes read as a text file in which a few bytes are wrong (a NUL, a stray byte of another
/// encoding), rather than as a tape image: almost all printable, with lines, no blank leader.
bool looks_like_damaged_text(std::span<const std::uint8_t> bytes);

/// s with what a terminal would hide or act on spelled out: control bytes as \x07, bytes that are
/// not UTF-8 as \xD0, invisible characters as U+FEFF. Other UTF-8 (Cyrillic) is kept.
std::string visible(std::string_view s);

}  // namespace tape
