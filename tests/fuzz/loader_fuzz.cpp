// libFuzzer target: any bytes as a program text, in every dialect, through the loader, lint, search and a
// format rewrite.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "tape/error.hpp"
#include "tape/format_spec.hpp"
#include "tape/lint.hpp"
#include "tape/search.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<std::uint64_t> frames(text.size());
    for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = i * 2 + 100;  // a tape with gaps
    bool with_frames = size % 2 == 0;
    // Every dialect, none, and the automatic choice, by the size.
    constexpr tape::Dialect dialects[] = {tape::Dialect::gost, tape::Dialect::fanuc, tape::Dialect::linuxcnc,
                                          tape::Dialect::none, tape::Dialect::automatic};
    tape::LoadOptions options{dialects[(size / 2) % 5]};
    tape::LoadedTape t = tape::load(text, with_frames ? frames : std::vector<std::uint64_t>{}, options);
    static const tape::FormatSpec spec =
        tape::parse_format_spec("% : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*");
    static const tape::FormatSpec implied = tape::parse_format_spec("N03 G02 X+053 Y+530 Z+53 F031 S04 T04 M02");
    auto findings = tape::lint(t, tape::LintOptions{&spec});
    for (const auto& f : findings)
        if (!f.where.byte || *f.where.byte > text.size()) __builtin_trap();
    for (const auto& p : t.programs)
        for (const auto& b : p.blocks) {
            if (b.where.offset >= text.size()) __builtin_trap();
            for (const auto& w : b.words) {
                try {
                    tape::format_word(w, implied, &spec, size % 3 == 0);
                    tape::format_word(w, spec, &implied, false);
                } catch (const tape::Error&) {
                }
            }
        }
    // The loader fed in three pieces finds the same blocks and findings as on the whole text.
    struct Count : tape::ProgramVisitor {
        std::size_t blocks = 0, findings = 0;
        void block(const tape::Block&) override { ++blocks; }
        void finding(const tape::Finding&) override { ++findings; }
    } pieces;
    {
        tape::ProgramLoader loader(pieces, options);
        std::string_view all(text);
        std::span<const std::uint64_t> all_frames;
        if (with_frames) all_frames = frames;
        std::size_t a = size / 3, b = size - size / 5;
        auto frames_of = [&](std::size_t from, std::size_t n) {
            return all_frames.empty() ? all_frames : all_frames.subspan(from, n);
        };
        loader.feed(all.substr(0, a), frames_of(0, a));
        loader.feed(all.substr(a, b - a), frames_of(a, b - a));
        loader.feed(all.substr(b), frames_of(b, size - b));
        loader.finish();
    }
    std::size_t blocks = 0;
    for (const auto& p : t.programs) blocks += p.blocks.size();
    if (pieces.blocks != blocks || pieces.findings != t.findings.size()) __builtin_trap();
    tape::find_main_block(t, text.size() / 2);
    tape::find_rewind_stop(t, text.size());
    tape::find_numbered_blocks(t, 1);
    tape::frame_offset(t, size);
    return 0;
}
