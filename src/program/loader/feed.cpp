// The loader's first stage: pieces of text, however they are cut, become whole lines with their
// positions (byte, frame, line, column); the dialect is chosen first when it is automatic.
#include <algorithm>
#include <utility>

#include "codec/swar.hpp"
#include "codec/utf8.hpp"
#include "program/loader/loader.hpp"
#include "tape/rules.hpp"

namespace tape {

using namespace loading;

Loader::Loader(ProgramVisitor& visitor, const LoadOptions& options)
    : v_(visitor), options_(options), leader_open_(options.leader) {
    if (options_.dialect != Dialect::automatic) choose(DialectChoice{options_.dialect, ""});
}

void Loader::choose(DialectChoice choice) {
    rules_ = &dialect_rules(choice.dialect);
    linuxcnc_ = choice.dialect == Dialect::linuxcnc;
    if (choice.close) {
        second_found_ = std::make_unique<SecondFindings>();
        second_ = std::make_unique<Loader>(*second_found_, LoadOptions{*choice.close, options_.leader});
    }
    v_.dialect(choice);
}

// Every finding of the loader: made only for the rules of the dialect, and, when two were close,
// only where the other reading makes it too.
void Loader::report(Finding f) {
    if (const Rule* r = find_rule(f.id()); r && !rule_applies(*r, rules_->dialect)) return;
    if (second_ && !second_found_->found.count({std::string(f.id()), f.where.byte.value_or(0)})) return;
    v_.finding(std::move(f));
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
    // Exactly dialect_sample_bytes may end inside a line: its end is known only with the next byte.
    if (sniff_.size() <= dialect_sample_bytes) return;
    choose(guess_dialect(sniff_));
    feed_lines(sniff_, sniff_frames_.size() == sniff_.size() ? std::span<const std::uint64_t>(sniff_frames_)
                                                             : std::span<const std::uint64_t>());
    sniff_ = {};
    sniff_frames_ = {};
}

// Whole lines are loaded as they come; the unfinished last one waits for the next piece. A second
// reading takes them first, so that what it finds is known when this one looks.
void Loader::feed_lines(std::string_view text, std::span<const std::uint64_t> frame_of) {
    if (second_) second_->feed(text, frame_of);
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
    if (second_) std::erase_if(second_found_->found, [&](const auto& f) { return f.second < base_; });
}

void Loader::finish() {
    if (!rules_) {
        choose(guess_dialect(sniff_));
        std::string held = std::move(sniff_);
        std::vector<std::uint64_t> frames = std::move(sniff_frames_);
        feed_lines(held, frames.size() == held.size() ? std::span<const std::uint64_t>(frames)
                                                      : std::span<const std::uint64_t>());
    }
    if (second_) second_->finish();
    if (!pending_.empty()) run(pending_, pending_frames_);
    // No '%' came: what was held before it is the program (a program that needs no '%'), and the
    // comments held after a last '%' start its program.
    if (state_ == State::label && !held_.empty()) release_leader(true);
    if (state_ == State::pending && !held_.empty()) start_pending();
    bool cut_in_block = !pending_.empty() && last_line_was_block_ && !pending_frames_.empty();
    pending_.clear();
    pending_frames_.clear();
    if (state_ == State::pending) close_pending_empty();
    if (cut_in_block) {  // one cause: the tape was cut or read short, so the program has no end either
        bool open = state_ == State::program;
        report(program_finding("incomplete-block", last_block_where_, last_block_ordinal_,
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
    line_start_ = column_offset_ = b;
    column_ = 1;
    line_end_ = e;
    swar::LineMarks marks = swar::line_marks(text_.data() + b, e - b);
    line_ascii_ = !marks.high;
    line_semicolon_ = marks.semicolon;
    line_close_ = marks.close;
}

// Columns count characters, not bytes: on a line that is not ASCII the count goes on from the last
// place asked for (forwards or back), so that a line's findings cost its length once, not once each.
// at()'s general case: a tape's frames, or a line with characters of more than one byte.
Location Loader::located(std::size_t offset) const {
    Location l;
    l.offset = base_ + offset;
    if (!frame_of_.empty()) l.frame = frame_of_[std::min(offset, frame_of_.size() - 1)] + 1;
    l.line = line_no_;
    l.column = offset - line_start_ + 1;
    if (line_ascii_) return l;
    auto characters = [&](std::size_t from, std::size_t to) {
        return static_cast<std::uint64_t>(std::count_if(text_.begin() + static_cast<std::ptrdiff_t>(from),
                                                        text_.begin() + static_cast<std::ptrdiff_t>(to),
                                                        [](char c) { return !utf8::is_continuation(c); }));
    };
    if (offset >= column_offset_)
        column_ += characters(column_offset_, offset);
    else
        column_ -= characters(offset, column_offset_);
    column_offset_ = offset;
    l.column = column_;
    return l;
}

// Findings of rules the dialect does not have are not made at all.
void Loader::find(std::string_view rule, std::size_t offset, std::uint64_t block, std::string message) {
    const Rule* r = find_rule(rule);
    if (r && !rule_applies(*r, rules_->dialect)) return;
    if (block && block == blk_.ordinal && blk_.damaged) return;  // the bad frame read past is the one cause
    report(program_finding(rule, at(offset), block, std::move(message)));
}

std::size_t Loader::skip_blanks(std::size_t i, std::size_t e) const {
    while (i < e && is_blank(text_[i])) ++i;
    return i;
}

}  // namespace tape
