// Loader: characters -> label, programs, blocks, words (ГОСТ 20999-83 §1-§3).
// One pass over the text, a line (block) at a time; problems become findings, never exceptions.
#include "tape/program.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "codec/utf8.hpp"
#include "program/loader/loader.hpp"
#include "tape/rules.hpp"

namespace tape {

Finding program_finding(std::string_view rule, const Location& where, std::uint64_t block, std::string message) {
    const Rule* r = find_rule(rule);
    Severity severity = r ? r->severity : Severity::error;
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

// A word not made by the loader (digit_count -1): its digits read from the text.
std::optional<long long> Word::integer_of_text() const {
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

std::string_view program_key(std::string_view s) {
    if (!s.empty() && (s[0] == 'O' || s[0] == 'o' || s[0] == ':')) s.remove_prefix(1);
    while (s.size() > 1 && s[0] == '0') s.remove_prefix(1);
    return s;
}

// Asked of every block by the loader: a block without M words costs a loop.
bool holds_end_code(const Block& block, std::span<const int> ends) {
    for (const Word& w : block.words)
        if (auto v = w.address == 'M' ? w.integer() : std::nullopt)
            if (std::find(ends.begin(), ends.end(), *v) != ends.end()) return true;
    return false;
}

std::string Block::text() const {
    std::string out = skip ? "/" : "";
    auto add = [&](const std::string& piece) {
        if (!out.empty() && out != "/") out += ' ';
        out += piece;
    };
    if (number) add(number->text);
    for (const auto& w : words) add(w.text);
    for (const auto& s : statements) add(s.text);
    for (const auto& c : comments) add(c.semicolon ? ";" + c.text : "(" + c.text + ")");
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
    void record_end(const Location& where, bool closes_program) override {
        t_.record_end = where;
        if (closes_program && !t_.programs.empty()) t_.programs.back().ended = true;
    }
    void dialect(const DialectChoice& choice) override {
        t_.dialect = choice.dialect;
        t_.dialect_reason = choice.reason;
    }
    void finding(const Finding& f) override { t_.findings.push_back(f); }

private:
    LoadedTape& t_;
};

}  // namespace

ProgramLoader::ProgramLoader(ProgramVisitor& visitor, const LoadOptions& options)
    : loader_(std::make_unique<Loader>(visitor, options)) {}
ProgramLoader::~ProgramLoader() = default;
void ProgramLoader::feed(std::string_view text, std::span<const std::uint64_t> frame_of) {
    loader_->feed(text, frame_of);
}
void ProgramLoader::finish() { loader_->finish(); }

void load_each(std::string_view text, std::span<const std::uint64_t> frame_of, ProgramVisitor& visitor,
               const LoadOptions& options) {
    ProgramLoader loader(visitor, options);
    loader.feed(text, frame_of);
    loader.finish();
}

LoadedTape load(std::string text, std::vector<std::uint64_t> frame_of, const LoadOptions& options) {
    LoadedTape t;
    t.text = std::move(text);
    t.frame_of = std::move(frame_of);
    Collector collect(t);
    load_each(t.text, t.frame_of, collect, options);
    return t;
}

}  // namespace tape
