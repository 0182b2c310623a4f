// The rule table: the one place a rule's id, severity, dialects and reference are written.
#include "tape/rules.hpp"

#include <array>

namespace tape {
namespace {

constexpr auto E = Severity::error, W = Severity::warning, N = Severity::note;
constexpr std::string_view all = "gost fanuc linuxcnc";
// What holds for every control, also when no known dialect fits (none): characters, parity, blocks, comments.
constexpr std::string_view every = "gost fanuc linuxcnc none";

constexpr std::array table = std::to_array<Rule>({
    // The loader: how characters become programs, blocks and words.
    {"unexpected-character", E, every, "ГОСТ 20999-83 tables 1-3; ISO 646 (every control reads 7-bit code)",
     "a character, or a run of characters, that no program of the dialect may hold outside comments (when no "
     "dialect fits: a control character or one that is not 7-bit, which no control reads)",
     "a controller stops on it with a tape alarm; on a read tape it is often a misread frame"},
    {"unknown-word", E, all, "ГОСТ 20999-83 §3.1, table 1; the dialect's manual",
     "a word or statement this dialect does not know (lowercase letters in ГОСТ or Fanuc programs, a macro "
     "statement in a ГОСТ program); it is kept in the listing, flagged, and not checked further",
     "the controller rejects it; with --dialect the right reading may be chosen"},
    {"no-digits", E, all, "ГОСТ 20999-83 §3.1.1", "an address letter with no value after it",
     "an address alone is a tape alarm on every controller"},
    {"two-points", E, all, "ГОСТ 20999-83 §3.1.4", "a number with more than one decimal point",
     "the controller cannot read the value"},
    {"skip-position", E, all, "ГОСТ 20999-83 §2.7", "'/' (block skip) anywhere but at the start of a block",
     "a '/' in the middle of a block is no block skip and stops the controller"},
    {"main-position", E, "gost", "ГОСТ 20999-83 §2.6", "':' (main block) anywhere but in place of N",
     "a reader searching for main blocks stops at every ':'"},
    {"percent-in-block", E, all, "ГОСТ 20999-83 §1.4, table 2", "'%' inside a block",
     "'%' is the program start and the rewind stop: a reader rewinding stops there"},
    {"comment-forbidden-char", E, "gost", "ГОСТ 20999-83 §1.5", "'%' or ':' inside a comment",
     "readers searching for '%' or ':' stop inside the comment"},
    {"unclosed-comment", E, every, "ГОСТ 20999-83 §1.5", "'(' without ')' before the end of block",
     "the controller reads the next blocks as comment, or stops"},
    {"program-start", E, all, "ГОСТ 20999-83 §1.4, §1.6, §1.8",
     "what stands between '%' and the end of that block: only a program number may; '%%' only before "
     "the first program; a '%' that starts no program",
     "the controller does not find the program it is asked for"},
    {"program-end", W, all, "ГОСТ 20999-83 §1.9; Fanuc: M02, M30, M99; LinuxCNC: M2, M30 or the closing '%'",
     "a program that is not ended before the next program or the end of the tape",
     "without its end the controller runs on into what follows, or waits at the end of the tape"},
    {"incomplete-block", W, every, "ГОСТ 20999-83 §2.1",
     "a tape that ends in the middle of a block, without its end of block",
     "a controller does not execute a block until its end of block: the tape was cut or read short"},
    {"no-program", E, "gost", "ГОСТ 20999-83 §1.4, §1.8",
     "a tape with no '%': everything on it is label, which a controller skips",
     "nothing on the tape runs; with --dialect linuxcnc or fanuc no '%' is needed"},
    {"macro-syntax", E, "fanuc linuxcnc",
     "Fanuc Custom Macro B (operator's manual, 'Custom macro'); LinuxCNC 'O codes' and 'Expressions'",
     "a malformed macro expression or statement: unbalanced [ ], an unknown function or operator, IF "
     "without GOTO or THEN, WHILE without DO, GOTO without a target, an assignment without a value",
     "the controller stops with a macro alarm when it reaches the block"},
    {"control-flow", E, "fanuc linuxcnc",
     "Fanuc Custom Macro B: WHILE/DO/END; LinuxCNC 'O codes': sub/endsub, if/endif, while/endwhile",
     "loops and subroutines that are not closed, or closed without being opened",
     "the controller stops with an alarm, or loops where the programmer did not mean to"},
    {"goto-target", E, "fanuc", "Fanuc Custom Macro B: GOTO n branches to the block with sequence number n",
     "a GOTO to a block number that no block of the same program has",
     "the controller stops with 'sequence number not found' in the middle of machining"},
    {"block-target", E, "fanuc",
     "Fanuc lathe: multiple repetitive cycles G70-G73 (P first, Q last block of the profile); Haas: M97 local "
     "subprogram call",
     "the P or Q of a lathe cycle G70-G73, or the P of Haas's M97, naming a block number no block of the program "
     "has (M98 P names a program and M99 P a block of the caller: they are not checked)",
     "the control stops with 'sequence number not found' when it reaches the cycle or the call"},
    {"duplicate-target", W, "fanuc", "Fanuc: sequence number search; G70-G73 P/Q, GOTO, Haas M97 P",
     "a block number that stands on more than one block of the program while a cycle, GOTO or M97 names it",
     "the control goes to the one it finds first, which may not be the one the programmer meant"},
    {"repeated-dimension", E, all, "ГОСТ 20999-83 §2.4",
     "a dimension or interpolation word twice in one block (Fanuc and LinuxCNC: the axis words and I J K; "
     "their P Q R are parameters)",
     "one of the two values is lost; usually a misread or mistyped address"},
    {"g-group", E, all, "ГОСТ 20999-83 §2.5, table 4",
     "two G codes of one group in a block (G00/G01/G02/G03, G17/G18/G19, G80-G89, G54-G59, G90/G91, "
     "G93-G95, G96/G97)",
     "only one can be in effect: LinuxCNC refuses the block, Fanuc silently takes the last"},
    {"unknown-code", E, all,
     "ГОСТ 20999-83 tables 4 and 7 (G00-G99, M00-M99); the Fanuc and LinuxCNC G- and M-code lists",
     "a G or M code that is not in the dialect's table (src/program/code_tables.cpp): G890 or M930 in a ГОСТ "
     "program, G38.2 in a Fanuc one",
     "the controller stops with an alarm, or the code was misread or mistyped"},
    {"console-command", W, "linuxcnc", "GRBL v1.1 commands ($$, $I, $G, ?); the LinuxCNC G-code reference",
     "a line that is a GRBL console command ($I, $$, $G, ?) rather than G-code, in a file for the RS274NGC "
     "family",
     "GRBL runs it when a sender streams the file; LinuxCNC and other controls stop on it"},
    {"word-order", W, "gost", "ГОСТ 20999-83 §2.2",
     "a word out of the recommended order G, X Y Z U V W P Q R A B C, I J K, F, S, T, M (once a block)",
     "controllers of the ГОСТ family may expect this order"},
    {"sign-not-allowed", E, all, "ГОСТ 20999-83 §3.1.1, §3.3", "a sign on an N G F S T M E or O word",
     "these words have no sign: a sign there is a typing or reading mistake"},
    {"block-number-order", W, "gost", "ГОСТ 20999-83 §2.3", "a block number not greater than the one before",
     "searches by block number find the wrong block"},
    {"no-feed", W, all, "ГОСТ 20999-83 §3.7; Fanuc alarm 011; LinuxCNC 'F: set feed rate'",
     "a feed move (G01, G02, G03 in effect, with axis words) before any F in the program",
     "the controller stops with 'feed rate zero', or moves at a feed left from an earlier program"},
    {"arc-center", E, all, "ГОСТ 20999-83 §3.2; Fanuc and LinuxCNC: circular interpolation",
     "a G02/G03 block with an end point but no I, J, K (or, Fanuc and LinuxCNC, R)",
     "the controller cannot know the arc: it stops, or cuts a different path"},
    {"arc-radius", E, all,
     "controller manual excerpt §4.3, alarm 7.56 (to 1 µm, machine constant 55); LinuxCNC interp_arc.cc; Fanuc "
     "parameter No. 3410",
     "an arc by I, J, K whose radius to the end differs from its radius to the start by more than the control's "
     "tolerance (--arc-tolerance), or whose radius is zero",
     "the control stops with an alarm, or cuts a spiral that is not the part"},
    {"arc-radius-short", E, all, "Fanuc and LinuxCNC: circular interpolation by R",
     "an arc by R whose R is shorter than half the distance from its start to its end",
     "no circle of that radius reaches the end point: the control alarms"},
    {"arc-full-circle-r", E, all, "Fanuc and LinuxCNC: circular interpolation by R",
     "an arc by R that ends where it starts",
     "a full circle by R has no one centre: the control alarms or does nothing"},
    {"after-end", N, all, "ГОСТ 20999-83 §1.9", "text after M02/M30 that is not a new program",
     "the controller does not read it: it is not part of the program"},
    {"spec-address", E, all, "ГОСТ 20999-83 §9", "an address the controller format does not have",
     "the controller rejects the word"},
    {"spec-sign", E, all, "ГОСТ 20999-83 §9", "a sign the controller format does not allow for the address",
     "the controller rejects the word"},
    {"spec-point", E, all, "ГОСТ 20999-83 §3.1.4, §9", "a decimal point where the controller format has none",
     "the controller rejects the word or reads another value"},
    {"spec-digits", E, all, "ГОСТ 20999-83 §9", "more digits before or after the point than the format allows",
     "the controller rejects the word or reads another value"},
    {"spec-main", E, all, "ГОСТ 20999-83 §2.6, §9", "a ':' main block where the controller format has none",
     "the controller rejects the block"},
    {"spec-skip", E, all, "ГОСТ 20999-83 §2.7, §9", "a '/' block skip where the controller format has none",
     "the controller rejects the block"},
    {"machine-feed-code", E, all, "the machine's profile (tape machines show NAME): its feed code table",
     "a feed word whose first digit is no mode of the machine's feed code table (the 16К20Ф3С5's table 3: 1, 2, 7)",
     "the control rejects the word, or runs the feed in another mode"},
    {"machine-prefix", E, all, "the machine's profile: S, T and M words of three digits, the first 0 or 1",
     "an S, T or M word whose first digit is not 0 (at once) or 1 (after the machine's acknowledgement)",
     "the control rejects the word"},
    {"machine-speed-code", E, all, "the machine's profile: its spindle speed code table",
     "a speed code outside the machine's complete speed table", "the control rejects the word"},
    {"machine-travel", E, all, "the machine's profile: the travel of its axes (min_mm, max_mm)",
     "two end points of an axis farther apart than the axis travels, with nothing between them that moves the "
     "program's zero or the tool (work offsets, coordinate settings, tool and compensation words)",
     "wherever the program's zero stands, one of them is outside the travel: the control stops at its limit"},
    {"spec-word", E, all, "ГОСТ 20999-83 §9", "tape format: a word that cannot be written in the controller format",
     "the value does not fit the digits the controller reads"},
    // The codec's bad frames, which lint lists among the findings of a damaged tape read with -k.
    {"parity", E, every, "ГОСТ 13052-74 / ISO 646: even parity on track 8; EIA RS-244: odd parity on track 5",
     "a frame whose holes fail the code's parity check",
     "a misread or damaged frame: which character it was is not known, and nothing guesses it"},
    {"not_in_code", E, every, "ГОСТ 13052-74 / ISO 646; EIA RS-244",
     "a frame with good parity that is no character of the code",
     "a misread or damaged frame, or a tape in another code"},
    {"blank-frame", W, every, "ГОСТ 20999-83 §1.10 (blank tape only before '%' and after the end); EIA RS-244",
     "blank tape inside a block, between two of its characters (an error with --strict)",
     "a character whose holes were all lost reads as blank tape and vanishes: in EIA 0 1 2 4 8 - and space have "
     "one hole, so Z-1 becomes Z1"},
    {"run-decided", N, every, "tape restore: the doubts file beside the image (IMAGE.restore.json)",
     "a run of equal frames whose length the restoration decided against a read, by its odds or the program's rules",
     "a wrong length would hide here if the odds misled: one more read of the place settles it"},
    {"implied-point", W, all, "ГОСТ 20999-83 §3.1.4",
     "tape format: a program with no decimal point anywhere, whose numbers are taken as whole numbers",
     "with an implied point the same digits mean another size; give the source format with --from"},
});

}  // namespace

std::span<const Rule> all_rules() { return table; }

const Rule* find_rule(std::string_view id) {
    for (const auto& r : table)
        if (r.id == id) return &r;
    return nullptr;
}

bool rule_applies(const Rule& rule, Dialect d) {
    std::string_view name = dialect_name(d);
    for (std::size_t at = rule.dialects.find(name); at != std::string_view::npos;
         at = rule.dialects.find(name, at + 1)) {
        bool starts = at == 0 || rule.dialects[at - 1] == ' ';
        bool ends = at + name.size() == rule.dialects.size() || rule.dialects[at + name.size()] == ' ';
        if (starts && ends) return true;
    }
    return false;
}

}  // namespace tape
