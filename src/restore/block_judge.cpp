// A repair candidate judged by the block it stands in (block_judge.hpp).
#include "block_judge.hpp"

#include <algorithm>
#include <cmath>

#include "tape/code_tables.hpp"
#include "tape/decode.hpp"
#include "tape/lint.hpp"
#include "tape/machine_checks.hpp"

namespace tape::detail {
namespace {

bool end_of_block(const FrameCode& code, Frame f) {
    return code.kind(f) == FrameKind::character && code.character(f) == '\n';
}

// Where a damaged character's word lies in its line's text (one character per entry, '\x01' for the
// damaged ones): the letter before its value, sign, digits and point, and the value after a damaged
// letter. The spaces some tapes punch inside a word ("X - 0040000") belong to it.
std::pair<std::size_t, std::size_t> word_span(const std::u32string& line, std::size_t at) {
    auto value = [](char32_t c) { return (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-' || c == 1; };
    auto letter = [](char32_t c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
    std::size_t from = at, to = at + 1;
    while (from > 0 && (value(line[from - 1]) || line[from - 1] == ' ')) --from;
    if (from > 0 && letter(line[from - 1]))
        --from;
    else
        while (from < at && line[from] == ' ') ++from;
    while (to < line.size() && (value(line[to]) || line[to] == ' ')) ++to;
    while (to > at + 1 && line[to - 1] == ' ') --to;
    return {from, to};
}

std::u32string characters(const FrameCode& code, std::span<const Frame> frames, std::span<const std::size_t> damaged) {
    std::u32string out;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        bool is_damaged = std::find(damaged.begin(), damaged.end(), i) != damaged.end();
        FrameKind k = code.kind(frames[i]);
        if (is_damaged)
            out += char32_t{1};
        else if (k == FrameKind::character)
            out += static_cast<char32_t>(static_cast<unsigned char>(code.character(frames[i])));
        else if (is_bad_frame(k))
            out += char32_t{0xFFFD};
    }
    return out;
}

std::string utf8(const std::u32string& s) {
    std::string out;
    for (char32_t c : s) {
        if (c == 1) continue;
        if (c == 0xFFFD)
            out += bad_frame_marker;
        else
            out += static_cast<char>(c);
    }
    return out;
}

// The lines of text around frames [from, to): `lines` whole lines before, and one after.
std::pair<std::size_t, std::size_t> around(const FrameCode& code, std::span<const Frame> image, std::size_t from,
                                           std::size_t to, int lines) {
    std::size_t b = from;
    for (int n = 0; n < lines && b > 0; ++n) {
        --b;
        while (b > 0 && !end_of_block(code, image[b - 1])) --b;
    }
    std::size_t e = to;
    while (e < image.size() && !end_of_block(code, image[e])) ++e;
    return {b, std::min(e + 1, image.size())};
}

// The character nearest to frames[at] in direction dir (+1, -1) that is no space (blank tape and DEL
// skipped, as a reader skips them), or 0 at the block's end.
char next_character(const FrameCode& code, std::span<const Frame> frames, std::size_t at, int dir) {
    for (std::size_t i = at; dir > 0 ? i + 1 < frames.size() : i > 0;) {
        i = dir > 0 ? i + 1 : i - 1;
        if (code.kind(frames[i]) != FrameKind::character) continue;
        char c = code.character(frames[i]);
        if (c != ' ') return c;
    }
    return 0;
}

// A decided frame is a space between two digits: it splits a number.
bool splits_digits(const FrameCode& code, const BlockTry& t) {
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    for (std::size_t at : t.decided)
        if (code.kind(t.frames[at]) == FrameKind::character && code.character(t.frames[at]) == ' ' &&
            digit(next_character(code, t.frames, at, -1)) && digit(next_character(code, t.frames, at, 1)))
            return true;
    return false;
}

}  // namespace

std::string joined(const Breaks& breaks) {
    std::string s;
    for (const auto& r : breaks) s += (s.empty() ? "" : ", ") + r;
    return s;
}

// The block with `copies` copies of value where it has `written` from first_copy on, and the copies'
// indices in it.
BlockTry with_copies(std::span<const Frame> block, std::size_t first_copy, std::size_t written, std::size_t copies,
                     Frame value) {
    BlockTry t{std::vector<Frame>(block.begin(), block.end()), {}};
    auto at = t.frames.begin() + static_cast<std::ptrdiff_t>(first_copy);
    t.frames.erase(at, at + static_cast<std::ptrdiff_t>(written));
    t.frames.insert(t.frames.begin() + static_cast<std::ptrdiff_t>(first_copy), copies, value);
    for (std::size_t k = 0; k < copies; ++k) t.decided.push_back(first_copy + k);
    return t;
}

std::string block_text(const FrameCode& code, std::span<const Frame> frames, std::span<const std::size_t> wanted,
                       std::vector<std::pair<std::size_t, std::size_t>>* places) {
    std::string s;
    std::size_t line = 0, column = 0;
    if (places) places->assign(wanted.size(), {0, 0});
    for (std::size_t i = 0; i < frames.size(); ++i) {
        FrameKind k = code.kind(frames[i]);
        bool gives = k == FrameKind::character || is_bad_frame(k);
        if (gives) ++column;
        if (places)
            for (std::size_t w = 0; w < wanted.size(); ++w)
                if (wanted[w] == i) (*places)[w] = {line, gives ? column : 0};
        if (k == FrameKind::character) {
            s += code.character(frames[i]);
            if (code.character(frames[i]) == '\n') column = 0, ++line;
        } else if (is_bad_frame(k)) {
            s += bad_frame_marker;
        }
    }
    return s;
}

BlockJudge::BlockJudge(const RepairSetup& setup, std::span<const Frame> image, std::size_t from, std::size_t to,
                       std::uint64_t line, std::span<const std::size_t> damaged)
    : s_(setup),
      frames_(image.begin() + static_cast<std::ptrdiff_t>(from), image.begin() + static_cast<std::ptrdiff_t>(to)),
      from_(from),
      line_(line) {
    auto [b, e] = around(s_.code, image, from, to, 2);
    before_ = block_text(s_.code, image.subspan(b, from - b));
    after_ = block_text(s_.code, image.subspan(to, e - to));
    // The program's start, where it stands before the context: a block after it is a block of a program.
    if (dialect_rules(s_.dialect).needs_percent && before_.find('%') == std::string::npos && s_.first_percent < from)
        before_ = "%\n" + before_;
    before_lines_ = static_cast<std::uint64_t>(std::count(before_.begin(), before_.end(), '\n'));
    // The baseline: the block with the damaged words left out.
    std::vector<std::size_t> local;
    for (std::size_t d : damaged) local.push_back(d - from);
    std::u32string chars = characters(s_.code, frames_, local);
    std::vector<bool> gone(chars.size(), false);
    for (std::size_t i = 0; i < chars.size(); ++i)
        if (chars[i] == 1) {
            auto [x, y] = word_span(chars, i);
            std::fill(gone.begin() + static_cast<std::ptrdiff_t>(x), gone.begin() + static_cast<std::ptrdiff_t>(y),
                      true);
            spans_.emplace_back(x + 1, y);  // columns, from 1, of the line's first characters
        }
    std::u32string kept;
    for (std::size_t i = 0; i < chars.size(); ++i)
        if (!gone[i]) kept += chars[i];
    baseline_ = error_keys(load_with_context(utf8(kept)));
}

LoadedTape BlockJudge::load_with_context(const std::string& block_text) const {
    // A piece from inside the text has no leader: what stands before a '%' in it is program text.
    return load(before_ + block_text + after_, {}, LoadOptions{s_.dialect, false});
}

// Rules about the program as a whole (a GOTO's or cycle's target, loops and o-words closed), which a block and its
// neighbours cannot settle.
bool whole_program_rule(std::string_view id) {
    return id == "goto-target" || id == "block-target" || id == "duplicate-target" || id == "control-flow";
}

// The error findings of the snippet (context, block, context) by key, from the block's first line on.
std::map<std::string, int> BlockJudge::error_keys(const LoadedTape& t) const {
    std::vector<std::string_view> lines;
    for (std::size_t from = 0; from <= t.text.size();) {
        std::size_t to = std::min(t.text.find('\n', from), t.text.size());
        lines.push_back(std::string_view(t.text).substr(from, to - from));
        from = to + 1;
    }
    std::map<std::string, int> out;
    for (const auto& f : lint(t, LintOptions{s_.spec})) {
        std::uint64_t l = f.where.line.value_or(0);
        if (f.severity != Severity::error || l <= before_lines_ || l > lines.size() || f.id() == "parity" ||
            whole_program_rule(f.id()))
            continue;
        ++out[finding_key(f, lines[l - 1])];
    }
    return out;
}

namespace {
bool is_arc_rule(std::string_view rule) { return rule == "arc-radius" || rule == "arc-radius-short"; }
}  // namespace

// The try's block moves along an arc: its own G02 or G03, or, with no motion code of its own, the one in
// effect before it.
bool BlockJudge::tried_arc(const LoadedTape& t) const {
    for (const auto& p : t.programs)
        for (const auto& b : p.blocks) {
            if (b.where.line != before_lines_ + 1) continue;
            std::optional<long long> motion;
            for (const auto& w : b.words)
                if (w.address == 'G' && w.integer() && *w.integer() >= 0 && *w.integer() <= 3) motion = w.integer();
            const MotionState* state = s_.rules ? s_.rules->state_before(line_) : nullptr;
            if (!motion && state && state->motion >= 0) motion = state->motion;
            return motion == 2 || motion == 3;
        }
    return false;
}

// A decided frame is a tab (HT) where the controller's format has none (no '.' in its notation), the
// tape writes no tab elsewhere and, with a machine, keeps its notation.
bool BlockJudge::tab_off_format(const BlockTry& t) const {
    const FormatSpec* spec = s_.machine ? &s_.machine->format : s_.spec;
    if (!spec || spec->tab || !s_.rules || s_.rules->tabs() ||
        (s_.machine && !s_.rules->machine_rule_trusted('\t', "spec-tab")))
        return false;
    return std::any_of(t.decided.begin(), t.decided.end(), [&](std::size_t at) {
        return s_.code.kind(t.frames[at]) == FrameKind::character && s_.code.character(t.frames[at]) == '\t';
    });
}

// The findings by rule, those the undamaged program has too left out.
std::map<std::string, int> BlockJudge::by_rule(const std::map<std::string, int>& keys) const {
    std::map<std::string, int> out;
    for (const auto& [key, n] : keys)
        if (!(s_.rules && s_.rules->excused(key))) out[key.substr(0, key.find(':'))] += n;
    return out;
}

Breaks BlockJudge::judge(const BlockTry& t) const {
    Breaks out;
    std::vector<std::pair<std::size_t, std::size_t>> places;
    LoadedTape tried = load_with_context(block_text(s_.code, t.frames, t.decided, &places));
    // By rule, not by key: a key names the character a finding points at, and a finding about the whole
    // block (an arc off its circle) points at its first character, which the damaged word may be; a try
    // that puts there the character the baseline has there would escape it.
    const std::map<std::string, int> found = by_rule(error_keys(tried));
    std::map<std::string, int> more = found;
    for (const auto& [rule, n] : by_rule(baseline_)) more[rule] -= n;
    // Lint's arc rules are the arc rule: they judge only where the tape's own arcs close, and decide only
    // between tries where some arc closes (a block off its circle as written is closed by chance by a
    // try that makes it another arc: G90 read as K90, F120 as R120).
    const bool arcs = s_.rules && s_.rules->arcs_trusted();
    for (const auto& [rule, n] : more)
        if (n > 0 && (!is_arc_rule(rule) || arcs)) out.push_back(is_arc_rule(rule) ? "arc" : rule);
    if (arcs && found.count("arc-radius") + found.count("arc-radius-short") == 0 && tried_arc(tried))
        out.push_back(std::string(arc_closes));
    if (s_.rules) own_rules(tried, places, out);
    if (s_.rules && s_.rules->digits_never_split() && splits_digits(s_.code, t)) out.push_back("word-format");
    if (tab_off_format(t)) out.push_back("spec-tab");
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// The word of block b that the character at column stands in: the last word starting at or before it.
// (The block number is a word here too.)
const Word* word_at(const Block& b, std::uint64_t line, std::size_t column) {
    const Word* out = nullptr;
    auto consider = [&](const Word& w) {
        if (w.where.line == line && w.where.column <= column && (!out || w.where.column > out->where.column)) out = &w;
    };
    if (b.number) consider(*b.number);
    for (const auto& w : b.words) consider(w);
    return out;
}

// The program's own rules, on the words the decided frames stand in.
void BlockJudge::own_rules(const LoadedTape& t, const std::vector<std::pair<std::size_t, std::size_t>>& places,
                           Breaks& out) const {
    const TapeRules& rules = *s_.rules;
    const Block* first = nullptr;
    std::vector<const Word*> words;
    auto add = [&](const Word* w) {
        if (w && std::find(words.begin(), words.end(), w) == words.end()) words.push_back(w);
    };
    for (const auto& p : t.programs)
        for (const auto& b : p.blocks) {
            if (b.where.line == before_lines_ + 1) first = &b;
            for (const auto& [line, column] : places)
                if (column) add(word_at(b, before_lines_ + 1 + line, column));
            // And every word that now starts where a damaged word stood (a candidate may split it).
            if (b.where.line != before_lines_ + 1) continue;
            for (const auto& [x, y] : spans_) {
                if (b.number && b.number->where.column >= x && b.number->where.column <= y) add(&*b.number);
                for (const auto& w : b.words)
                    if (w.where.line == b.where.line && w.where.column >= x && w.where.column <= y) add(&w);
            }
        }
    for (const Word* w : words) {
        std::string value = w->text.substr(1);
        if (rules.address_unused(w->address)) out.push_back("unused-address");
        if (rules.case_broken(*w)) out.push_back("letter-case");
        if ((w->address == 'G' || w->address == 'M') && !code_known(s_.dialect, w->address, code_value(value)) &&
            !rules.code_used(w->address, code_value(value)))
            out.push_back("unknown-code");
        if ((w->address == 'G' || w->address == 'M') && s_.machine && rules.machine_codes_trusted())
            if (machine_lists_code(*s_.machine, *w) == false) out.push_back("machine-code");
        auto shape = shape_of(*w);
        if ((shape && rules.format_broken(w->address == ':' ? 'N' : w->address, *shape)) || rules.form_broken(*w))
            out.push_back("word-format");
        const FormatSpec* spec = first ? rules.block_spec(line_, *first) : s_.spec;
        if (spec)
            for (const auto& [rule, message] : check_word(*w, *spec, rules.points()))
                if (!s_.machine || rules.machine_rule_trusted(w->address, rule)) out.push_back(std::string(rule));
        if ((w->address == 'N' || w->address == ':') && w->where.line == before_lines_ + 1)
            if (auto expected = rules.expected_number(line_); expected && w->integer() != expected)
                out.push_back("block-number");
        if ((w->address == 'F' || w->address == 'S' || w->address == 'T') && shape)
            if (rules.value_out_of_range(
                    w->address, std::strtod(w->digits().c_str(), nullptr) / std::pow(10.0, std::max(shape->after, 0))))
                out.push_back("value-range");
    }
    // The machine's feed codes and prefixed words, on the words the decided frames stand in.
    if (s_.machine && first)
        machine_checks(*s_.machine, *first, [&](const Finding& f) {
            for (const Word* w : words)
                if (w->where.line == f.where.line && w->where.column == f.where.column)
                    out.push_back(std::string(f.id()));
        });
    // Where the neighbours say which number the block has, a try that leaves it none breaks the sequence.
    if (first && !first->number && rules.expected_number(line_)) out.push_back("block-number");
    if (const MotionState* state = rules.state_before(line_); state && first && rules.arcs_trusted())
        if (auto agrees = arc_agrees(*state, *first)) out.push_back(std::string(*agrees ? arc_closes : "arc"));
}

}  // namespace tape::detail
