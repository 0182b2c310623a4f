// Loader: characters -> label, programs, blocks, words (ГОСТ 20999-83 §1-§3).
// One pass over the text, a line (block) at a time; problems become findings, never exceptions.
#include "tape/program.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "codec/swar.hpp"
#include "codec/utf8.hpp"

namespace tape {

Finding program_finding(std::string_view rule, Severity severity, const Location& where, std::uint64_t block,
                        std::string message) {
    Position at = where.position();
    if (block) at.block = block;
    return Finding{
        .code = Errc::bad_program, .where = at, .message = std::move(message), .rule = rule, .severity = severity};
}

std::string Word::digits() const {
    std::string d;
    for (char c : text)
        if (c >= '0' && c <= '9') d += c;
    return d;
}

std::optional<long long> Word::integer() const {
    if (has_point()) return std::nullopt;
    long long v = 0;
    int n = 0;
    for (char c : text) {
        if (c < '0' || c > '9') continue;
        if (++n > 18) return std::nullopt;
        v = v * 10 + (c - '0');
    }
    if (n == 0) return std::nullopt;
    return sign == '-' ? -v : v;
}

bool Block::ends_program() const {
    return std::any_of(words.begin(), words.end(), [](const Word& w) {
        if (w.address != 'M') return false;
        auto v = w.integer();
        return v && (*v == 2 || *v == 30);
    });
}

std::string Block::text() const {
    std::string out = skip ? "/" : "";
    auto add = [&](const std::string& piece) {
        if (!out.empty() && out != "/") out += ' ';
        out += piece;
    };
    if (number) add(number->text);
    for (const auto& w : words) add(w.text);
    for (const auto& c : comments) add("(" + c.text + ")");
    return out;
}

Location LoadedTape::locate(std::uint64_t offset) const {
    Location l;
    l.offset = offset;
    if (!frame_of.empty()) l.frame = frame_of[std::min<std::uint64_t>(offset, frame_of.size() - 1)] + 1;
    std::string_view before(text.data(), std::min<std::uint64_t>(offset, text.size()));
    l.line = 1 + static_cast<std::uint64_t>(std::count(before.begin(), before.end(), '\n'));
    auto line_start = before.rfind('\n');
    line_start = line_start == std::string_view::npos ? 0 : line_start + 1;
    l.column = 1;
    for (std::size_t i = line_start; i < before.size(); ++i) l.column += !utf8::is_continuation(before[i]);
    return l;
}

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// What a character can be inside a word, looked up once per character in the hot loop.
enum class CharClass : std::uint8_t { other, digit, point, sign, blank };
constexpr auto char_class = [] {
    std::array<CharClass, 256> t{};
    for (int c = '0'; c <= '9'; ++c) t[static_cast<std::size_t>(c)] = CharClass::digit;
    t['.'] = CharClass::point;
    t['+'] = t['-'] = CharClass::sign;
    t[' '] = t['\t'] = t['\r'] = CharClass::blank;
    return t;
}();
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_address(char c) { return c >= 'A' && c <= 'Z'; }

}  // namespace

// The loader behind ProgramLoader: one pass, a line (block) at a time.
class Loader {
public:
    explicit Loader(ProgramVisitor& v) : v_(v) {}

