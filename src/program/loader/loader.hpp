// The loader behind ProgramLoader: characters -> label, programs, blocks, words, statements, in one
// pass, a line at a time, in the dialect's reading (tape/dialect.hpp). Its stages are the files of
// this folder: feed.cpp (pieces of text -> lines and positions), programs.cpp (lines -> label,
// programs, the end of the record), block.cpp (a line -> blocks and their items), word.cpp (a word,
// the hot loop) and statements.cpp (macro statements, o-words).
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "program/chars.hpp"
#include "tape/program.hpp"

namespace tape {

namespace loading {
using chars::is_blank, chars::is_digit, chars::is_letter, chars::is_lower, chars::is_upper, chars::upper;

inline bool listed(std::string_view name, std::span<const std::string_view> list) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

inline std::string_view trim_right(std::string_view s) {
    while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
    return s;
}
}  // namespace loading

class Loader {
public:
    Loader(ProgramVisitor& visitor, const LoadOptions& options);
    void feed(std::string_view text, std::span<const std::uint64_t> frame_of);
    void finish();

private:
    enum class State { label, pending, program, after_end, record_ended };

    void choose(DialectChoice choice);
    void report(Finding f);
    void feed_lines(std::string_view text, std::span<const std::uint64_t> frame_of);
    void keep(std::string_view text, std::span<const std::uint64_t> frame_of);
    void run(std::string_view text, std::span<const std::uint64_t> frame_of);
    Location end_location() const;
    void begin_line(std::size_t b, std::size_t e);
    /// Where byte offset of text_ stands.
    Location at(std::size_t offset) const {
        Location l;
        locate(offset, l);
        return l;
    }
    /// The same, written into l field by field, inline for the plain case (an ASCII line of a text), as
    /// every word asks: a Location made on the stack and copied whole reads back what was just stored
    /// in a wider piece than it was stored in, and the CPU stalls on that.
    void locate(std::size_t offset, Location& l) const {
        if (!line_ascii_ || !frame_of_.empty()) {
            l = located(offset);
            return;
        }
        l.offset = base_ + offset;
        l.frame.reset();
        l.line = line_no_;
        l.column = offset - line_start_ + 1;
    }
    Location located(std::size_t offset) const;
    void find(std::string_view rule, std::size_t offset, std::uint64_t block, std::string message);
    std::size_t skip_blanks(std::size_t i, std::size_t e) const;

    void line(std::size_t b, std::size_t e, bool has_lf);
    void label_line(std::size_t b, std::size_t first, std::size_t e, std::string_view whole);
    bool comment_only(std::size_t i, std::size_t e) const;
    void hold(std::size_t b, std::string_view whole);
    bool held_ends_program() const;
    void release_leader(bool as_program);
    void start_pending();
    bool header_comment(std::size_t b, std::size_t first, std::size_t e, std::string_view whole);
    void replay_held();
    void after_end_line(std::size_t b, bool blank, std::string_view whole);
    void percent_line(std::size_t b, std::size_t pct, std::size_t e);
    void open_pending(std::size_t pct, std::size_t e, bool from_label);
    void close_pending_empty();
    void start(Program p);
    bool program_number_at(std::size_t i, std::size_t e) const;
    std::string program_number(std::size_t i, std::size_t e) const;
    void start_numbered(std::size_t i, std::size_t e);
    void unterminated();
    void blocks_in_line(std::size_t i, std::size_t e);

