// The loader's second stage: lines become the label, programs (started by '%', an O number, or their
// first block), the text after a program's end, and the end of the record (ГОСТ 20999-83 §1.4-§1.9).
#include <tuple>
#include <utility>

#include "program/loader/loader.hpp"

namespace tape {

using namespace loading;

void Loader::line(std::size_t b, std::size_t e, bool has_lf) {
    std::size_t first = skip_blanks(b, e);
    bool blank = first >= e;
    last_line_was_block_ = false;
    std::string_view whole = text_.substr(b, e - b + (has_lf ? 1 : 0));
    if (state_ == State::label) {
        label_line(b, first, e, whole);
        return;
    }
    if (state_ == State::pending && header_comment(b, first, e, whole)) return;
    if (!blank && text_[first] == '%') {
        if (state_ == State::pending && !held_.empty()) start_pending();
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
            start_pending();
            blocks_in_line(first, e);
            return;
        case State::after_end:
            if (!blank && program_number_at(first, e)) {
                start_numbered(first, e);
                blocks_in_line(first, e);
                return;
            }
            if (!blank && local_subprograms_ && !after_end_started_ && text_[first] == 'N' && first + 1 < e &&
                is_digit(text_[first + 1])) {  // Haas: M97 Pn calls the block Nn after M30, up to its M99
                state_ = State::program;
                blocks_in_line(first, e);
                return;
            }
            after_end_line(b, blank, whole);
            return;
        case State::record_ended:  // after the end of record nothing is read
            after_end_line(b, blank, whole);
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

// Before the first program: label, a '%', or (where the dialect needs no '%') the program itself. Where
// it needs none, the lines before the first '%' are held until it comes: label (a comment, a part name,
// set-up notes) unless they end a program, which that '%' then closes (LinuxCNC's closing '%').
void Loader::label_line(std::size_t b, std::size_t first, std::size_t e, std::string_view whole) {
    bool blank = first >= e;
    auto pct = rules_->needs_percent ? text_.find('%', b) : (blank || text_[first] != '%' ? e : first);
    if (pct != std::string_view::npos && pct < e) {
        if (!held_.empty()) release_leader(held_ends_program());
        leader_open_ = false;
        if (state_ == State::label && pct > b) v_.label(text_.substr(b, pct - b));
        percent_line(b, pct, e);
    } else if (leader_open_ && !rules_->needs_percent) {
        hold(b, whole);
        if (held_.size() >= dialect_sample_bytes) release_leader(true);  // too long for a label: the program
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
}

// Fanuc: comment lines between a '%' and the O number are held, so that the O number still names the
// program they stand in (and no program of comments alone is made before it).
bool Loader::header_comment(std::size_t b, std::size_t first, std::size_t e, std::string_view whole) {
    if (!rules_->o_program_number || pending_header_.number || held_.size() >= dialect_sample_bytes) return false;
    if (first >= e ? held_.empty() : !comment_only(first, e)) return false;
    hold(b, whole);
    return true;
}

// Nothing but comments (and Fanuc's ';') from i to e.
bool Loader::comment_only(std::size_t i, std::size_t e) const {
    while ((i = skip_blanks(i, e)) < e) {
        if (text_[i] == ';' && rules_->semicolon_comment) return true;
        if (text_[i] == ';' && rules_->semicolon_ends_block) {
            ++i;
            continue;
        }
        auto close = text_.find(')', i);
        if (text_[i] != '(' || close == std::string_view::npos || close >= e) return false;
        i = close + 1;
    }
    return true;
}

void Loader::hold(std::size_t b, std::string_view whole) {
    if (held_.empty()) {
        held_base_ = base_ + b;
        held_line_ = line_no_ - 1;
    }
    held_ += whole;
    if (!frame_of_.empty()) {
        auto from = frame_of_.begin() + static_cast<std::ptrdiff_t>(b);
        held_frames_.insert(held_frames_.end(), from, from + static_cast<std::ptrdiff_t>(whole.size()));
    }
}

// The held text before the first '%' read on its own: does a block in it end a program?
bool Loader::held_ends_program() const {
    struct Ends : ProgramVisitor {
        bool ended = false;
        void block(const Block& b) override { ended |= b.ends; }
    } seen;
    Loader trial(seen, LoadOptions{rules_->dialect, false});
    trial.feed(held_, {});
    trial.finish();
    return seen.ended;
}

// The held text before the first '%' is label, or is read as the program it is.
void Loader::release_leader(bool as_program) {
    leader_open_ = false;
    if (as_program) {
        replay_held();
        return;
    }
    v_.label(held_);
    held_.clear();
    held_frames_.clear();
}

// The program a '%' opened starts, with the comment lines held after the '%'.
void Loader::start_pending() {
    start(std::move(pending_header_));
    if (!held_.empty()) replay_held();
}

// Loads the held lines at their own places in the text, then goes on where it was.
void Loader::replay_held() {
    std::string held = std::move(held_);
    std::vector<std::uint64_t> frames = std::move(held_frames_);
    held_.clear();
    held_frames_.clear();
    auto saved = std::tuple(text_, frame_of_, base_, line_no_, line_start_, line_end_, line_ascii_, line_semicolon_,
                            line_close_, column_offset_, column_);
    base_ = held_base_;
    line_no_ = held_line_;
    run(held, frames);
    std::tie(text_, frame_of_, base_, line_no_, line_start_, line_end_, line_ascii_, line_semicolon_, line_close_,
             column_offset_, column_) = saved;
}

// Text after a program's end or the end of the record: blank lines count once text has come.
void Loader::after_end_line(std::size_t b, bool blank, std::string_view whole) {
    if (!blank || after_end_started_) {
        after_end_started_ = true;
        v_.after_end(whole, at(b));
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
    if (program_number_at(i, e)) {  // Fanuc's "%O1200(TOKARKA)": the program's first block on the '%' line
        p.number = program_number(i, e);
        p.numbered_by_block = true;
        start(std::move(p));
        blocks_in_line(i, e);
        return;
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
    after_end_started_ = last_block_stops_ = local_subprograms_ = false;
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

// A program that ends without its end code. Fanuc's that stops on a #3000 alarm in its last block and
// LinuxCNC's subroutine file (o<name> sub ... endsub, called by name) have ended all the same.
void Loader::unterminated() {
    if (last_block_stops_) {
        state_ = State::after_end;
        return;
    }
    bool blocks = last_block_ordinal_ != 0;
    std::string ends = rules_->dialect == Dialect::fanuc      ? "M02, M30 or M99"
                       : rules_->dialect == Dialect::linuxcnc ? "M2, M30 or a closing '%'"
                                                              : "M02 or M30 (§1.9)";
    report(program_finding("program-end", blocks ? last_block_where_ : program_start_, last_block_ordinal_,
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

}  // namespace tape
