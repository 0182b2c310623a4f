// What the text of a program says about the control it was written for: clues that only one dialect's
// programs hold (an O number, an o-word, a ':' main block), and clues of controls the tool has no
// dialect for (Okuma's "VC1=", Sinumerik's "%_N_…_MPF", Philips' "N1=8001"). Counted line by line
// outside comments; guess_dialect weighs them with how each dialect reads the text.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "tape/dialect.hpp"

namespace tape::detection {

/// Whom a clue points to.
enum class Side { gost, fanuc, linuxcnc, foreign };

/// The kinds of clue, each with its side, weight and words (the table in dialect_evidence.cpp).
enum class Clue {
    o_number,           // fanuc: "O1234" or ":1234" starting a program, "%O1200"
    macro,              // fanuc: #1, [ ] outside o-words, IF GOTO WHILE, G65, M99
    semicolon_end,      // fanuc: ';' ending a block
    subprogram_call,    // fanuc: M98, Haas's M97
    corner_word,        // fanuc: ",C1." ",R2."
    names_fanuc,        // fanuc: a line naming Fanuc or Haas
    lowercase,          // linuxcnc: a line with lowercase words
    o_word,             // linuxcnc: o<name>, o100 sub/if/while/call
    named_parameter,    // linuxcnc: #<name>
    semicolon_comment,  // linuxcnc: ';' followed by a comment
    linuxcnc_code,      // linuxcnc: G64 P, G90.1, G91.1, G33.1, G38.n, G43.2, G59.1-3, G5.2
    polar_word,         // linuxcnc: ^60, @1.5
    comment_command,    // linuxcnc: (debug,…) (msg,…) (print,…) (abort,…)
    console_command,    // linuxcnc: a GRBL console line ($I, $$, ?) in a file streamed to GRBL
    names_linuxcnc,     // linuxcnc: a line naming LinuxCNC
    main_block,         // gost: ':' in place of N with words after it
    percent_number,     // gost: '%' with a program number
    signed_dimension,   // gost: X+12.5, Z + 0000000: the explicit '+' of the standard's examples
    assignment,         // foreign: NAME=, R1=, N1= (a letter address given a value)
    header,             // foreign: %PM, %MPF, %_N_…_MPF, $NAME.MIN%
    keyword_line,       // foreign: DEF, CALL, RTS, GOTOF, GOTOB, PROC, MSG(, Okuma's NLABEL
    parameter_word,     // foreign: H&K's P123.22.5, P125.-90 (parameter 123 set to 22.5)
};
inline constexpr std::size_t clue_count = 22;

struct ClueInfo {
    Side side;
    std::uint64_t weight;
    std::string_view what;  // "O program number(s)"
};
const ClueInfo& clue_info(Clue c);

/// The clues of a whole text, counted once a line each (macro clues once each).
class Evidence {
public:
    void scan(std::string_view text);

    /// The weighted clues for d (gost, fanuc, linuxcnc).
    std::uint64_t support(Dialect d) const;
    /// Lines showing the syntax of a control no dialect here reads.
    std::uint64_t foreign() const;
    /// "3 O program number(s) (line 2), 12 macro statement(s) (line 5)": the clues of one side found.
    std::string describe(Side side) const;
    /// The text starts with '%' (after blank lines, or after label text): a tape's program start.
    bool starts_with_percent() const { return starts_with_percent_; }

private:
    void line(std::string_view line, std::uint64_t number);
    void words(std::string_view line, std::size_t i, std::uint64_t number);
    void add(Clue c, std::uint64_t number, std::uint64_t n = 1);

    void leader_ends(bool percent);

    std::array<std::uint64_t, clue_count> count_{};
    std::array<std::uint64_t, clue_count> first_line_{};
    bool starts_with_percent_ = false;
    // Before the first '%' the clues are held: that text is label (its clues say nothing of the
    // program) unless it ends a program, which the '%' then closes.
    std::array<std::uint64_t, clue_count> leader_count_{};
    std::array<std::uint64_t, clue_count> leader_first_line_{};
    bool in_leader_ = true, leader_ends_program_ = false;
};

}  // namespace tape::detection
