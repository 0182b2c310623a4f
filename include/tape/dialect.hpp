// Program dialects: what a controller family accepts beyond the literal ГОСТ 20999-83 / ISO 6983 reading.
// What each accepts is data (DialectRules), read by the loader and lint, and listed in tape(1).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tape {

enum class Dialect {
    gost,       ///< ГОСТ 20999-83 / ISO 6983 as written: '%' starts every program, capitals only
    fanuc,      ///< Fanuc 0i/16i/18i/21i/30i: O numbers, closing '%', Custom Macro B, ';' as end of block
    linuxcnc,   ///< LinuxCNC RS274NGC: no '%' needed, any case, ';' comments, o-words, named parameters
    none,       ///< no known dialect fits (Okuma, Sinumerik, ...): only what holds for every control is checked
    automatic,  ///< decided from the text before loading (guess_dialect)
};

std::string_view dialect_name(Dialect d);
std::optional<Dialect> parse_dialect(std::string_view name);

/// What a dialect accepts: one row of the table in dialect.cpp.
struct DialectRules {
    Dialect dialect;
    bool needs_percent;                 ///< text before the first '%' is label, not program (§1.8)
    bool lowercase;                     ///< lowercase letters are addresses as their capitals
    bool semicolon_ends_block;          ///< ';' is the end of block as manuals print it
    bool semicolon_comment;             ///< ';' starts a comment to the end of the line
    bool macro_b;                       ///< Custom Macro B: #n variables, [ ] expressions, IF/GOTO/WHILE/DO/END
    bool o_words;                       ///< o-word subroutines and control flow, #<named> parameters
    bool o_program_number;              ///< 'O' (or ':') and digits at a block's start is the program number
    bool main_blocks;                   ///< ':' in place of N marks a main block (§2.6)
    bool skip_levels;                   ///< "/1".."/9" optional block skip levels
    bool closing_percent;               ///< a '%' after the end of program closes the record
    bool ordered_words;                 ///< the recommended word order (§2.2) is checked
    bool increasing_numbers;            ///< block numbers are checked to increase
    bool corner_words;                  ///< \",C1.\" chamfer and \",R2.\" corner rounding after a move
    std::span<const int> program_ends;  ///< the M codes that end a program, e.g. 2 30 99
    std::string_view reference;         ///< the document the dialect follows
};

const DialectRules& dialect_rules(Dialect d);

/// The dialect auto chooses and why, in words for -v.
struct DialectChoice {
    Dialect dialect = Dialect::gost;
    std::string reason;
    /// The runner-up, when it came within the margin: the text is read as dialect, and only what the
    /// two readings both find is reported (lint keeps the rules they share).
    std::optional<Dialect> close{};
};

/// How much of a text's start the dialect is chosen from.
inline constexpr std::size_t dialect_sample_bytes = 64 << 10;
/// The first dialect_sample_bytes of text in whole lines: the same sample however the text came in pieces.
std::string_view dialect_sample(std::string_view text);

/// Chooses a dialect from the start of a text program (dialect_sample: whatever follows is not read) by weighing,
/// for each dialect, the clues only its programs hold (O numbers and Custom Macro B for Fanuc;
/// o-words, named parameters, lowercase and ';' comments for LinuxCNC; ':' main blocks and numbered
/// '%' for ГОСТ) against the lines its reading cannot make sense of that another's can. Answers
/// Dialect::none when the text holds the syntax of a control none of them reads (NAME= assignments,
/// %MPF or $NAME% headers, DEF or CALL statements) or most of it reads in none; sets close when the
/// runner-up came within the margin. A text with no clue is read as ГОСТ when it starts with '%',
/// else as LinuxCNC (no ГОСТ tape program can have no '%' before it). The reason says what decided.
DialectChoice guess_dialect(std::string_view text);

}  // namespace tape