    std::size_t block(std::size_t i, std::size_t e);
    std::size_t block_head(std::size_t i, std::size_t end);
    bool stops_program(const Block& b) const;
    bool after_semicolon(std::size_t i) const;
    std::size_t block_item(std::size_t i, std::size_t end);
    std::size_t letters(std::size_t i, std::size_t end);
    std::size_t block_end(std::size_t i, std::size_t e) const;
    std::size_t statement_end(std::size_t i, std::size_t e) const;
    void word(std::size_t i, std::size_t e, std::size_t* next, std::uint64_t block_no, Word& w);
    bool macro_word(std::size_t i, std::size_t e, std::size_t* next, Word& w);
    std::size_t flagged(std::size_t i, std::size_t e, std::size_t end, std::string message,
                        std::string_view rule = "unknown-word");
    std::size_t stray_close(std::size_t i, std::size_t e) const;
    Word& flagged_word(std::size_t i, std::string_view text);
    std::size_t macro_statement(std::size_t i, std::size_t e, const std::string& keyword);
    struct MacroScan {  // a macro statement being read: its start, where reading is, its end
        std::size_t start, at, end;
    };
    bool if_statement(MacroScan& m);
    bool macro_condition(MacroScan& m, const char* what);
    void loop_number(MacroScan& m, Statement& s, const char* what);
    void goto_target(MacroScan& m, Statement& s);
    std::size_t assignment(std::size_t i, std::size_t e);
    std::size_t o_word(std::size_t i, std::size_t e);
    Statement& add_statement(Statement::Kind kind, std::size_t from, std::size_t to);
    void macro_problem(std::size_t i, std::string message);
    std::optional<long long> number_after(std::size_t& i, std::size_t end) const;
    std::size_t comment(std::size_t open, std::size_t e);
    std::size_t unexpected(std::size_t i, std::size_t e, std::uint64_t block_no);
    Word& next_word();

    ProgramVisitor& v_;
    LoadOptions options_;
    // Two dialects close: the runner-up reads the same text, and what it finds (rule, byte) is kept
    // here until this reading has passed it; a finding of this reading stands only if it is there too.
    struct SecondFindings : ProgramVisitor {
        std::set<std::pair<std::string, std::uint64_t>> found;
        void finding(const Finding& f) override { found.emplace(f.id(), f.where.byte.value_or(0)); }
    };
    std::unique_ptr<SecondFindings> second_found_;
    std::unique_ptr<Loader> second_;
    const DialectRules* rules_ = nullptr;
    bool linuxcnc_ = false;
    std::string sniff_;  // automatic: the text held until the dialect is chosen, and its frames
    std::vector<std::uint64_t> sniff_frames_;

    std::string_view text_;                    // the lines being loaded now
    std::span<const std::uint64_t> frame_of_;  // their frames, or empty
    std::uint64_t base_ = 0;                   // offset of text_[0] from the start of the text
    bool ends_with_lf_ = false;                // of the text loaded so far: where its end is
    std::uint64_t last_line_chars_ = 0;
    std::optional<std::uint64_t> last_frame_{};
    std::string pending_;  // an unfinished line, and its frames
    std::vector<std::uint64_t> pending_frames_;
    State state_ = State::label;
    std::uint64_t line_no_ = 0, ordinal_ = 0;
    std::size_t line_start_ = 0;
    bool line_ascii_ = true;
    // The line [line_start_, line_end_) holds a ';' or a ')': where it holds none, no block of it needs
    // to look for one.
    std::size_t line_end_ = 0;
    bool line_semicolon_ = true, line_close_ = true;
    bool within_line(std::size_t i, std::size_t e) const { return i >= line_start_ && e <= line_end_; }
    mutable std::size_t column_offset_ = 0;  // the last place of a non-ASCII line a column was counted for
    mutable std::uint64_t column_ = 1;       // and that column
    bool any_program_ = false;
    bool after_end_started_ = false;
    bool last_line_was_block_ = false;
    bool last_block_stops_ = false;   // the last block stops the program without an end code
    bool local_subprograms_ = false;  // Haas: the program calls blocks after its M30 (M97 P)
    Program pending_header_;          // a '%' whose program starts with its first block
    // Lines held back until what they are is known (at most dialect_sample_bytes): where the dialect
    // needs no '%', the text before the first '%' (label, or the program a closing '%' ends), and the
    // comment lines between a '%' and the O number of its program.
    std::string held_;
    std::vector<std::uint64_t> held_frames_;
    std::uint64_t held_base_ = 0, held_line_ = 0;  // the offset of its first line, and the line before it
    bool leader_open_ = true;                      // the text before the first '%' may still be label
    bool pending_from_label_ = false;
    Location program_start_, last_block_where_;
    std::uint64_t last_block_ordinal_ = 0;
    Block blk_;  // reused: its vectors keep their capacity from block to block
    std::size_t words_used_ = 0, comments_used_ = 0;
};

}  // namespace tape
