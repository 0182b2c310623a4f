// tape diff: two reads of one tape aligned and compared frame by frame, to look before merging.
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/outputs.hpp"
#include "cli/restore_inputs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "motion_diff_report.hpp"
#include "restore_report.hpp"
#include "tape/align.hpp"

namespace cli {
namespace {

struct DiffArgs {
    std::string first, second, code = "auto";
    bool strict = false, motion = false;
    double tolerance_mm = 0.001;
    ProgramSource source;  // --motion: the programs are read as plot reads them
    MotionArgs machine;
};

std::string side(const std::optional<tape::FrameCode>& code, const std::vector<tape::Frame>& frames, std::int32_t i) {
    if (i == tape::ReadAlignment::none) return "-";
    return "frame " + std::to_string(i + 1) + " " + frame_text(code, frames[static_cast<std::size_t>(i)]);
}

tape::ReadAlignment aligned(const std::vector<TapeInput>& reads) {
    std::vector<std::span<const tape::Frame>> spans{reads[0].frames, reads[1].frames};
    try {
        return tape::align_reads(spans);
    } catch (const tape::UnrelatedRead& e) {
        fail(display_name(reads[e.read()].name), tape::Errc::bad_image, unrelated_text(e, reads));
    } catch (const tape::Error& e) {
        fail("", e);
    }
}

// Blank leader or trailer: the columns before the first and after the last where either read has holes.
std::pair<std::size_t, std::size_t> data_columns(const tape::ReadAlignment& al, const std::vector<TapeInput>& reads) {
    std::size_t from = al.columns(), to = 0;
    for (std::size_t c = 0; c < al.columns(); ++c)
        for (std::size_t r = 0; r < 2; ++r) {
            std::int32_t i = al.frame(c, r);
            if (i != tape::ReadAlignment::none && reads[r].frames[static_cast<std::size_t>(i)] != tape::blank_frame)
                from = std::min(from, c), to = c + 1;
        }
    return {from, to};
}

struct Counts {
    // Frames that differ; frames one read has where the other has none; of the latter, blank leader or
    // trailer one read has longer, and data before the other read begins or after it ends.
    std::uint64_t differ = 0, only[2] = {0, 0}, ends[2] = {0, 0}, before[2] = {0, 0}, after[2] = {0, 0};
};

// A read that begins late or ends early inside the data (cut, or its reader started late) misses frames
// the other has: said in one line, each way it happens.
void say_cut_short(const Counts& n, const std::vector<TapeInput>& reads) {
    for (std::size_t has = 0; has < 2; ++has) {
        std::string other = display_name(reads[1 - has].name), with = display_name(reads[has].name);
        if (n.before[has])
            say("", other + " begins " + std::to_string(n.before[has]) + " frame(s) late, inside the data " + with +
                        " holds before it: a read started late or a cut tape, a difference");
        if (n.after[has])
            say("", other + " ends " + std::to_string(n.after[has]) + " frame(s) early, inside the data " + with +
                        " holds after it: a read stopped early or a cut tape, a difference");
    }
}

void run(const DiffArgs& a) {
    if (a.motion) return run_motion_diff(a.first, a.second, a.source, a.machine, a.tolerance_mm);
    std::vector<TapeInput> reads = read_all_bounded({a.first, a.second});
    std::string code_name;
    std::optional<tape::FrameCode> code = code_for_reads(a.code, "", reads, code_name);
    tape::ReadAlignment al = aligned(reads);
    auto [from, to] = data_columns(al, reads);
    std::string out;
    Counts n;
    for (std::size_t c = 0; c < al.columns(); ++c) {
        std::int32_t x = al.frame(c, 0), y = al.frame(c, 1);
        bool same = x != tape::ReadAlignment::none && y != tape::ReadAlignment::none &&
                    reads[0].frames[static_cast<std::size_t>(x)] == reads[1].frames[static_cast<std::size_t>(y)];
        if (same) continue;
        // Blank leader or trailer one read has longer: no difference of the tape, unless --strict.
        bool blank_end = (c < from || c >= to) && (x == tape::ReadAlignment::none || y == tape::ReadAlignment::none);
        std::size_t has = x == tape::ReadAlignment::none ? 1 : 0;
        if (blank_end) ++n.ends[has];
        if (blank_end && !a.strict) continue;
        if (!blank_end && (x == tape::ReadAlignment::none || y == tape::ReadAlignment::none) && !al.covers(1 - has, c))
            ++(c < al.first_column(1 - has) ? n.before : n.after)[has];
        if (x != tape::ReadAlignment::none && y != tape::ReadAlignment::none)
            ++n.differ;
        else
            ++n.only[has];
        out += side(code, reads[0].frames, x) + "  |  " + side(code, reads[1].frames, y) + "\n";
    }
    out += std::to_string(n.differ) + " frame(s) differ, " + std::to_string(n.only[0]) + " only in " +
           display_name(reads[0].name) + ", " + std::to_string(n.only[1]) + " only in " + display_name(reads[1].name) +
           "\n";
    write_output("-", out, false, false);
    say_cut_short(n, reads);
    if ((n.ends[0] || n.ends[1]) && !a.strict)
        say("", "note: the leader and trailer differ in length by " + std::to_string(n.ends[0] + n.ends[1]) +
                    " blank frame(s), which is no difference of the tape (--strict counts them)");
    if (n.differ + n.only[0] + n.only[1]) throw Exit{bad_data};
}

}  // namespace

void add_diff(CLI::App& app) {
    auto a = std::make_shared<DiffArgs>();
    auto* sub = app.add_subcommand(
        "diff",
        "Two reads of one tape aligned and compared frame by frame; with --motion, two programs by what they cut");
    sub->add_option("read1", a->first, "A read of the tape, in any image format (--motion: a program, text or tape)")
        ->required();
    sub->add_option("read2", a->second, "Another read of the same tape (--motion: another program)")->required();
    auto* motion = sub->add_flag("--motion", a->motion,
                                 "Compare the toolpaths: the same within --tolerance, or the first move that differs, "
                                 "with its block in each (exit 1)");
    sub->add_option("--tolerance", a->tolerance_mm,
                    "With --motion: how far apart two points may be and be the same, mm")
        ->check(real_number(1e-6, 100))
        ->capture_default_str()
        ->needs(motion);
    add_dialect_option(sub, a->source.dialect);
    add_motion_options(sub, a->machine);
    sub->add_option("--code,-c", a->code, "How frames are named: auto, iso, eia, or none (holes only)")
        ->check(CLI::IsMember({"auto", "iso", "eia", "none"}))
        ->capture_default_str();
    sub->add_flag("--strict", a->strict,
                  "Count blank leader and trailer of different length as differences (they are a note otherwise)");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
