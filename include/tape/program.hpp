// Programs, blocks (кадры) and words rebuilt from a character stream per ГОСТ 20999-83.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/dialect.hpp"
#include "tape/error.hpp"

namespace tape {

/// Where something stands: on tape (frame, from 1) when the text came from a tape, and always in the
/// text (byte offset from 0; line and column, in characters, from 1).
struct Location {
    std::uint64_t offset = 0;
    std::optional<std::uint64_t> frame{};
    std::uint64_t line = 0;
    std::uint64_t column = 0;

    /// The same place as a diagnostic's position.
    Position position() const { return Position{.frame = frame, .line = line, .column = column, .byte = offset}; }
};

/// One word: address letter, optional sign, digits, optional explicit decimal point (§3.1).
struct Word {
    char address = 0;    ///< 'A'..'Z' (lowercase read as capitals where the dialect allows), ':' for a main block
    std::string text;    ///< as written, spaces removed: "X+12.5", "S64", "x1.5", "Z-[#1+2.]"
    char sign = 0;       ///< '+', '-' or 0
    int point = -1;      ///< explicit point: digits before it (X.03 -> 0, X1030. -> 4); -1 none
    bool macro = false;  ///< the value is a macro variable or expression ("X#1", "Z[#2*2]")
    bool known = true;   ///< false: the dialect does not know it; kept as written and reported once
    Location where;
    /// The loader's reading of the digits as it met them, so that integer(), asked again by every
    /// check, does not read the text again: digit_count -1 when the word was not made by the loader.
    long long digits_value = 0;
    int digit_count = -1;

    bool has_point() const { return point >= 0; }
    /// The digits without sign and point: "125" for.
    std::string digits() const;
    /// The integer value of a word without a point (G01 -> 1), or nullopt (point, no digits, too long).
    /// Inline: every check asks it of every word, and the loader has already read the digits.
    std::optional<long long> integer() const {
        if (has_point() || macro || !known) return std::nullopt;
        if (digit_count < 0) return integer_of_text();
        if (digit_count == 0 || digit_count > 18) return std::nullopt;
        return sign == '-' ? -digits_value : digits_value;
    }

private:
    std::optional<long long> integer_of_text() const;
};

struct Comment {
    std::string text;        ///< between the brackets (or after ';'), as written
    Location where;          ///< the '(' or ';'
    bool semicolon = false;  ///< a ';' comment to the end of the line (LinuxCNC)
};

/// A macro statement: Fanuc Custom Macro B or a LinuxCNC o-word, kept as written.
struct Statement {
    enum class Kind { assignment, if_goto, if_then, go_to, while_do, loop_do, loop_end, output, o_word };
    Kind kind = Kind::assignment;
    std::string text;                   ///< as written, blanks kept: "IF [#1 EQ 2] GOTO 10"
    std::optional<long long> number{};  ///< GOTO's target block, DO/END's loop number
    std::string label;                  ///< o-word: its number or <name>, lowercase ("100", "<probe>")
    std::string keyword;                ///< o-word: sub, endsub, call, if, else, endif, while, ...
    Location where;
};

struct Block {
    Location where;                ///< the first character of the block
    std::uint64_t ordinal = 0;     ///< 1-based count of blocks on the whole tape
    bool skip = false;             ///< '/' block skip (§2.7)
    int skip_level = 0;            ///< Fanuc "/1".."/9"; 0 for a plain '/'
    bool main = false;             ///< ':' main block (§2.6)
    bool ends = false;             ///< ends the program in the loader's dialect (M02, M30; Fanuc also M99)
    bool damaged = false;          ///< holds a bad frame read past (U+FFFD): its findings are the bad frame's
    std::optional<Word> number{};  ///< N… or :… (address 'N' or ':')
    std::vector<Word> words;       ///< the other words, in order, flagged ones (Word::known) included
    std::vector<Comment> comments;
    std::vector<Statement> statements;
    std::string source;  ///< the block as written, without its end of block

