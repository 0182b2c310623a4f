// Controller format specifications in the notation of ГОСТ 20999-83 §9, e.g.
//     % : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*
// and the checks and rewriting of words that follow from them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/program.hpp"

namespace tape {

/// How one address is written for a controller.
struct WordFormat {
    char address = 0;
    std::string text;            ///< as in the spec: "X+053"
    bool sign = false;           ///< '+': the value may be positive or negative, sign written
    bool dimension = false;      ///< two or three digits: digits before and after the implied point
    int before = 0;              ///< dimension: digits before the point; otherwise: the number of digits
    int after = 0;               ///< dimension: digits after the point
    bool omit_leading = false;   ///< leading zeros may be left out (first spec digit 0)
    bool omit_trailing = false;  ///< trailing zeros may be left out (last spec digit 0, dimensions only)
};

struct FormatSpec {
    std::string text;
    bool program_start = false;   ///< '%'
    bool main_block = false;      ///< ':'
    bool block_skip = false;      ///< '/'
    bool explicit_point = false;  ///< 'DS': the controller accepts an explicit decimal point
    bool tab = false;             ///< '.': HT is used
    std::vector<WordFormat> words;

    /// The format of an address (':' uses N's), or nullptr.
    const WordFormat* find(char address) const;
};

/// Parses the notation. Throws Error(Errc::usage) saying which part is not understood, or
/// "empty format specification" when the text holds nothing but blanks.
FormatSpec parse_format_spec(std::string_view text);

/// An exact decimal value: sign, whole digits (no leading zeros), fraction digits (no trailing zeros).
struct DecimalValue {
    bool negative = false;
    std::string whole;
    std::string fraction;
};

/// The value of a word. An explicit point decides; without one a dimension word is read with the
/// implied point of `from` when given, else as a whole number (§3.1.4).
DecimalValue word_value(const Word& w, const WordFormat* from);

/// What is wrong with a word for this format (empty when nothing): each entry a rule id and message.
/// program_has_points: the program writes explicit points, so words without one are whole numbers.
std::vector<std::pair<std::string_view, std::string>> check_word(const Word& w, const FormatSpec& spec,
                                                                 bool program_has_points);

/// The word rewritten for the format: all digits the format has (leading zeros left out where the
/// format allows and strip_zeros), the sign when the format has one, an explicit point only with DS
/// (".5" when the format has no digits before the point). What it returns passes check_word for spec
/// and has the same value. Throws Error(Errc::bad_text) when the value does not fit, or for a main
/// block number (':') when the format has no ':'.
std::string format_word(const Word& w, const FormatSpec& spec, const FormatSpec* from, bool strip_zeros);

}  // namespace tape
