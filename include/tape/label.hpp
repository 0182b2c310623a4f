// Leader labels: text punched as dot-matrix letters made of holes into the leader, readable by eye along
// the tape, as tape operators did ("DETAIL 17" before the program).
//
// Each letter is a glyph 5 frames wide and 6 tracks high; a marker frame stands before each letter and
// after the last. Every frame of a label also has a rail hole, a track punched along the whole label:
//   ISO  glyph rows (top to bottom) on tracks 6..1, rail on track 7, track 8 the parity of the code.
//        Every label frame has track 7, so its character is 0x40-0x7F: never %, LF, CR, ':', DC1-DC4
//        (all below 0x40), never a character a reader or controller acts on before the program.
//   EIA  glyph rows on tracks 8, 7, 6, 4, 3, 2, rail on track 1, track 5 odd parity. Track 1 is never
//        punched alone with track 8, so no frame is End of Block; the font has no column that would make
//        the rewind stop (tracks 1, 2, 4: glyph rows 3 and 5 alone), which the tests check.
// A marker is the rail alone, or with the top row punched before a Cyrillic letter drawn like a Latin
// letter or digit (А, В, Е, З, К, М, Н, О, Р, С, Т, Х): so that they read back as what was punched.
// Decoding skips a recognised label (tape/input.hpp): the program and its decoded text are unchanged.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/code.hpp"
#include "tape/frame.hpp"

namespace tape {

inline constexpr std::size_t label_max_chars = 80;     ///< characters of one label
inline constexpr std::size_t label_glyph_frames = 6;   ///< a marker frame and 5 glyph frames a character
inline constexpr std::size_t label_glyph_rows = 6;     ///< tracks a glyph is drawn on
inline constexpr std::size_t label_blank_around = 10;  ///< blank frames kept before and after a label in a leader

/// Frames of a label of `chars` characters: 6 a character and the closing marker.
constexpr std::size_t label_frame_count(std::size_t chars) { return chars * label_glyph_frames + 1; }

/// The characters the font has, in the order tests go over them: Latin capitals, digits, Cyrillic
/// capitals (Ё included), space, '-', '.', '/'. UTF-8.
std::string label_alphabet();

/// The label's frames (no blank tape around them) in code (ISO with its parity, or EIA). Lower-case
/// letters are punched as capitals. Throws Error(Errc::usage) for an empty text, more than
/// label_max_chars characters, a character the font does not have (named in the message), or a
/// 5-track code.
std::vector<Frame> label_frames(std::string_view text, const FrameCode& code);

/// The glyph of a character as rows of '#' (hole) and '.', top row first, for documentation and tests;
/// empty when the font has no such character.
std::vector<std::string> label_glyph(char32_t c);

/// Whose letters a label is punched in.
enum class LabelFont {
    letters,  ///< this tool's font (the layout above): read back as text
    title,    ///< another's: a title of letters of holes (as on the Elliott 900 archive's tapes), found, not read
};

/// A label found in a tape's leader.
struct LeaderLabel {
    std::string text;          ///< UTF-8, capitals, as punched (spaces kept, none added); empty for a title
    std::uint64_t first = 0;   ///< 0-based index of its first frame
    std::uint64_t frames = 0;  ///< how many frames it takes
    Code code = Code::iso;     ///< the layout it was punched in
    LabelFont font = LabelFont::letters;
};

/// The label in the leader of a tape whose first frames are `frames`: after the blank frames at the
/// start, a whole label (ISO or EIA layout) followed by a blank frame; else a title in another font (see
/// find_title). nullopt when the tape does not start so. Never throws.
std::optional<LeaderLabel> find_label(std::span<const Frame> frames);

/// A title in another font at the start of the tape: after the blank leader, at least three glyphs of
/// one to eight frames with one to fifteen blank frames between them, then blank tape again (sixteen
/// frames or more). Its frames are pictures, not characters: they hold both even and odd numbers of holes
/// and columns that are control characters no text has. nullopt when there is none.
std::optional<LeaderLabel> find_title(std::span<const Frame> frames);

/// frames (a tape's frames from 0-based index `at` on) with those of label made blank: a copy in
/// scratch when any of them is in the label, else frames itself. What decoding reads instead of a label.
std::span<const Frame> without_label(std::span<const Frame> frames, std::uint64_t at,
                                     const std::optional<LeaderLabel>& label, std::vector<Frame>& scratch);

/// How far into a tape find_label may look: the leader up to its first punched frame plus this many.
inline constexpr std::size_t label_search_frames = label_frame_count(label_max_chars) + 1;

}  // namespace tape