    /// "N001", ":005" or "".
    std::string number_text() const { return number ? number->text : std::string(); }
    /// True when the block ends the program: M02 or M30 (and M99 for Fanuc), as the loader decided.
    bool ends_program() const { return ends; }
    /// The block written out: "/N006 M00 (TEXT)", words separated by one space.
    std::string text() const;
};

/// True when the block holds one of the M codes in ends (DialectRules::program_ends, or {99}).
bool holds_end_code(const Block& block, std::span<const int> ends);

/// A program number without its 'O' or ':' and leading zeros ("O0012", ":12" -> "12"), so that the
/// spellings of one number compare equal.
std::string_view program_key(std::string_view number);

struct Program {
    Location start;                       ///< the '%' that starts it, or its first block when none does
    std::optional<std::string> number{};  ///< between '%' and LF (§1.6), or Fanuc's "O1234"
    bool percent = true;                  ///< started by a '%' (LinuxCNC and Fanuc programs need none)
    bool numbered_by_block = false;       ///< number is Fanuc's "O1234" block, not the text after '%'
    std::vector<Block> blocks;
    bool ended = false;     ///< a block with M02/M30 closes it (§1.9)
    std::string after_end;  ///< text after the end, up to the next '%': not part of it
    std::optional<Location> after_end_at{};
};

/// A finding of the loader or of lint: a Diagnostic with a rule id (Errc::bad_program).
using Finding = Diagnostic;
/// The finding of rule (an id of tape/rules.hpp, which gives its severity) at where, in block
/// (Block::ordinal; 0 when not in a block).
Finding program_finding(std::string_view rule, const Location& where, std::uint64_t block, std::string message);

/// The contents of a tape: the label section, the programs, and what the loader found wrong.
struct LoadedTape {
    Dialect dialect = Dialect::gost;       ///< the dialect it was read in
    std::string dialect_reason;            ///< why, when it was chosen automatically
    std::string label;                     ///< before the first '%' (§1.8), in every dialect: never executed
    bool physical_start = false;           ///< "%%": the physical start of the tape (§1.8)
    std::optional<Location> record_end{};  ///< the '%' after the last program: end of record, rewind stop
    std::vector<Program> programs;
    std::vector<Finding> findings;        ///< syntax findings, in text order
    std::string text;                     ///< the characters the tape was loaded from
    std::vector<std::uint64_t> frame_of;  ///< 0-based frame of each byte of text, empty for text input

    /// The location of byte offset in text.
    Location locate(std::uint64_t offset) const;
};

/// Receives what the loader finds, in text order, without anything being kept: the way to read long
/// tapes, or a tape as it comes off a reader. The Block passed is reused for the next one: copy what
/// you keep.
class ProgramVisitor {
public:
    virtual ~ProgramVisitor() = default;
    /// Text before the first '%' (§1.8), in pieces as lines come; where the dialect needs no '%', all of
    /// it when the '%' comes (until then it may yet be a program that '%' closes).
    virtual void label(std::string_view text) { (void)text; }
    /// A '%' starts a program; the header has its start and number and no blocks yet.
    virtual void program_start(const Program& header) { (void)header; }
    virtual void block(const Block& block) { (void)block; }
    /// Text after M02/M30 up to the next '%' (§1.9), a line at a time.
    virtual void after_end(std::string_view text, const Location& where) { (void)text, (void)where; }
    /// The '%%' physical start mark (§1.8).
    virtual void physical_start() {}
    /// A '%' after the last program, followed by nothing: the end of the record, the rewind stop.
    /// closes_program: it ends the program before it (LinuxCNC's closing '%').
    virtual void record_end(const Location& where, bool closes_program) { (void)where, (void)closes_program; }
    /// The dialect the text is read in, before anything else; with Dialect::automatic, why it was chosen.
    virtual void dialect(const DialectChoice& choice) { (void)choice; }
    virtual void finding(const Finding& finding) { (void)finding; }
    /// The text has ended; where is just past its last character.
    virtual void end(const Location& where) { (void)where; }
};

/// How text is read into programs.
struct LoadOptions {
    Dialect dialect = Dialect::gost;  ///< automatic: chosen from the first 64 KiB (guess_dialect)
    /// Where the dialect needs no '%': text before the first '%' is label unless it ends a program that
    /// '%' closes. false: it is the program (a piece cut from inside a text, which has no leader).
    bool leader = true;
};

/// The loader fed a piece of text at a time, in bounded memory (a line is held until its LF comes):
/// the same findings and blocks as load() however the text is cut.
class ProgramLoader {
public:
    explicit ProgramLoader(ProgramVisitor& visitor, const LoadOptions& options = {});
    ~ProgramLoader();
    ProgramLoader(const ProgramLoader&) = delete;
    ProgramLoader& operator=(const ProgramLoader&) = delete;

    /// The next piece of text; frame_of (0-based frame of each of its bytes) empty for text input.
    void feed(std::string_view text, std::span<const std::uint64_t> frame_of = {});
    /// The text has ended: loads the last line and reports a program left open.
    void finish();

private:
    std::unique_ptr<class Loader> loader_;
};

/// Streams text through the loader: the same parse as load(), block by block.
/// frame_of as for load(); text and frame_of must outlive the call only.
void load_each(std::string_view text, std::span<const std::uint64_t> frame_of, ProgramVisitor& visitor,
               const LoadOptions& options = {});

/// Rebuilds programs from decoded characters. frame_of (0-based frame of each byte, as decode() gives
/// with positions) may be empty for a plain text program. Never throws on bad input: syntax problems
/// become findings (the loader's rules in tape/rules.hpp).
LoadedTape load(std::string text, std::vector<std::uint64_t> frame_of = {}, const LoadOptions& options = {});

}  // namespace tape
