// Loader: characters -> label, programs, blocks, words (ГОСТ 20999-83 §1-§3).
// One pass over the text, a line (block) at a time; problems become findings, never exceptions.
#include <algorithm>
#include <cstring>

#include "tape/program.hpp"
#include "utf8.hpp"

namespace tape {

std::string_view severity_name(Severity s) {
    switch (s) {
    case Severity::info: return "info";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
    }
    return "?";
}

std::optional<long long> Word::integer() const {
    if (has_point() || digits.empty() || digits.size() > 18) return std::nullopt;
    long long v = 0;
    for (char d : digits) v = v * 10 + (d - '0');
    return sign == '-' ? -v : v;
}

bool Block::ends_program() const {
    return std::any_of(words.begin(), words.end(), [](const Word& w) {
        auto v = w.integer();
        return w.address == 'M' && v && (*v == 2 || *v == 30);
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
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_address(char c) { return c >= 'A' && c <= 'Z'; }

class Loader {
public:
    explicit Loader(LoadedTape& t) : t_(t), text_(t.text) {}

    void run() {
        std::size_t b = 0;
        while (b < text_.size()) {
            auto nl = text_.find('\n', b);
            std::size_t e = nl == std::string::npos ? text_.size() : nl;
            begin_line(b, e);
            line(b, e, nl != std::string::npos);
            b = e + 1;
        }
        if (!t_.programs.empty() && !t_.programs.back().ended) unterminated(t_.programs.back());
    }

private:
    enum class State { label, program, after_end };

    LoadedTape& t_;
    const std::string& text_;
    State state_ = State::label;
    std::uint64_t line_no_ = 0, ordinal_ = 0;
    std::size_t line_start_ = 0;
    bool line_ascii_ = true;

    void begin_line(std::size_t b, std::size_t e) {
        ++line_no_;
        line_start_ = b;
        line_ascii_ = std::none_of(text_.begin() + static_cast<std::ptrdiff_t>(b), text_.begin() + static_cast<std::ptrdiff_t>(e),
                                   [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
    }

    Location at(std::size_t offset) const {
        Location l;
        l.offset = offset;
        if (!t_.frame_of.empty()) l.frame = t_.frame_of[std::min(offset, t_.frame_of.size() - 1)] + 1;
        l.line = line_no_;
        l.column = offset - line_start_ + 1;
        if (!line_ascii_)
            l.column = 1 + static_cast<std::uint64_t>(std::count_if(text_.begin() + static_cast<std::ptrdiff_t>(line_start_),
                                                                    text_.begin() + static_cast<std::ptrdiff_t>(offset),
                                                                    [](char c) { return !utf8::is_continuation(c); }));
        return l;
    }

    void find(std::string_view rule, Severity s, std::size_t offset, std::uint64_t block, std::string message) {
        t_.findings.push_back(Finding{rule, s, at(offset), block, std::move(message)});
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
            if (pct == std::string::npos || pct >= e) {
                t_.label.append(text_, b, e - b);
                if (has_lf) t_.label += '\n';
                return;
            }
            t_.label.append(text_, b, pct - b);
            start_program(pct, e);
            return;
        }
        case State::after_end:
            if (first < e && text_[first] == '%') {
                start_program(first, e);
                return;
            }
            if (first < e || !t_.programs.back().after_end.empty()) {
                auto& p = t_.programs.back();
                if (!p.after_end_at) p.after_end_at = at(b);
                p.after_end.append(text_, b, e - b);
                if (has_lf) p.after_end += '\n';
            }
            return;
        case State::program:
            if (first < e && text_[first] == '%') {
                unterminated(t_.programs.back());
                start_program(first, e);
                return;
            }
            block(first, e);
            return;
        }
    }

    void unterminated(const Program& p) {
        t_.findings.push_back(Finding{"program-end", Severity::error,
                                      p.blocks.empty() ? p.start : p.blocks.back().where,
                                      p.blocks.empty() ? 0 : p.blocks.back().ordinal,
                                      "the program does not end with M02 or M30 (§1.9)"});
    }

    void start_program(std::size_t pct, std::size_t e) {
        Program p;
        p.start = at(pct);
        std::size_t i = skip_blanks(pct + 1, e);
        if (i < e && text_[i] == '%') {
            if (t_.programs.empty()) t_.physical_start = true;
            else find("program-start", Severity::error, i, 0, "'%%' marks the physical start of the tape only before the first program (§1.8)");
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
        t_.programs.push_back(std::move(p));
        state_ = State::program;
    }

    // Address (or ':'), sign, digits and point, spaces allowed between; i at the address.
    Word word(std::size_t i, std::size_t e, std::size_t* next, std::uint64_t block_no, bool report = true) {
        Word w;
        w.address = text_[i];
        w.where = at(i);
        w.text += text_[i];
        int points = 0;
        for (++i; i < e; ++i) {
            char c = text_[i];
            if (is_blank(c)) continue;
            if ((c == '+' || c == '-') && !w.sign && w.digits.empty() && points == 0) {
                w.sign = c;
            } else if (is_digit(c)) {
                w.digits += c;
            } else if (c == '.') {
                if (++points == 1) w.point = static_cast<int>(w.digits.size());
            } else {
                break;
            }
            w.text += c;
        }
        *next = i;
        if (!report) return w;
        if (w.digits.empty())
            find("no-digits", Severity::error, w.where.offset, block_no, "the word " + w.text + " has no digits (§3.1.1)");
        if (points > 1)
            find("two-points", Severity::error, w.where.offset, block_no, "the word " + w.text + " has " + std::to_string(points) + " decimal points");
        return w;
    }

    void block(std::size_t i, std::size_t e) {
        if (i >= e) return;  // an empty line is no block
        Block blk;
        blk.where = at(i);
        blk.ordinal = ++ordinal_;
        if (text_[i] == '/') {
            blk.skip = true;
            i = skip_blanks(i + 1, e);
        }
        if (i < e && (text_[i] == ':' || text_[i] == 'N')) {
            blk.main = text_[i] == ':';
            blk.number = word(i, e, &i, blk.ordinal);
        }
        while ((i = skip_blanks(i, e)) < e) {
            char c = text_[i];
            if (is_address(c)) {
                blk.words.push_back(word(i, e, &i, blk.ordinal));
            } else if (c == ':' || (c >= 'a' && c <= 'z')) {
                unexpected(i, e, blk.ordinal);
                word(i, e, &i, blk.ordinal, false);  // read past its digits; it is no word of this block
            } else if (c == '(') {
                i = comment(i, e, blk);
            } else {
                unexpected(i, e, blk.ordinal);
                i += utf8::length(text_, i);
            }
        }
        auto& p = t_.programs.back();
        p.blocks.push_back(std::move(blk));
        if (p.blocks.back().ends_program()) {
            p.ended = true;
            state_ = State::after_end;
        }
    }

    std::size_t comment(std::size_t open, std::size_t e, Block& blk) {
        auto close = text_.find(')', open);
        bool closed = close != std::string::npos && close < e;
        std::size_t end = closed ? close : e;
        Comment c{text_.substr(open + 1, end - open - 1), at(open)};
        for (std::size_t k = open + 1; k < end; ++k)
            if (text_[k] == '%' || text_[k] == ':')
                find("comment-forbidden-char", Severity::error, k, blk.ordinal,
                     std::string("'") + text_[k] + "' must not stand inside a comment (§1.5)");
        if (!closed) find("unclosed-comment", Severity::error, open, blk.ordinal, "the comment is not closed with ')' before the end of block");
        blk.comments.push_back(std::move(c));
        return closed ? close + 1 : e;
    }

    void unexpected(std::size_t i, std::size_t e, std::uint64_t block_no) {
        char c = text_[i];
        std::string shown(utf8::char_at(std::string_view(text_).substr(0, e), i));
        if (c == '/')
            find("skip-position", Severity::error, i, block_no, "'/' (block skip) may stand only at the start of a block, before N or ':' (§2.7)");
        else if (c == ':')
            find("main-position", Severity::error, i, block_no, "':' (main block) may stand only at the start of a block, in place of N (§2.6)");
        else if (c == '%')
            find("percent-in-block", Severity::error, i, block_no, "'%' (program start) inside a block");
        else if (c >= 'a' && c <= 'z')
            find("unexpected-character", Severity::error, i, block_no, "'" + shown + "' is no address: table 1 has the capital letters A-Z");
        else
            find("unexpected-character", Severity::error, i, block_no, "'" + shown + "' is no character of an NC program outside comments (tables 1-3)");
    }
};

}  // namespace

LoadedTape load(std::string text, std::vector<std::uint64_t> frame_of) {
    LoadedTape t;
    t.text = std::move(text);
    t.frame_of = std::move(frame_of);
    Loader(t).run();
    return t;
}

}  // namespace tape
