// libFuzzer target: format specifications (ГОСТ 20999-83 §9 notation) and rewriting words for them.
// Input: line 1 the controller's spec, line 2 the spec the program is written in (empty: none), the
// rest a program. Every word format_word writes must pass lint with the spec (no spec-* finding)
// and keep its value; a word that does not fit is an Error(bad_text), a bad spec an Error(usage).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "tape/error.hpp"
#include "tape/format_spec.hpp"
#include "tape/lint.hpp"

namespace {

std::string_view next_line(std::string_view& text) {
    auto nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
    return line;
}

std::optional<tape::FormatSpec> parse(std::string_view text) {
    try {
        return tape::parse_format_spec(text);
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::usage) __builtin_trap();
        return std::nullopt;
    }
}

// The formatted word as the only word of a one-block program, checked as lint checks it.
void check_written(const std::string& out, const tape::Word& in, const tape::FormatSpec& spec,
                   const tape::FormatSpec* from) {
    tape::LoadedTape t = tape::load("%\n" + out + "\n");
    for (const auto& f : t.findings)
        if (f.rule != "program-end") __builtin_trap();
    for (const auto& f : tape::lint(t, tape::LintOptions{&spec}))
        if (f.rule.substr(0, 5) == "spec-") __builtin_trap();
    if (t.programs.size() != 1 || t.programs[0].blocks.size() != 1) __builtin_trap();
    const tape::Block& b = t.programs[0].blocks[0];
    if (!b.number && b.words.size() != 1) __builtin_trap();
    const tape::Word& back = b.number ? *b.number : b.words[0];
    tape::DecimalValue was = tape::word_value(in, from ? from->find(in.address) : nullptr);
    tape::DecimalValue now = tape::word_value(back, spec.find(in.address));
    if (was.negative != now.negative || was.whole != now.whole || was.fraction != now.fraction) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    std::optional<tape::FormatSpec> spec = parse(next_line(text));
    std::string_view from_text = next_line(text);
    std::optional<tape::FormatSpec> from;
    if (!from_text.empty()) from = parse(from_text);
    if (!spec) return 0;
    bool strip_zeros = size % 2 == 1;
    tape::LoadedTape program = tape::load(std::string(text));
    auto findings = tape::lint(program, tape::LintOptions{&*spec});
    for (const auto& f : findings)
        if (!f.where.byte || *f.where.byte > text.size()) __builtin_trap();
    for (const auto& p : program.programs)
        for (const auto& b : p.blocks) {
            // Words the loader found malformed (no digits, two points) are not the formatter's to keep.
            bool clean = true;
            for (const auto& f : program.findings)
                if (f.where.block == b.ordinal && f.rule != "program-end") clean = false;
            auto put = [&](const tape::Word& w) {
                std::string out;
                try {
                    out = tape::format_word(w, *spec, from ? &*from : nullptr, strip_zeros);
                } catch (const tape::Error& e) {
                    if (e.code() != tape::Errc::bad_text) __builtin_trap();
                    return;
                }
                if (clean) check_written(out, w, *spec, from ? &*from : nullptr);
            };
            if (b.number) put(*b.number);
            for (const auto& w : b.words) put(w);
        }
    return 0;
}
