// The loader's third stage: one block (кадр) of a line becomes its skip mark, number, words,
// comments and statements (ГОСТ 20999-83 §2); what belongs nowhere is kept as a flagged word and
// reported once.
#include <algorithm>
#include <array>
#include <cstring>
#include <utility>

#include "codec/utf8.hpp"
#include "program/loader/loader.hpp"
#include "program/macro.hpp"
#include "tape/decode.hpp"

namespace tape {

using namespace loading;

namespace {

constexpr std::array<std::string_view, 9> macro_keywords = {"IF",    "GOTO",  "WHILE", "DO",   "END",
                                                            "POPEN", "PCLOS", "DPRNT", "BPRNT"};

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

}  // namespace

// Where the block starting at i ends: the end of the line, or Fanuc's ';' outside comments.
std::size_t Loader::block_end(std::size_t i, std::size_t e) const {
    if (!rules_->semicolon_ends_block || (!line_semicolon_ && within_line(i, e)) || i >= e ||
        !std::memchr(text_.data() + i, ';', e - i))
        return e;
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
    i = block_head(i, end);
    // A comment whose '(' was lost reads as words up to its ')': one finding for all of it. Where no
    // dialect fits, ( ) may be no comment at all (Heidenhain's is ';'): nothing to say of a ')'.
    if (std::size_t close = stray_close(i, end); close != std::string_view::npos && rules_->dialect != Dialect::none)
        i = flagged(skip_blanks(i, end), end, close + 1,
                    "is taken as a comment whose '(' is missing: ')' closes no comment", "unexpected-character");
    if (i < end && after_semicolon(start_at) && is_letter(text_[i]) && i + 1 < end && is_letter(text_[i + 1]) &&
        !listed(macro::name_at(text_, i), macro_keywords))  // words after ';' on its line: a remark, one finding
        i = flagged(i, end, end,
                    "is text after ';', which ends the block: it reads as no block (a remark stands in ( ))");
    while ((i = skip_blanks(i, end)) < end) i = block_item(i, end);
    Block& blk = blk_;
    blk.words.resize(words_used_);
    blk.comments.resize(comments_used_);
    blk.source.assign(trim_right(text_.substr(start_at, end - start_at)));
    static constexpr int m97[] = {97};
    blk.ends = holds_end_code(blk, rules_->program_ends);
    last_block_stops_ = !blk.statements.empty() && stops_program(blk);
    local_subprograms_ |= rules_->dialect == Dialect::fanuc && holds_end_code(blk, m97);  // Haas's M97 P calls
    last_block_where_ = blk.where;
    last_block_ordinal_ = blk.ordinal;
    v_.block(blk);
    if (blk.ends) state_ = State::after_end;
    return end < e ? end + 1 : e;
}

// The block at i follows a ';' that ended the one before it on the same line (Fanuc).
bool Loader::after_semicolon(std::size_t i) const {
    while (i > line_start_ && is_blank(text_[i - 1])) --i;
    return i > line_start_ && text_[i - 1] == ';';
}

// A block no program goes on after, though it holds no end code: Fanuc's #3000 alarm, LinuxCNC's
// endsub closing a subroutine file.
bool Loader::stops_program(const Block& b) const {
    return std::any_of(b.statements.begin(), b.statements.end(), [&](const Statement& s) {
        return (rules_->macro_b && s.kind == Statement::Kind::assignment && s.text.starts_with("#3000")) ||
               (rules_->o_words && s.kind == Statement::Kind::o_word && s.keyword == "endsub");
    });
}

// The block's start: the reused Block emptied, then '/' (with its level) and the number. Returns
// where the words begin.
std::size_t Loader::block_head(std::size_t i, std::size_t end) {
    Block& blk = blk_;
    words_used_ = comments_used_ = 0;
    blk.statements.clear();
    locate(i, blk.where);
    blk.ordinal = ++ordinal_;
    blk.skip = blk.main = blk.ends = false;
    blk.skip_level = 0;
    bool numbered = false;  // the number's Word kept from the block before, its string's capacity with it
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
        if (!blk.number) blk.number.emplace();
        word(i, end, &i, blk.ordinal, *blk.number);
        numbered = true;
    }
    if (!numbered) blk.number.reset();
    return i;
}

