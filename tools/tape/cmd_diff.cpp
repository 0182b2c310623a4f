// tape diff: two reads of one tape aligned and compared frame by frame, to look before merging.
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "restore_report.hpp"
#include "tape/align.hpp"

namespace cli {
namespace {

struct DiffArgs {
    std::string first, second, code = "auto";
};

std::string side(const std::optional<tape::FrameCode>& code, const std::vector<tape::Frame>& frames, std::int32_t i) {
    if (i == tape::ReadAlignment::none) return "-";
    return "frame " + std::to_string(i + 1) + " " + frame_text(code, frames[static_cast<std::size_t>(i)]);
}

void run(const DiffArgs& a) {
    std::vector<TapeInput> reads{read_tape(a.first, ""), read_tape(a.second, "")};
    const TapeInput &one = reads[0], &two = reads[1];
    std::string code_name;
    std::optional<tape::FrameCode> code = code_for_reads(a.code, "even", reads, code_name);
    std::vector<std::span<const tape::Frame>> spans{one.frames, two.frames};
    tape::ReadAlignment al = [&] {
        try {
            return tape::align_reads(spans);
        } catch (const tape::Error& e) {
            fail("", e);
        }
    }();
    std::string out;
    std::uint64_t differ = 0, only_one = 0, only_two = 0;
    for (std::size_t c = 0; c < al.columns(); ++c) {
        std::int32_t x = al.frame(c, 0), y = al.frame(c, 1);
        bool same = x != tape::ReadAlignment::none && y != tape::ReadAlignment::none &&
                    one.frames[static_cast<std::size_t>(x)] == two.frames[static_cast<std::size_t>(y)];
        if (same) continue;
        // Where one read simply has not begun or has ended, it is no difference of the tape.
        if (x == tape::ReadAlignment::none && !al.covers(0, c)) continue;
        if (y == tape::ReadAlignment::none && !al.covers(1, c)) continue;
        if (x == tape::ReadAlignment::none)
            ++only_two;
        else if (y == tape::ReadAlignment::none)
            ++only_one;
        else
            ++differ;
        out += side(code, one.frames, x) + "  |  " + side(code, two.frames, y) + "\n";
    }
    out += std::to_string(differ) + " frame(s) differ, " + std::to_string(only_one) + " only in " +
           display_name(one.name) + ", " + std::to_string(only_two) + " only in " + display_name(two.name) + "\n";
    write_output("-", out, false, false);
    if (differ + only_one + only_two) throw Exit{bad_data};
}

}  // namespace

void add_diff(CLI::App& app) {
    auto a = std::make_shared<DiffArgs>();
    auto* sub = app.add_subcommand("diff", "Two reads of one tape aligned and compared frame by frame");
    sub->add_option("read1", a->first, "A read of the tape, in any image format")->required();
    sub->add_option("read2", a->second, "Another read of the same tape")->required();
    sub->add_option("--code,-c", a->code, "How frames are named: auto, iso, eia, or none (holes only)")
        ->check(CLI::IsMember({"auto", "iso", "eia", "none"}))
        ->capture_default_str();
    sub->callback([a] { run(*a); });
}

}  // namespace cli
