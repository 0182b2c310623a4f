// Restoration: the reads aligned, a vote per column, the program's own rules deciding what the vote
// left open (repair.hpp), and the final checks (tape/restore.hpp).
#include "tape/restore.hpp"

#include <algorithm>
#include <array>

#include "read_cuts.hpp"
#include "repair.hpp"
#include "repair_world.hpp"
#include "vote.hpp"

namespace tape {
namespace {

// The image from the verdicts: the frames written, each problem given its place in it, the counts.
// The vote's problems are moved out (the runs stay).
void make_image(detail::VoteResult&& vote, RestoreResult& out) {
    std::size_t written = 0;
    for (const auto& d : vote.verdicts) written += d.write;
    out.frames.reserve(written);
    out.problems.reserve(vote.problems.size());
    for (const auto& d : vote.verdicts) {
        ++out.counts[static_cast<std::size_t>(d.status)];
        if (d.problem >= 0) {
            RestoreProblem p = std::move(vote.problems[static_cast<std::size_t>(d.problem)]);
            p.after = out.frames.size();
            p.frame = d.write ? std::optional<std::uint64_t>(out.frames.size() + 1) : std::nullopt;
            if (!d.write && in_doubt(d.status)) ++out.contested_unwritten;
            out.problems.push_back(std::move(p));
        }
        if (d.write) out.frames.push_back(d.written);
    }
    vote.problems = {}, vote.verdicts = {};
}

// No read went past the tape's start (or end): what each read has at that end.
RestoreProblem missing_end_problem(const ReadAlignment& a, std::span<const std::span<const Frame>> reads, bool start) {
    RestoreProblem p;
    p.status = FrameStatus::missing;
    p.column = start ? 0 : a.columns() - 1;
    for (std::size_t r = 0; r < a.reads(); ++r) {
        bool any = a.first_column(r) < a.end_column(r);
        p.seen.push_back(!any ? std::nullopt : frame_at(a, reads, start ? a.first_column(r) : a.end_column(r) - 1, r));
        p.covered.push_back(any);
    }
    p.reason = start ? "no read starts with leader: the start of the tape may be missing; read it again from "
                       "before its first punched frame"
                     : "no read ends with trailer: the end of the tape may be missing; read it again to past its "
                       "last punched frame";
    return p;
}

void add_missing_end(RestoreResult& out, RestoreProblem p, bool start) {
    p.frame = start ? 1 : out.frames.size();
    p.after = start ? 0 : out.frames.size();
    ++out.counts[static_cast<std::size_t>(FrameStatus::missing)];
    (start ? out.missing_start : out.missing_end) = 1;
    if (start)
        out.problems.insert(out.problems.begin(), std::move(p));
    else
        out.problems.push_back(std::move(p));
}

}  // namespace

std::string_view status_name(FrameStatus s) {
    static constexpr std::array<std::string_view, frame_status_count> names = {
        "clean", "voted", "inferred", "guessed", "contested", "unstable", "unresolved", "missing", "extra"};
    return names[static_cast<std::size_t>(s)];
}

bool RestoreResult::complete() const {
    return !unchecked && !code_misfit &&
           count(FrameStatus::guessed) + count(FrameStatus::contested) + count(FrameStatus::unstable) +
                   count(FrameStatus::unresolved) + count(FrameStatus::missing) ==
               0;
}

double frame_distance_cm(std::uint64_t frame) { return frame == 0 ? 0 : static_cast<double>(frame - 1) * 0.254; }

RestoreResult restore(std::span<const std::span<const Frame>> given, const RestoreOptions& options) {
    // Reads in another code than the one given: every frame would fail it and stand in doubt. They are
    // voted as frames of no code, nothing is repaired, and the result says the code does not fit.
    RestoreOptions o = options;
    // Long stretches only one read has are left out before aligning (read_cuts.hpp).
    const detail::CutReads cut = detail::cut_reads(given, o.doubts, o.align);
    const std::span<const std::span<const Frame>> reads(cut.reads);
    bool misfit = false;
    if (o.code) {
        // By most reads, not the longest: one read of noise must not undo the code the others fit.
        auto failing = std::count_if(reads.begin(), reads.end(),
                                     [&](std::span<const Frame> r) { return detail::code_does_not_fit(r, *o.code); });
        misfit = 2 * static_cast<std::size_t>(failing) > reads.size();
        if (misfit) o.code.reset();
    }
    detail::VoteResult vote;
    std::unique_ptr<detail::RepairWorld> world;
    std::optional<RestoreProblem> missing_start, missing_end;
    RestoreResult out;
    {
        // The alignment and what the vote knew are let go before the image is made: they are the
        // largest things held.
        ReadAlignment a = align_reads(reads, o.align);
        const detail::VoteContext v = detail::make_vote_context(a, reads, o);
        vote = detail::vote(v, o);
        detail::keep_stretches_most_reads_hold(v, vote);
        if (o.code) world = detail::decide_runs_by_rules(v, vote, o);
        if (!detail::read_past_end(v, true)) missing_start = missing_end_problem(a, reads, true);
        if (!detail::read_past_end(v, false)) missing_end = missing_end_problem(a, reads, false);
        out.reference = a.reference();
        std::size_t related = 0;
        for (std::size_t r = 0; r < a.reads(); ++r) {
            out.shared.push_back(a.shared(r));
            out.related.push_back(a.related(r));
            related += a.related(r);
        }
        out.unchecked = related == 1 && !o.code && !misfit;
    }
    make_image(std::move(vote), out);
    out.counts[static_cast<std::size_t>(FrameStatus::extra)] += cut.unmatched;
    for (const auto& run : vote.runs) out.run_length_votes += !run.blank_end && run.decided(o.run_odds);
    out.code_misfit = misfit;
    if (o.code) {
        detail::repair_unresolved(out, *o.code, o, std::move(world));
        detail::number_lines(out, *o.code);
    }
    if (missing_start) add_missing_end(out, std::move(*missing_start), true);
    if (missing_end) add_missing_end(out, std::move(*missing_end), false);
    return out;
}

}  // namespace tape