    // Whole lines are loaded as they come; the unfinished last one waits for the next piece.
    void feed(std::string_view text, std::span<const std::uint64_t> frame_of) {
        if (!frame_of.empty() && frame_of.size() != text.size()) frame_of = {};
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

    void finish() {
        if (!pending_.empty()) run(pending_, pending_frames_);
        pending_.clear();
        pending_frames_.clear();
        if (state_ != State::label && state_ != State::after_end) unterminated();
        v_.end(end_location());
    }

private:
    enum class State { label, program, after_end };

    std::string_view text_;                    // the lines being loaded now
    std::span<const std::uint64_t> frame_of_;  // their frames, or empty
    std::uint64_t base_ = 0;                   // offset of text_[0] from the start of the text
    bool ends_with_lf_ = false;                // of the text loaded so far: where its end is
    std::uint64_t last_line_chars_ = 0;
    std::optional<std::uint64_t> last_frame_{};
    std::string pending_;  // an unfinished line, and its frames
    std::vector<std::uint64_t> pending_frames_;
    ProgramVisitor& v_;
    State state_ = State::label;
    std::uint64_t line_no_ = 0, ordinal_ = 0;
    std::size_t line_start_ = 0;
    bool line_ascii_ = true;
    bool any_program_ = false;
    bool after_end_started_ = false;
    Location program_start_, last_block_where_;
    std::uint64_t last_block_ordinal_ = 0;
    Block blk_;  // reused: its vectors keep their capacity from block to block

    void keep(std::string_view text, std::span<const std::uint64_t> frame_of) {
        pending_ += text;
        pending_frames_.insert(pending_frames_.end(), frame_of.begin(), frame_of.end());
    }

    // Loads whole lines (the last may lack its LF only at the end of the text).
    void run(std::string_view text, std::span<const std::uint64_t> frame_of) {
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
    Location end_location() const {
        Location l;
        l.offset = base_;
        l.frame = last_frame_;
        l.line = ends_with_lf_ || line_no_ == 0 ? line_no_ + 1 : line_no_;
        l.column = ends_with_lf_ || line_no_ == 0 ? 1 : last_line_chars_ + 1;
        return l;
    }

    void begin_line(std::size_t b, std::size_t e) {
        ++line_no_;
        line_start_ = b;
        line_ascii_ = !swar::any_high_byte(text_.data() + b, e - b);
    }

    Location at(std::size_t offset) const {
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

    void find(std::string_view rule, Severity s, std::size_t offset, std::uint64_t block, std::string message) {
        v_.finding(program_finding(rule, s, at(offset), block, std::move(message)));
    }

    std::size_t skip_blanks(std::size_t i, std::size_t e) const {
        while (i < e && is_blank(text_[i])) ++i;
        return i;
    }

    void line(std::size_t b, std::size_t e, bool has_lf) {
        std::size_t first = skip_blanks(b, e);
        switch (state_) {
            case State::label: {
                auto pct = text_.find('%', b);
                if (pct == std::string_view::npos || pct >= e) {
                    v_.label(text_.substr(b, e - b + (has_lf ? 1 : 0)));
                    return;
                }
                if (pct > b) v_.label(text_.substr(b, pct - b));
                start_program(pct, e);
                return;
            }
            case State::after_end:
                if (first < e && text_[first] == '%') {
                    start_program(first, e);
                    return;
                }
                if (first < e || after_end_started_) {
                    after_end_started_ = true;
                    v_.after_end(text_.substr(b, e - b + (has_lf ? 1 : 0)), at(b));
                }
                return;
            case State::program:
                if (first < e && text_[first] == '%') {
                    unterminated();
                    start_program(first, e);
                    return;
                }
                block(first, e);
                return;
        }
    }

    void unterminated() {
        bool blocks = last_block_ordinal_ != 0;
        v_.finding(program_finding("program-end", Severity::error, blocks ? last_block_where_ : program_start_,
                                   last_block_ordinal_, "the program does not end with M02 or M30 (§1.9)"));
    }

    void start_program(std::size_t pct, std::size_t e) {
        Program p;
        p.start = at(pct);
        std::size_t i = skip_blanks(pct + 1, e);
        if (i < e && text_[i] == '%') {
            if (!any_program_)
                v_.physical_start();
            else
                find("program-start", Severity::error, i, 0,
                     "'%%' marks the physical start of the tape only before the first program (§1.8)");
            i = skip_blanks(i + 1, e);
        }
        std::string number;
        bool odd = false;
        for (; i < e; ++i) {
            if (is_blank(text_[i])) continue;
            odd |= !(is_digit(text_[i]) || is_address(text_[i]));
            number += text_[i];
        }
        if (odd)
            find("program-start", Severity::error, pct, 0,
                 "between '%' and the end of block only a program number may stand, not '" + number + "' (§1.4, §1.6)");
        if (!number.empty()) p.number = number;
        any_program_ = true;
        after_end_started_ = false;
        program_start_ = p.start;
        last_block_ordinal_ = 0;
        state_ = State::program;
        v_.program_start(p);
    }

    // Address (or ':'), sign, digits and point, spaces allowed between; i at the address.
    // Scans first, then copies whole runs: this is the loader's hot loop.
    void word(std::size_t i, std::size_t e, std::size_t* next, std::uint64_t block_no, Word& w, bool report = true) {
        w.address = text_[i];
        w.where = at(i);
        w.sign = 0;
        w.point = -1;
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
        if (!report) return;
        if (digits == 0)
            find("no-digits", Severity::error, i, block_no, "the word " + w.text + " has no digits (§3.1.1)");
        if (points > 1)
            find("two-points", Severity::error, i, block_no,
                 "the word " + w.text + " has " + std::to_string(points) + " decimal points");
    }

    // The next reused slot of blk_.words, grown only when a block has more words than any before.
    Word& next_word(std::size_t& used) {
        if (used == blk_.words.size()) blk_.words.emplace_back();
        return blk_.words[used++];
    }

    void block(std::size_t i, std::size_t e) {
        if (i >= e) return;  // an empty line is no block
        Block& blk = blk_;
        std::size_t used = 0, comments = 0;
        blk.where = at(i);
        blk.ordinal = ++ordinal_;
        blk.skip = blk.main = false;
        blk.number.reset();
        if (text_[i] == '/') {
            blk.skip = true;
            i = skip_blanks(i + 1, e);
        }
        if (i < e && (text_[i] == ':' || text_[i] == 'N')) {
            blk.main = text_[i] == ':';
            blk.number.emplace();
            word(i, e, &i, blk.ordinal, *blk.number);
        }
        Word scratch;
        while ((i = skip_blanks(i, e)) < e) {
            char c = text_[i];
            if (is_address(c)) {
                word(i, e, &i, blk.ordinal, next_word(used));
            } else if (c == ':' || (c >= 'a' && c <= 'z')) {
                unexpected(i, e, blk.ordinal);
                word(i, e, &i, blk.ordinal, scratch, false);  // read past its digits; it is no word of this block
            } else if (c == '(') {
                i = comment(i, e, comments);
            } else {
                unexpected(i, e, blk.ordinal);
                i += utf8::length(text_, i);
            }
        }
        blk.words.resize(used);
        blk.comments.resize(comments);
        last_block_where_ = blk.where;
        last_block_ordinal_ = blk.ordinal;
        v_.block(blk);
        if (blk.ends_program()) state_ = State::after_end;
    }

    std::size_t comment(std::size_t open, std::size_t e, std::size_t& used) {
        auto close = text_.find(')', open);
        bool closed = close != std::string_view::npos && close < e;
        std::size_t end = closed ? close : e;
        if (used == blk_.comments.size()) blk_.comments.emplace_back();
        Comment& c = blk_.comments[used++];
        c.text.assign(text_.substr(open + 1, end - open - 1));
        c.where = at(open);
        for (std::size_t k = open + 1; k < end; ++k)
            if (text_[k] == '%' || text_[k] == ':')
                find("comment-forbidden-char", Severity::error, k, blk_.ordinal,
                     std::string("'") + text_[k] + "' must not stand inside a comment (§1.5)");
        if (!closed)
            find("unclosed-comment", Severity::error, open, blk_.ordinal,
                 "the comment is not closed with ')' before the end of block");
        return closed ? close + 1 : e;
    }

    void unexpected(std::size_t i, std::size_t e, std::uint64_t block_no) {
        char c = text_[i];
        std::string shown(utf8::char_at(text_.substr(0, e), i));
        if (c == '/')
            find("skip-position", Severity::error, i, block_no,
                 "'/' (block skip) may stand only at the start of a block, before N or ':' (§2.7)");
        else if (c == ':')
            find("main-position", Severity::error, i, block_no,
                 "':' (main block) may stand only at the start of a block, in place of N (§2.6)");
        else if (c == '%')
            find("percent-in-block", Severity::error, i, block_no, "'%' (program start) inside a block");
        else if (c >= 'a' && c <= 'z')
            find("unexpected-character", Severity::error, i, block_no,
                 "'" + shown + "' is no address: table 1 has the capital letters A-Z");
        else
            find("unexpected-character", Severity::error, i, block_no,
                 "'" + shown + "' is no character of an NC program outside comments (tables 1-3)");
    }
};

namespace {

// load(): keeps everything the loader streams.
class Collector : public ProgramVisitor {
public:
    explicit Collector(LoadedTape& t) : t_(t) {}
    void label(std::string_view text) override { t_.label += text; }
    void program_start(const Program& header) override { t_.programs.push_back(header); }
    void block(const Block& b) override {
        Program& p = t_.programs.back();
        p.blocks.push_back(b);
        if (b.ends_program()) p.ended = true;
    }
    void after_end(std::string_view text, const Location& where) override {
        Program& p = t_.programs.back();
        if (!p.after_end_at) p.after_end_at = where;
        p.after_end += text;
    }
    void physical_start() override { t_.physical_start = true; }
    void finding(const Finding& f) override { t_.findings.push_back(f); }

private:
    LoadedTape& t_;
};

}  // namespace

ProgramLoader::ProgramLoader(ProgramVisitor& visitor) : loader_(std::make_unique<Loader>(visitor)) {}
ProgramLoader::~ProgramLoader() = default;
void ProgramLoader::feed(std::string_view text, std::span<const std::uint64_t> frame_of) {
    loader_->feed(text, frame_of);
}
void ProgramLoader::finish() { loader_->finish(); }

void load_each(std::string_view text, std::span<const std::uint64_t> frame_of, ProgramVisitor& visitor) {
    ProgramLoader loader(visitor);
    loader.feed(text, frame_of);
    loader.finish();
}

LoadedTape load(std::string text, std::vector<std::uint64_t> frame_of) {
    LoadedTape t;
    t.text = std::move(text);
    t.frame_of = std::move(frame_of);
    Collector collect(t);
    load_each(t.text, t.frame_of, collect);
    return t;
}

}  // namespace tape
