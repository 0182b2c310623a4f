// What a tape's own program says about how it is written, learned from its blocks that no damage
// touches, for repair to hold a candidate against (repair.cpp): the word formats it keeps, its block
// numbers' step, the G and M codes it uses, the values its feeds, speeds and tools take, where the tool
// stands before each damaged block (for arcs), which findings it has anyway, and how its characters
// follow one another (for guesses).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "tape/format_spec.hpp"
#include "tape/frame.hpp"
#include "tape/lint.hpp"
#include "tape/machine_checks.hpp"
#include "tape/program.hpp"

namespace tape::detail {

/// How a word is written: its sign, and the digits before and after an explicit point (without one,
/// all its digits and after = -1).
struct WordShape {
    char sign = 0;
    int before = 0, after = -1;
    auto operator<=>(const WordShape&) const = default;
};
/// A G or M word is a code the machine's profile lists (an M word of a prefixed M read without its first
/// digit, 0 or 1: M104 is M04); nullopt for a word that is no code (no whole number).
std::optional<bool> machine_lists_code(const MachineProfile& p, const Word& w);

/// The shape of a plain word; nullopt for a macro value or a word with no digits.
std::optional<WordShape> shape_of(const Word& w);

/// The machine's state where a block begins, as far as the blocks before it tell.
struct MotionState {
    std::array<std::optional<double>, 3> at{};  ///< X, Y, Z
    std::array<bool, 3> pointed{};              ///< the coordinate was written with a decimal point
    bool absolute = true;                       ///< G90 (G91: incremental)
    int plane = 17;                             ///< G17, G18, G19
    int motion = -1;                            ///< the modal motion G code (0-3), or -1
};

/// Moves state through one block: G90/G91, the plane, the motion code, and X, Y, Z. A block whose
/// axis words mean something else (a dwell, a reference return, a setting), or whose values are
/// macro expressions, leaves the axes it names unknown.
void advance(MotionState& state, const Block& block);

/// For a G02/G03 block with a centre (I, J, K) or a radius (R): true when its start (state) and end lie
/// on one circle within the controller's tolerance, false when they do not; nullopt when the block is
/// no arc or where the tool stands is not known.
std::optional<bool> arc_agrees(const MotionState& before, const Block& block);

/// Learned as the loader streams the program's text through it (load_each), so that no block is held:
/// then finish() with that text.
class TapeRules : public ProgramVisitor {
public:
    /// damaged_lines: the lines (from 1) whose blocks are left out of what is learned; the motion state
    /// before each is kept. numbers_damaged: those of them whose damage may touch the block number (the
    /// others' numbers still tell the sequence).
    TapeRules(const std::set<std::uint64_t>& damaged_lines, const std::set<std::uint64_t>& numbers_damaged,
              const FormatSpec* spec, const MachineProfile* machine = nullptr);
    ~TapeRules() override;

    void dialect(const DialectChoice& choice) override { lint_->dialect(choice); }
    void program_start(const Program& header) override;
    void block(const Block& b) override;
    void after_end(std::string_view text, const Location& where) override { lint_->after_end(text, where); }
    void finding(const Finding& f) override { lint_->finding(f); }
    void end(const Location& where) override { lint_->end(where); }
    /// The findings the undamaged program has anyway, once the whole text went through.
    void finish(std::string_view text);

