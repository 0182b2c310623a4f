// Loader: characters -> label, programs, blocks, words (ГОСТ 20999-83 §1-§3), read as the dialect
// reads them. One pass, a line (block) at a time; problems become findings, never exceptions.
#include "loader.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <utility>

#include "chars.hpp"
#include "codec/swar.hpp"
#include "codec/utf8.hpp"
#include "macro.hpp"
#include "tape/decode.hpp"
#include "tape/rules.hpp"

namespace tape {
namespace {

constexpr std::size_t sniff_limit = 64 << 10;  // text looked at to choose a dialect

using chars::is_blank, chars::is_digit, chars::is_letter, chars::is_lower, chars::is_upper, chars::upper;

// What a character can be inside a word, looked up once per character in the hot loop.
enum class CharClass : std::uint8_t { other, digit, point, sign, blank };
constexpr auto char_class = [] {
    std::array<CharClass, 256> t{};
    for (int c = '0'; c <= '9'; ++c) t[static_cast<std::size_t>(c)] = CharClass::digit;
    t['.'] = CharClass::point;
    t['+'] = t['-'] = CharClass::sign;
    t[' '] = t['\t'] = t['\r'] = t[0x11] = t[0x12] = t[0x13] = t[0x14] = CharClass::blank;
    return t;
}();

constexpr std::array<std::string_view, 9> macro_keywords = {"IF",    "GOTO",  "WHILE", "DO",   "END",
                                                            "POPEN", "PCLOS", "DPRNT", "BPRNT"};
constexpr std::array<std::string_view, 15> o_keywords = {"SUB",    "ENDSUB", "CALL",      "RETURN", "IF",
                                                         "ELSEIF", "ELSE",   "ENDIF",     "WHILE",  "ENDWHILE",
                                                         "DO",     "REPEAT", "ENDREPEAT", "BREAK",  "CONTINUE"};
bool listed(std::string_view name, std::span<const std::string_view> list) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

// Russian keyboards type Cyrillic letters that look like Latin addresses: "Х+37." reads as X+37.
std::string look_alike_hint(std::string_view token) {
    static constexpr std::array<std::pair<std::string_view, char>, 14> pairs = {{{"А", 'A'},
                                                                                 {"В", 'B'},
                                                                                 {"С", 'C'},
                                                                                 {"Е", 'E'},
                                                                                 {"Н", 'H'},
                                                                                 {"К", 'K'},
                                                                                 {"М", 'M'},
                                                                                 {"О", 'O'},
                                                                                 {"Р", 'P'},
                                                                                 {"Т", 'T'},
                                                                                 {"Х", 'X'},
                                                                                 {"У", 'Y'},
                                                                                 {"З", 'Z'},
                                                                                 {"І", 'I'}}};
    for (const auto& [cyrillic, latin] : pairs)
        if (token.starts_with(cyrillic))
            return std::string(": its first letter is the Cyrillic ") + std::string(cyrillic) + ", not the Latin " +
                   latin;
    return "";
}

std::string_view trim_right(std::string_view s) {
    while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
    return s;
}

}  // namespace

Loader::Loader(ProgramVisitor& visitor, const LoadOptions& options) : v_(visitor), options_(options) {
    if (options_.dialect != Dialect::automatic) choose(options_.dialect, "");
}

void Loader::choose(Dialect d, std::string reason) {
    rules_ = &dialect_rules(d);
    linuxcnc_ = d == Dialect::linuxcnc;
    v_.dialect(DialectChoice{d, std::move(reason)});
}

// Automatic: the text is held until enough of it has come to choose the dialect from.
void Loader::feed(std::string_view text, std::span<const std::uint64_t> frame_of) {
    if (!frame_of.empty() && frame_of.size() != text.size()) frame_of = {};
    if (rules_) {
        feed_lines(text, frame_of);
        return;
    }
    sniff_ += text;
    sniff_frames_.insert(sniff_frames_.end(), frame_of.begin(), frame_of.end());
    if (sniff_.size() < sniff_limit) return;
    auto choice = guess_dialect(sniff_);
    choose(choice.dialect, std::move(choice.reason));
    feed_lines(sniff_, sniff_frames_.size() == sniff_.size() ? std::span<const std::uint64_t>(sniff_frames_)
                                                             : std::span<const std::uint64_t>());
    sniff_ = {};
    sniff_frames_ = {};
}

// Whole lines are loaded as they come; the unfinished last one waits for the next piece.
void Loader::feed_lines(std::string_view text, std::span<const std::uint64_t> frame_of) {
    auto last_nl = text.rfind('\n');
    if (last_nl == std::string_view::npos) {
        keep(text, frame_of);
        return;
    }
    std::size_t from = 0;
    if (!pending_.empty()) {
        from = text.find('\n') + 1;
        keep(text.substr(0, from), frame_of.empty() ? frame_of : frame_of.first(from));
        run(pending_, pending_frames_);
        pending_.clear();
        pending_frames_.clear();
    }
    run(text.substr(from, last_nl + 1 - from),
        frame_of.empty() ? frame_of : frame_of.subspan(from, last_nl + 1 - from));
    keep(text.substr(last_nl + 1), frame_of.empty() ? frame_of : frame_of.subspan(last_nl + 1));
}

void Loader::finish() {
    if (!rules_) {
        auto choice = guess_dialect(sniff_);
        choose(choice.dialect, std::move(choice.reason));
        std::string held = std::move(sniff_);
        std::vector<std::uint64_t> frames = std::move(sniff_frames_);
        feed_lines(held, frames.size() == held.size() ? std::span<const std::uint64_t>(frames)
                                                      : std::span<const std::uint64_t>());
    }
    bool cut_in_block = false;
    if (!pending_.empty()) {
        run(pending_, pending_frames_);
        cut_in_block = last_line_was_block_ && !pending_frames_.empty();
    }
    pending_.clear();
    pending_frames_.clear();
    if (state_ == State::pending) close_pending_empty();
    if (cut_in_block) {  // one cause: the tape was cut or read short, so the program has no end either
        bool open = state_ == State::program;
        v_.finding(program_finding("incomplete-block", last_block_where_, last_block_ordinal_,
                                   std::string("the tape ends in the middle of a block: its end of block (LF) never "
                                               "came") +
                                       (open ? ", nor the end of program" : "")));
        state_ = State::after_end;
    }
    if (state_ == State::program) unterminated();
    v_.end(end_location());
}

void Loader::keep(std::string_view text, std::span<const std::uint64_t> frame_of) {
    pending_ += text;
    pending_frames_.insert(pending_frames_.end(), frame_of.begin(), frame_of.end());
}

// Loads whole lines (the last may lack its LF only at the end of the text).
void Loader::run(std::string_view text, std::span<const std::uint64_t> frame_of) {
    text_ = text;
    frame_of_ = frame_of;
    std::size_t b = 0;
    while (b < text_.size()) {
        auto nl = text_.find('\n', b);
        std::size_t e = nl == std::string_view::npos ? text_.size() : nl;
        begin_line(b, e);
        line(b, e, nl != std::string_view::npos);
        b = e + 1;
    }
    if (!text_.empty()) {
        ends_with_lf_ = text_.back() == '\n';
        if (!ends_with_lf_) {
            auto start = text_.rfind('\n');
            std::string_view last = text_.substr(start == std::string_view::npos ? 0 : start + 1);
            last_line_chars_ = static_cast<std::uint64_t>(
                std::count_if(last.begin(), last.end(), [](char c) { return !utf8::is_continuation(c); }));
        }
        if (!frame_of_.empty()) last_frame_ = frame_of_.back() + 1;
    }
    base_ += text_.size();
}

// Just past the last character: the start of the line after a final LF, else the end of the last line.
Location Loader::end_location() const {
    Location l;
    l.offset = base_;
    l.frame = last_frame_;
    l.line = ends_with_lf_ || line_no_ == 0 ? line_no_ + 1 : line_no_;
    l.column = ends_with_lf_ || line_no_ == 0 ? 1 : last_line_chars_ + 1;
    return l;
}

void Loader::begin_line(std::size_t b, std::size_t e) {
    ++line_no_;
    line_start_ = b;
    line_ascii_ = !swar::any_high_byte(text_.data() + b, e - b);
}

Location Loader::at(std::size_t offset) const {
    Location l;
    l.offset = base_ + offset;
    if (!frame_of_.empty()) l.frame = frame_of_[std::min(offset, frame_of_.size() - 1)] + 1;
    l.line = line_no_;
    l.column = offset - line_start_ + 1;
    if (!line_ascii_)
        l.column =
            1 + static_cast<std::uint64_t>(std::count_if(text_.begin() + static_cast<std::ptrdiff_t>(line_start_),
                                                         text_.begin() + static_cast<std::ptrdiff_t>(offset),
                                                         [](char c) { return !utf8::is_continuation(c); }));
    return l;
}

// Findings of rules the dialect does not have are not made at all.
void Loader::find(std::string_view rule, std::size_t offset, std::uint64_t block, std::string message) {
    const Rule* r = find_rule(rule);
    if (r && !rule_applies(*r, rules_->dialect)) return;
    if (block && block == blk_.ordinal && blk_.damaged) return;  // the bad frame read past is the one cause
    v_.finding(program_finding(rule, at(offset), block, std::move(message)));
}

std::size_t Loader::skip_blanks(std::size_t i, std::size_t e) const {
    while (i < e && is_blank(text_[i])) ++i;
    return i;
}

void Loader::line(std::size_t b, std::size_t e, bool has_lf) {
    std::size_t first = skip_blanks(b, e);
    bool blank = first >= e;
    last_line_was_block_ = false;
    std::string_view whole = text_.substr(b, e - b + (has_lf ? 1 : 0));
    if (state_ == State::label) {
        auto pct = rules_->needs_percent ? text_.find('%', b) : (blank || text_[first] != '%' ? e : first);
        if (pct != std::string_view::npos && pct < e) {
            if (pct > b) v_.label(text_.substr(b, pct - b));
            percent_line(b, pct, e);
        } else if (rules_->needs_percent || blank) {
            v_.label(whole);
        } else if (program_number_at(first, e)) {
            start_numbered(first, e);
            blocks_in_line(first, e);
        } else {
            Program p;
            p.start = at(first);
            p.percent = false;
            start(std::move(p));
            blocks_in_line(first, e);
        }
        return;
    }
    if (!blank && text_[first] == '%') {
        percent_line(b, first, e);
        return;
    }
    switch (state_) {
        case State::label:
            return;
        case State::pending:
            if (blank) return;
            if (!pending_header_.number && program_number_at(first, e)) {
                pending_header_.number = program_number(first, e);
                pending_header_.numbered_by_block = true;
            }
            start(std::move(pending_header_));
            blocks_in_line(first, e);
            return;
        case State::after_end:
            if (!blank && program_number_at(first, e)) {
                start_numbered(first, e);
                blocks_in_line(first, e);
                return;
            }
            if (!blank || after_end_started_) {
                after_end_started_ = true;
                v_.after_end(whole, at(b));
            }
            return;
        case State::record_ended:  // after the end of record nothing is read
            if (!blank || after_end_started_) {
                after_end_started_ = true;
                v_.after_end(whole, at(b));
            }
            return;
        case State::program:
            if (!blank && last_block_ordinal_ && program_number_at(first, e)) {
                unterminated();
                start_numbered(first, e);
            }
            blocks_in_line(first, e);
            return;
    }
}

// A line that starts with '%': a program start, the physical start of the tape, or the end of the record.
void Loader::percent_line(std::size_t b, std::size_t pct, std::size_t e) {
    (void)b;
    switch (state_) {
        case State::label:
            open_pending(pct, e, true);
            return;
        case State::pending:
            close_pending_empty();
            open_pending(pct, e, false);
            return;
        case State::program:
            if (linuxcnc_) {  // the closing '%' ends the program; LinuxCNC reads nothing after it
                v_.record_end(at(pct), true);
                state_ = State::record_ended;
                return;
            }
            unterminated();
            if (rules_->closing_percent) {
                v_.record_end(at(pct), false);
                state_ = State::record_ended;
                return;
            }
            open_pending(pct, e, false);
            return;
        case State::after_end:
            if (rules_->closing_percent && any_program_) {  // Fanuc: the end of record; reading stops
                v_.record_end(at(pct), false);
                state_ = State::record_ended;
                return;
            }
            open_pending(pct, e, false);
            return;
        case State::record_ended:  // a record that follows (files put one after the other)
            open_pending(pct, e, false);
            return;
    }
}

// A '%' opens a program that starts with its first block; when none comes it was the end of record.
void Loader::open_pending(std::size_t pct, std::size_t e, bool from_label) {
    Program p;
    p.start = at(pct);
    std::size_t i = skip_blanks(pct + 1, e);
    if (i < e && text_[i] == '%') {
        if (!any_program_ && from_label)
            v_.physical_start();
        else
            find("program-start", i, 0,
                 "'%%' marks the physical start of the tape only before the first program (§1.8)");
        i = skip_blanks(i + 1, e);
    }
    std::string number;
    bool odd = false;
    for (; i < e; ++i) {
        if (is_blank(text_[i]) || (text_[i] == ';' && rules_->semicolon_ends_block)) continue;  // Fanuc's "%;"
        odd |= !(is_digit(text_[i]) || is_upper(text_[i]));
        number += text_[i];
    }
    if (odd)
        find("program-start", pct, 0,
             "between '%' and the end of block only a program number may stand, not '" + number + "' (§1.4, §1.6)");
    if (!number.empty()) p.number = number;
    pending_header_ = std::move(p);
    pending_from_label_ = from_label;
    state_ = State::pending;
}

// A '%' followed by no block: the first one on the tape is an empty program (lint says so); one after
// a program is the end of the record, the rewind stop.
void Loader::close_pending_empty() {
    if (pending_from_label_ || pending_header_.number) {
        start(std::move(pending_header_));
        state_ = State::after_end;
        return;
    }
    v_.record_end(pending_header_.start, false);
    state_ = State::after_end;
    after_end_started_ = false;
}

void Loader::start(Program p) {
    any_program_ = true;
    after_end_started_ = false;
    program_start_ = p.start;
    last_block_ordinal_ = 0;
    state_ = State::program;
    v_.program_start(p);
}

// "O1234" as written, from its 'O' (or ':') at i.
std::string Loader::program_number(std::size_t i, std::size_t e) const {
    std::size_t digits = i + 1;
    while (digits < e && is_digit(text_[digits])) ++digits;
    return std::string(text_.substr(i, digits - i));
}

// A program without '%' that starts with its "O1234" at i.
void Loader::start_numbered(std::size_t i, std::size_t e) {
    Program p;
    p.start = at(i);
    p.percent = false;
    p.number = program_number(i, e);
    p.numbered_by_block = true;
    start(std::move(p));
}

// Fanuc: "O1234" (or ":1234") at a block's start is a program number, and so a program's start.
bool Loader::program_number_at(std::size_t i, std::size_t e) const {
    if (!rules_->o_program_number || i + 1 >= e) return false;
    return (text_[i] == 'O' || text_[i] == ':') && is_digit(text_[i + 1]);
}

void Loader::unterminated() {
    bool blocks = last_block_ordinal_ != 0;
    std::string ends = rules_->dialect == Dialect::fanuc      ? "M02, M30 or M99"
                       : rules_->dialect == Dialect::linuxcnc ? "M2, M30 or a closing '%'"
                                                              : "M02 or M30 (§1.9)";
    v_.finding(program_finding("program-end", blocks ? last_block_where_ : program_start_, last_block_ordinal_,
                               "the program does not end with " + ends));
    state_ = State::after_end;
}

// Fanuc's ';' ends a block as manuals print it, so one line may hold several.
void Loader::blocks_in_line(std::size_t i, std::size_t e) {
    while ((i = skip_blanks(i, e)) < e) {
        if (state_ == State::after_end) {
            after_end_started_ = true;
            v_.after_end(text_.substr(i, e - i), at(i));
            return;
        }
        i = block(i, e);
    }
}

// Where the block starting at i ends: the end of the line, or Fanuc's ';' outside comments.
std::size_t Loader::block_end(std::size_t i, std::size_t e) const {
    if (!rules_->semicolon_ends_block) return e;
    bool in_comment = false;
    for (; i < e; ++i) {
        char c = text_[i];
        in_comment = c == '(' ? true : (c == ')' ? false : in_comment);
        if (c == ';' && !in_comment) return i;
    }
    return e;
}

// A macro statement runs to its block's end, a comment or (LinuxCNC) a ';' comment, outside [ ].
std::size_t Loader::statement_end(std::size_t i, std::size_t e) const {
    int depth = 0;
    for (; i < e; ++i) {
        char c = text_[i];
        if (c == '[') ++depth;
        if (c == ']' && depth) --depth;
        if (depth == 0 && (c == '(' || c == ';')) return i;
    }
    return e;
}

Word& Loader::next_word() {
    if (words_used_ == blk_.words.size()) blk_.words.emplace_back();
    return blk_.words[words_used_++];
}

std::size_t Loader::block(std::size_t i, std::size_t e) {
    std::size_t end = block_end(i, e), start_at = i;
    Block& blk = blk_;
    words_used_ = comments_used_ = 0;
    blk.statements.clear();
    blk.where = at(i);
    blk.ordinal = ++ordinal_;
    blk.skip = blk.main = blk.ends = false;
    blk.skip_level = 0;
    blk.number.reset();
    last_line_was_block_ = true;
    if (text_[i] == '/') {
        blk.skip = true;
        ++i;
        if (rules_->skip_levels && i < end && text_[i] >= '1' && text_[i] <= '9') blk.skip_level = text_[i++] - '0';
        i = skip_blanks(i, end);
    }
    blk.damaged = !frame_of_.empty() && text_.substr(i, end - i).find(bad_frame_marker) != std::string_view::npos;
    if (i < end && text_[i] == ':' && program_number_at(i, end)) {  // Fanuc's ':1234' is O1234
        word(i, end, &i, blk.ordinal, next_word());
    } else if (i < end && (text_[i] == 'N' || (rules_->lowercase && text_[i] == 'n') ||
                           (text_[i] == ':' && rules_->main_blocks))) {
        blk.main = text_[i] == ':';
        blk.number.emplace();
        word(i, end, &i, blk.ordinal, *blk.number);
    }
    // A comment whose '(' was lost reads as words up to its ')': one finding for all of it.
    if (std::size_t close = stray_close(i, end); close != std::string_view::npos)
        i = flagged(skip_blanks(i, end), end, close + 1,
                    "is taken as a comment whose '(' is missing: ')' closes no comment", "unexpected-character");
    while ((i = skip_blanks(i, end)) < end) {
        char c = text_[i];
        bool next_letter = i + 1 < end && is_letter(text_[i + 1]);
        if (c == '(') {
            i = comment(i, end);
        } else if (c == ';' && rules_->semicolon_comment) {
            if (comments_used_ == blk.comments.size()) blk.comments.emplace_back();
            Comment& k = blk.comments[comments_used_++];
            k.text.assign(text_.substr(i + 1, end - i - 1));
            k.where = at(i);
            k.semicolon = true;
            i = end;
        } else if (c == '#') {
            if (rules_->macro_b || rules_->o_words)
                i = assignment(i, end);
            else
                i = flagged(i, end, statement_end(i, end),
                            "is a macro statement, which ГОСТ 20999-83 programs do not have (try --dialect fanuc)");
        } else if (rules_->o_words && (c == 'o' || c == 'O') && i + 1 < end &&
                   (is_digit(text_[i + 1]) || text_[i + 1] == '<')) {
            i = o_word(i, end);
        } else if (is_letter(c) && next_letter) {
            std::string name = macro::name_at(text_, i);
            if (rules_->macro_b && listed(name, macro_keywords) && (is_upper(c) || rules_->lowercase))
                i = macro_statement(i, end, name);
            else if (listed(name, macro_keywords) && !rules_->macro_b)
                i = flagged(i, end, statement_end(i, end),
                            "is a Custom Macro B statement, which this dialect does not have (try --dialect fanuc)");
            else
                i = flagged(i, end,
                            i + name.size() + macro::value_length(text_.substr(0, end), i + name.size(), linuxcnc_),
                            "is no word: an address is one letter followed by its value");
        } else if (c == ',' && rules_->corner_words && i + 1 < end && (text_[i + 1] == 'C' || text_[i + 1] == 'R')) {
            Word& w = next_word();  // ",C1." chamfer, ",R2." corner: a word of its own, not the C axis or R
            Location comma = at(i);
            word(i + 1, end, &i, blk.ordinal, w);
            w.text.insert(0, 1, ',');
            w.address = ',';
            w.where = comma;
        } else if (is_upper(c) || (is_lower(c) && rules_->lowercase)) {
            word(i, end, &i, blk.ordinal, next_word());
        } else if (is_lower(c)) {
            Word& w = next_word();
            word(i, end, &i, blk.ordinal, w);
            w.known = false;
            find("unknown-word", w.where.offset - base_, blk.ordinal,
                 "'" + w.text + "': lowercase letters are no addresses in " +
                     std::string(rules_->dialect == Dialect::gost ? "ГОСТ 20999-83 programs (table 1)"
                                                                  : "Fanuc programs") +
                     " (try --dialect linuxcnc)");
        } else {
            i = unexpected(i, end, blk.ordinal);
        }
    }
    blk.words.resize(words_used_);
    blk.comments.resize(comments_used_);
    blk.source.assign(trim_right(text_.substr(start_at, end - start_at)));
    blk.ends = holds_end_code(blk, rules_->program_ends);
    last_block_where_ = blk.where;
    last_block_ordinal_ = blk.ordinal;
    v_.block(blk);
    if (blk.ends) state_ = State::after_end;
    return end < e ? end + 1 : e;
}

// A word the dialect does not know, kept as written from i: the next word of the block.
Word& Loader::flagged_word(std::size_t i, std::string_view text) {
    Word& w = next_word();
    w.address = text_[i];
    w.where = at(i);
    w.sign = 0;
    w.point = -1;
    w.macro = false;
    w.known = false;
    w.text.assign(text);
    return w;
}

// The first ')' outside any comment from i to e, or npos.
std::size_t Loader::stray_close(std::size_t i, std::size_t e) const {
    bool in_comment = false;
    for (; i < e; ++i) {
        if (text_[i] == '(') in_comment = true;
        if (text_[i] == ')') {
            if (!in_comment) return i;
            in_comment = false;
        }
        if (text_[i] == ';' && !in_comment && (rules_->semicolon_comment || rules_->semicolon_ends_block)) break;
    }
    return std::string_view::npos;
}

// Something the dialect does not know, kept as one flagged word from i to to, reported once.
std::size_t Loader::flagged(std::size_t i, std::size_t e, std::size_t to, std::string message, std::string_view rule) {
    to = std::min(std::max(to, i + 1), e);
    Word& w = flagged_word(i, trim_right(text_.substr(i, to - i)));
    std::string_view span = w.text;
    find(rule, i, blk_.ordinal, "'" + std::string(span) + "' " + std::move(message));
    return to;
}

// Address (or ':'), sign, digits and point, spaces allowed between; i at the address.
// Scans first, then copies whole runs: this is the loader's hot loop.
void Loader::word(std::size_t i, std::size_t e, std::size_t* next, std::uint64_t block_no, Word& w) {
    w.address = rules_->lowercase ? upper(text_[i]) : text_[i];
    w.where = at(i);
    w.sign = 0;
    w.point = -1;
    w.macro = false;
    w.known = true;
    if (rules_->macro_b || rules_->o_words) {
        std::size_t v = skip_blanks(i + 1, e);
        if (v < e && (text_[v] == '+' || text_[v] == '-')) v = skip_blanks(v + 1, e);
        if (v < e && (text_[v] == '#' || text_[v] == '[' || (linuxcnc_ && is_letter(text_[v])))) {
            std::size_t n = macro::value_length(text_.substr(0, e), i + 1, linuxcnc_);
            if (n) {
                w.macro = true;
                w.text.clear();
                for (char c : text_.substr(i, n + 1))
                    if (!is_blank(c)) w.text += c;
                auto s = text_.substr(i + 1, n);
                auto sign = s.find_first_not_of(" \t\r");
                if (sign != std::string_view::npos && (s[sign] == '+' || s[sign] == '-')) w.sign = s[sign];
                if (auto problem = macro::check_expression(
                        s.substr(sign == std::string_view::npos ? 0 : sign + (w.sign != 0)), linuxcnc_))
                    macro_problem(i, "the value of " + w.text + ": " + *problem);
                *next = i + 1 + n;
                return;
            }
        }
    }
    int points = 0, digits = 0;
    std::size_t j = i + 1, end = j, first_blank = std::string_view::npos;
    for (; j < e; ++j) {
        char c = text_[j];
        CharClass k = char_class[static_cast<unsigned char>(c)];
        if (k == CharClass::digit)
            ++digits;
        else if (k == CharClass::point) {
            if (++points == 1) w.point = digits;
        } else if (k == CharClass::sign && !w.sign && digits == 0 && points == 0)
            w.sign = c;
        else if (k == CharClass::blank) {
            if (first_blank == std::string_view::npos) first_blank = j;
            continue;
        } else
            break;
        end = j + 1;
    }
    *next = j;
    std::string_view span = text_.substr(i, end - i);
    if (first_blank >= end) {
        w.text.resize(span.size());  // within the reused capacity: no allocation, one copy
        std::memcpy(w.text.data(), span.data(), span.size());
    } else {
        w.text.clear();
        for (char c : span)
            if (!is_blank(c)) w.text += c;
    }
    if (is_lower(text_[i]) && !rules_->lowercase) return;  // flagged as a whole by the caller
    if (digits == 0) find("no-digits", i, block_no, "the word " + w.text + " has no digits (§3.1.1)");
    if (points > 1)
        find("two-points", i, block_no, "the word " + w.text + " has " + std::to_string(points) + " decimal points");
}

void Loader::macro_problem(std::size_t i, std::string message) {
    find("macro-syntax", i, blk_.ordinal, std::move(message));
}

Statement& Loader::add_statement(Statement::Kind kind, std::size_t from, std::size_t to) {
    Statement& s = blk_.statements.emplace_back();
    s.kind = kind;
    s.text.assign(trim_right(text_.substr(from, to - from)));
    s.where = at(from);
    return s;
}

// The digits at i (blanks before them skipped), moving i past them; nullopt when none stand there.
std::optional<long long> Loader::number_after(std::size_t& i, std::size_t end) const {
    i = skip_blanks(i, end);
    std::size_t j = i;
    long long v = 0;
    while (j < end && is_digit(text_[j]) && j - i < 18) v = v * 10 + (text_[j++] - '0');
    if (j == i) return std::nullopt;
    i = j;
    return v;
}

// Fanuc Custom Macro B: IF [..] GOTO n | IF [..] THEN ..., GOTO n, WHILE [..] DO m, DO m, END m, and
// the output statements. Each statement is one; its problems are one finding.
std::size_t Loader::macro_statement(std::size_t i, std::size_t e, const std::string& keyword) {
    using K = Statement::Kind;
    std::size_t end = statement_end(i, e), k = i + keyword.size();
    auto condition = [&](const char* what) -> bool {
        k = skip_blanks(k, end);
        if (k >= end || text_[k] != '[') {
            macro_problem(i, std::string(what) + " needs its condition in [ ]");
            return false;
        }
        std::size_t n = macro::group_length(text_.substr(0, end), k);
        if (n == std::string_view::npos) {
            macro_problem(k, "'[' is not closed with ']'");
            return false;
        }
        if (auto problem = macro::check_expression(text_.substr(k, n), false)) {
            macro_problem(k, std::string(what) + " [" + std::string(text_.substr(k + 1, n - 2)) + "]: " + *problem);
            return false;
        }
        k = skip_blanks(k + n, end);
        return true;
    };
    auto loop_number = [&](Statement& s, const char* what) {
        s.number = number_after(k, end);
        if (!s.number || *s.number < 1 || *s.number > 3)
            macro_problem(i, std::string(what) + " needs a loop number 1, 2 or 3");
    };
    auto target = [&](Statement& s) {
        std::size_t before = k;
        s.number = number_after(k, end);
        if (!s.number) {
            std::size_t n = macro::value_length(text_.substr(0, end), k, false);
            if (n == 0) macro_problem(before, "GOTO needs the number of the block to go to");
            k += n;
        }
    };
    if (keyword == "IF") {
        Statement& s = add_statement(K::if_goto, i, end);
        if (!condition("IF")) return end;
        std::string next = macro::name_at(text_, k);
        if (next == "GOTO") {
            k += 4;
            target(s);
        } else if (next == "THEN") {
            s.kind = K::if_then;
            k = skip_blanks(k + 4, end);
            if (k >= end || text_[k] != '#')
                macro_problem(k, "IF [...] THEN needs an assignment after THEN");
            else {
                std::size_t statements = blk_.statements.size();
                assignment(k, end);
                blk_.statements.resize(statements);  // the assignment is part of the IF
            }
            return end;
        } else {
            macro_problem(i, "IF [...] must be followed by GOTO n or THEN");
            return end;
        }
    } else if (keyword == "GOTO") {
        Statement& s = add_statement(K::go_to, i, end);
        target(s);
    } else if (keyword == "WHILE") {
        Statement& s = add_statement(K::while_do, i, end);
        if (!condition("WHILE")) return end;
        if (macro::name_at(text_, k) != "DO") {
            macro_problem(i, "WHILE [...] must be followed by DO m");
            return end;
        }
        k += 2;
        loop_number(s, "DO");
    } else if (keyword == "DO" || keyword == "END") {
        Statement& s = add_statement(keyword == "DO" ? K::loop_do : K::loop_end, i, end);
        loop_number(s, keyword.c_str());
    } else {  // POPEN PCLOS DPRNT BPRNT
        Statement& s = add_statement(K::output, i, end);
        (void)s;
        if (keyword == "DPRNT" || keyword == "BPRNT") {
            k = skip_blanks(k, end);
            if (k >= end || text_[k] != '[' || macro::group_length(text_.substr(0, end), k) == std::string_view::npos)
                macro_problem(i, keyword + " needs its output in [ ]");
        }
        return end;
    }
    if (skip_blanks(k, end) < end)
        macro_problem(skip_blanks(k, end),
                      "'" + std::string(trim_right(text_.substr(skip_blanks(k, end), end - skip_blanks(k, end)))) +
                          "' after " + keyword + " has no meaning");
    return end;
}

// "#100 = expression": Fanuc takes the rest of the block; LinuxCNC one value, then more of the block.
std::size_t Loader::assignment(std::size_t i, std::size_t e) {
    std::size_t end = statement_end(i, e);
    std::size_t n = macro::reference_length(text_.substr(0, end), i, linuxcnc_);
    std::size_t eq = skip_blanks(i + (n ? n : 1), end);
    if (n == 0 || eq >= end || text_[eq] != '=') {
        Statement& s = add_statement(Statement::Kind::assignment, i, end);
        macro_problem(i, "'" + s.text + "': a variable is given a value with '#n = value'");
        return end;
    }
    if (auto problem = macro::check_expression(text_.substr(i, n), linuxcnc_)) macro_problem(i, *problem);
    std::size_t value = skip_blanks(eq + 1, end), value_end = end;
    if (linuxcnc_) {
        std::size_t len = macro::value_length(text_.substr(0, end), value, true);
        value_end = len ? value + len : value;
    }
    add_statement(Statement::Kind::assignment, i, value_end);
    std::string_view rhs = trim_right(text_.substr(value, value_end - value));
    if (rhs.empty())
        macro_problem(i, "the assignment to " + std::string(text_.substr(i, n)) + " has no value");
    else if (auto problem = macro::check_expression(rhs, linuxcnc_))
        macro_problem(value, "the value of " + std::string(text_.substr(i, n)) + ": " + *problem);
    return value_end;
}

// LinuxCNC o-words: "o100 sub", "o<probe> call [1] [2]", "o101 if [#1 GT 0]", ...
std::size_t Loader::o_word(std::size_t i, std::size_t e) {
    std::size_t end = statement_end(i, e), k = i + 1;
    Statement& s = add_statement(Statement::Kind::o_word, i, end);
    if (text_[k] == '<') {
        auto close = text_.find('>', k);
        if (close == std::string_view::npos || close >= end) {
            macro_problem(i, "the o-word name '<' is not closed with '>'");
            return end;
        }
        k = close + 1;
    } else {
        while (k < end && is_digit(text_[k])) ++k;
    }
    s.label.clear();
    for (char c : text_.substr(i + 1, k - i - 1)) s.label += is_upper(c) ? static_cast<char>(c - 'A' + 'a') : c;
    k = skip_blanks(k, end);
    std::string keyword = macro::name_at(text_, k);
    if (!listed(keyword, o_keywords)) {
        macro_problem(k, keyword.empty() ? "the o-word " + s.text + " has no keyword (sub, call, if, while, ...)"
                                         : "'" + keyword + "' is no o-word keyword");
        return end;
    }
    for (char c : keyword) s.keyword += static_cast<char>(c - 'A' + 'a');
    k = skip_blanks(k + keyword.size(), end);
    bool needs_condition = keyword == "IF" || keyword == "ELSEIF" || keyword == "WHILE" || keyword == "REPEAT";
    if (needs_condition && (k >= end || text_[k] != '['))
        macro_problem(i, "o" + s.label + " " + s.keyword + " needs its condition in [ ]");
    while (k < end) {  // arguments and conditions: [ ] groups
        if (text_[k] != '[') {
            macro_problem(k, "'" + std::string(trim_right(text_.substr(k, end - k))) + "' after o" + s.label + " " +
                                 s.keyword + " has no meaning");
            break;
        }
        std::size_t n = macro::group_length(text_.substr(0, end), k);
        if (n == std::string_view::npos) {
            macro_problem(k, "'[' is not closed with ']'");
            break;
        }
        if (auto problem = macro::check_expression(text_.substr(k, n), true)) {
            macro_problem(k, *problem);
            break;
        }
        k = skip_blanks(k + n, end);
    }
    return end;
}

std::size_t Loader::comment(std::size_t open, std::size_t e) {
    auto close = text_.find(')', open);
    bool closed = close != std::string_view::npos && close < e;
    std::size_t end = closed ? close : e;
    if (comments_used_ == blk_.comments.size()) blk_.comments.emplace_back();
    Comment& c = blk_.comments[comments_used_++];
    c.text.assign(text_.substr(open + 1, end - open - 1));
    c.where = at(open);
    c.semicolon = false;
    for (std::size_t k = open + 1; k < end; ++k)
        if (text_[k] == '%' || text_[k] == ':')
            find("comment-forbidden-char", k, blk_.ordinal,
                 std::string("'") + text_[k] + "' must not stand inside a comment (§1.5)");
    if (!closed)
        find("unclosed-comment", open, blk_.ordinal, "the comment is not closed with ')' before the end of block");
    return closed ? close + 1 : e;
}

// One finding for a run of characters that belong nowhere, or for a '/', ':' or '%' out of place;
// the run is kept as a flagged word, so that nothing read is dropped.
std::size_t Loader::unexpected(std::size_t i, std::size_t e, std::uint64_t block_no) {
    char c = text_[i];
    std::size_t j = i + 1;
    std::string message;
    std::string_view rule = "unexpected-character";
    if (c == '/' || (c == ':' && rules_->main_blocks)) {
        while (j < e && is_digit(text_[j])) ++j;  // its number ("/2", ":20") belongs to the one finding
        rule = c == '/' ? "skip-position" : "main-position";
        message = c == '/' ? "'/' (block skip) may stand only at the start of a block, before N or ':' (§2.7)"
                           : "':' (main block) may stand only at the start of a block, in place of N (§2.6)";
    } else if (c == '%') {
        rule = "percent-in-block";
        message = "'%' (program start) inside a block";
    } else {
        j = i;
        while (j < e && !is_blank(text_[j]) && !is_letter(text_[j]) && text_[j] != '(' && text_[j] != '#' &&
               text_[j] != ';' && text_[j] != '%' && text_[j] != '/')
            j += utf8::length(text_, j);
        j = std::min(std::max(j, i + 1), e);
    }
    Word& w = flagged_word(i, text_.substr(i, j - i));
    // A bad frame read past (decode --keep-going) stands as U+FFFD; on a tape the codec reported it.
    if (!frame_of_.empty() && w.text.starts_with(bad_frame_marker)) return j;
    if (message.empty())
        message = "'" + w.text + "' is no part of an NC program outside comments" +
                  (rules_->dialect == Dialect::gost ? " (ГОСТ 20999-83 tables 1-3)" : "") + look_alike_hint(w.text);
    find(rule, i, block_no, std::move(message));
    return j;
}

}  // namespace tape