// One item of a block at i: a comment, a statement, a word, or what belongs nowhere. Returns where
// the next one may start.
std::size_t Loader::block_item(std::size_t i, std::size_t end) {
    char c = text_[i];
    if (c == '(') return comment(i, end);
    if (linuxcnc_ && (c == '@' || c == '^')) {  // polar words: @ the distance, ^ the angle
        word(i, end, &i, blk_.ordinal, next_word());
        return i;
    }
    if (linuxcnc_ && words_used_ == 0 && comments_used_ == 0 && !blk_.number && (c == '$' || c == '?' || c == '~'))
        return flagged(i, end, statement_end(i, end),
                       "is a GRBL console command, not G-code: GRBL runs it when the file is streamed, LinuxCNC "
                       "stops on it",
                       "console-command");
    if (std::size_t k = c == ';' ? skip_blanks(i + 1, end) : end; c == ';' && !rules_->semicolon_comment &&
                                                                  !rules_->semicolon_ends_block && k + 1 < end &&
                                                                  is_letter(text_[k]) && is_letter(text_[k + 1]))
        return flagged(i, end, end,
                       "is a ';' comment, which ГОСТ 20999-83 programs do not have: a comment stands in ( ) (§1.5)",
                       "unexpected-character");
    if (c == ';' && rules_->semicolon_comment) {
        if (comments_used_ == blk_.comments.size()) blk_.comments.emplace_back();
        Comment& k = blk_.comments[comments_used_++];
        k.text.assign(trim_right(text_.substr(i + 1, end - i - 1)));  // without the CR of a CR LF line
        k.where = at(i);
        k.semicolon = true;
        return end;
    }
    if (c == '#') {
        if (rules_->macro_b || rules_->o_words) return assignment(i, end);
        return flagged(i, end, statement_end(i, end),
                       "is a macro statement, which ГОСТ 20999-83 programs do not have (try --dialect fanuc)");
    }
    if (rules_->o_words && (c == 'o' || c == 'O') && i + 1 < end && (is_digit(text_[i + 1]) || text_[i + 1] == '<'))
        return o_word(i, end);
    if (is_letter(c) && i + 1 < end && is_letter(text_[i + 1])) return letters(i, end);
    if (std::size_t k = c == ',' ? skip_blanks(i + 1, end) : end;
        c == ',' && rules_->corner_words && k < end && (text_[k] == 'C' || text_[k] == 'R')) {
        Word& w = next_word();  // ",C1." chamfer, ",R2." corner (", R 15." as typed): a word of its own
        Location comma = at(i);
        word(k, end, &i, blk_.ordinal, w);
        w.text.insert(0, 1, ',');
        w.address = ',';
        w.where = comma;
        return i;
    }
    if (is_upper(c) || (is_lower(c) && rules_->lowercase)) {
        word(i, end, &i, blk_.ordinal, next_word());
        return i;
    }
    if (is_lower(c)) {
        Word& w = next_word();
        word(i, end, &i, blk_.ordinal, w);
        w.known = false;
        find("unknown-word", w.where.offset - base_, blk_.ordinal,
             "'" + w.text + "': lowercase letters are no addresses in " +
                 std::string(rules_->dialect == Dialect::gost ? "ГОСТ 20999-83 programs (table 1)" : "Fanuc programs") +
                 " (try --dialect linuxcnc)");
        return i;
    }
    return unexpected(i, end, blk_.ordinal);
}

// Two letters or more: a macro keyword, or no word at all (an address is one letter).
std::size_t Loader::letters(std::size_t i, std::size_t end) {
    std::string name = macro::name_at(text_, i);
    bool keyword = listed(name, macro_keywords);
    if (rules_->macro_b && keyword && (is_upper(text_[i]) || rules_->lowercase)) return macro_statement(i, end, name);
    if (keyword && !rules_->macro_b)
        return flagged(i, end, statement_end(i, end),
                       "is a Custom Macro B statement, which this dialect does not have (try --dialect fanuc)");
    return flagged(i, end, i + name.size() + macro::value_length(text_.substr(0, end), i + name.size(), linuxcnc_),
                   "is no word: an address is one letter followed by its value");
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
    w.digit_count = -1;
    w.text.assign(text);
    return w;
}

// The first ')' outside any comment from i to e, or npos.
std::size_t Loader::stray_close(std::size_t i, std::size_t e) const {
    if (i >= e || (!line_close_ && within_line(i, e)) || !std::memchr(text_.data() + i, ')', e - i))
        return std::string_view::npos;  // most blocks
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
    if (rules_->dialect == Dialect::none) {  // only what no control reads: a control character, or not 7-bit
        if (std::none_of(w.text.begin(), w.text.end(), [](char k) {
                auto u = static_cast<unsigned char>(k);
                return u < 0x20 || u >= 0x7F;
            }))
            return j;
        message = "'" + w.text +
                  "' is a control character or none of 7-bit code: no control reads it outside comments" +
                  look_alike_hint(w.text);
    }
    if (message.empty())
        message = "'" + w.text + "' is no part of an NC program outside comments" +
                  (rules_->dialect == Dialect::gost ? " (ГОСТ 20999-83 tables 1-3)" : "") + look_alike_hint(w.text);
    find(rule, i, block_no, std::move(message));
    return j;
}

}  // namespace tape