    /// A word of this shape breaks how the tape writes the address (at least enough_words times, every
    /// time so): its point style (always or never a point), its number of decimals, a fixed width
    /// (zeros punched), its sign style (never '+', or always a sign); or it has more digits before the
    /// point than any of a hundred words or more of that address (ten of them with the most).
    bool format_broken(char address, const WordShape& shape) const;
    /// A word the dialect cannot read ("ZR83.25") where the tape writes that address as a word every
    /// time (enough_words of them).
    bool form_broken(const Word& w) const;
    /// An address letter no undamaged block uses, on a tape of enough_blocks such blocks or more.
    bool address_unused(char address) const;
    /// The word's letter is lower case where every word of the tape is upper case, or the other way
    /// round (enough_words of them).
    bool case_broken(const Word& w) const;
    /// How many undamaged words of the address (with digits) the tape's format for it rests on.
    std::size_t words_of(char address) const {
        auto n = words_.find(address);
        return n == words_.end() ? 0 : n->second;
    }
    /// G or M code value (code_value form) used in an undamaged block.
    bool code_used(char letter, std::string_view value) const;
    /// The number a damaged block's N word must have where its neighbours keep a steady step: the
    /// block numbers before and after line and the tape's step agree, or two numbered blocks on each
    /// side keep one step of their own (N99999 repeated keeps a step of 0).
    std::optional<long long> expected_number(std::uint64_t line) const;
    /// A feed, speed or tool number far outside the values the tape gives that address.
    bool value_out_of_range(char address, double value) const;
    /// A finding the undamaged program has too: its rule and what it is about (the code, or the
    /// character where it points).
    bool excused(const std::string& key) const { return excused_.count(key) > 0; }
    /// The motion state where a damaged line begins, if the blocks before it tell.
    const MotionState* state_before(std::uint64_t line) const;
    /// The tape's own undamaged arcs close as arc_agrees checks them (at least three, nine in ten): only
    /// then does arc geometry judge a repair (a controller may read I, J, K otherwise).
    bool arcs_trusted() const { return arcs_checked_ >= 3 && arcs_open_ * 10 <= arcs_checked_; }
    const FormatSpec* spec() const { return spec_; }
    /// The format block b at line is held to: the machine's, in the mode the blocks before it and its own
    /// codes set (b is a damaged line's block), else spec(); nullptr for none.
    const FormatSpec* block_spec(std::uint64_t line, const Block& b) const;
    const MachineProfile* machine() const { return machine_; }
    /// The tape's undamaged words of the address, enough_words of them or more, all fit the machine's
    /// format (a tape that does not keep its machine's format for an address, or shows too little of it,
    /// is not held to it there: a repair would be judged by a rule the tape itself may break).
    bool machine_format_trusted(char address) const {
        auto n = fitting_.find(address);
        return !untrusted_.count(address) && n != fitting_.end() && n->second >= enough_words;
    }
    /// Whether the machine's format rule (check_word's id) holds a repair of a word of the address. Digit
    /// counts vary by address and mode (the course text's OCR breaks them): as machine_format_trusted. A
    /// rule of notation (an address the format lacks, a sign on an unsigned address, a point without DS)
    /// holds wherever the tape's undamaged words, enough_words of them or more, never break it at any
    /// address: the tape keeps its machine's notation, and the profile says which addresses and signs
    /// the machine reads, also for an address the tape has too few words of. "spec-tab" (a tab where the
    /// format has no HT) holds where, besides, no undamaged line has one.
    bool machine_rule_trusted(char address, std::string_view rule) const;
    /// The G and M codes of the tape's undamaged blocks, enough_words of them or more, are all the
    /// machine's (its profile lists them): only then is a code the profile does not list ruled out (the
    /// profile lists the codes its sources give, and says nowhere that there are no others).
    bool machine_codes_trusted() const { return machine_codes_ >= enough_words && !foreign_codes_; }
    /// The dialect's grammar fits the undamaged program: lint finds errors in at most one block in five.
    /// Where it does not (no known dialect fits: an Okuma or Siemens program read as another), repairs
    /// are not judged by it.
    bool grammar_fits() const { return error_lines_ * 5 <= std::max<std::size_t>(blocks_, 1); }
    /// The undamaged lines write many numbers of two digits or more (enough_digit_pairs pairs of digits
    /// side by side, outside comments) and never a space between two digits: a space there breaks how
    /// the tape writes its words (it may put spaces between a letter, a sign and the digits).
    bool digits_never_split() const { return digit_pairs_ >= enough_digit_pairs && split_digits_ == 0; }
    /// An undamaged line holds a tab (HT).
    bool tabs() const { return tabs_; }
    /// The program writes explicit points somewhere (for a format spec's checks).
    bool points() const { return points_; }
    static constexpr std::size_t enough_words = 5;
    static constexpr std::size_t enough_blocks = 5;
    static constexpr std::size_t enough_digit_pairs = 20;

private:
    void learn_block(const Block& b, bool damaged);
    void learn_machine_format(const Word& w, const FormatSpec& spec);
    void learn_step();
    void learn_digit_spacing(std::string_view line);
    std::optional<long long> local_sequence(std::size_t at) const;
    bool more_digits_than_ever(char address, const WordShape& shape) const;
    static constexpr long long damaged_number = -1, no_number = -2;  // in numbers_

    const std::set<std::uint64_t>& damaged_lines_;
    const std::set<std::uint64_t>& numbers_damaged_;
    std::unique_ptr<LintVisitor> lint_;
    MotionState state_;

    std::map<char, std::map<WordShape, std::size_t>> shapes_;
    std::map<char, std::size_t> words_;
    std::map<char, std::size_t> padded_;      // words punched with leading zeros, by address
    std::map<char, std::size_t> unreadable_;  // words the dialect cannot read, by address, in undamaged blocks
    std::map<char, std::size_t> addresses_;   // words (and block numbers) by address, in undamaged blocks
    std::size_t undamaged_blocks_ = 0, lower_words_ = 0, upper_words_ = 0;
    std::set<std::string> codes_;
    std::vector<std::pair<std::uint64_t, long long>> numbers_;  // (line, N) of each block
    std::map<char, std::pair<double, double>> ranges_;          // F S T: least and most
    std::map<char, std::size_t> range_words_;
    std::set<std::string> excused_;
    std::map<std::uint64_t, MotionState> before_;
    const FormatSpec* spec_;
    const MachineProfile* machine_;
    std::optional<MachineFormat> format_;                   // with a machine: the mode where the next block begins
    std::map<std::uint64_t, MachineFormat> format_before_;  // and where each damaged line begins
    std::set<char> untrusted_;             // addresses whose undamaged words break the machine's digit counts
    std::map<char, std::size_t> fitting_;  // undamaged words that keep them, by address
    std::set<std::string, std::less<>> broken_rules_;  // the machine's rules of notation undamaged words break
    std::size_t checked_words_ = 0;                    // undamaged words held to the machine's format
    std::size_t machine_codes_ = 0;                    // undamaged G and M words the profile lists
    bool foreign_codes_ = false;                       // and some it does not
    bool points_ = false;
    std::size_t digit_pairs_ = 0, split_digits_ = 0;  // in undamaged lines: digits side by side, and apart
    bool tabs_ = false;                               // an undamaged line holds a tab (HT)
    long long step_ = 0;                              // the block numbers' steady step, 0 for none
    std::size_t arcs_checked_ = 0, arcs_open_ = 0;
    std::size_t blocks_ = 0, error_lines_ = 0;
};

/// How a tape's frames follow one another, for guesses: counts of one, two and three frames in a row
/// (blank tape skipped, as a reader skips it; DEL counted, as DEC tapes punch it after every tab), the
/// three mixed so that a frame seen often but never in this company still counts.
class CharModel {
public:
    void learn(std::span<const Frame> frames);
    /// How likely f is between the two frames before it and the one after (blank tape skipped), by how
    /// the tape goes: a log-odds score, higher is likelier.
    double score(Frame before2, Frame before1, Frame f, Frame after) const;

private:
    double chance(Frame a, Frame b, Frame c) const;  // of c after a b

    std::unordered_map<std::uint32_t, std::uint32_t> trigrams_;  // (a, b, c) -> count
    std::unordered_map<std::uint32_t, std::uint32_t> bigrams_;   // (a, b) -> count
    std::array<std::uint64_t, 256> unigrams_{};
    std::uint64_t total_ = 0;
};

/// The key of a finding for TapeRules::excused: its rule, and the code (unknown-code) or the character
/// at its column in text otherwise.
std::string finding_key(const Finding& f, std::string_view line_text);

/// True when text reads as an NC program: most of its letters outside comments are addresses followed
/// by a value, as words are. DEC MACRO source, Elliott SIR and other text get no NC grammar.
bool looks_like_nc_program(std::string_view text);

}  // namespace tape::detail
