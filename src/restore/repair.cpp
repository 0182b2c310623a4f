// Repair of what the vote left open (repair.hpp): frames no read has right and good readings that
// disagree, held against the block they stand in (block_repair.hpp), a line at a time.
#include "repair.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "block_repair.hpp"
#include "repair_world.hpp"

namespace tape::detail {
namespace {

// A frame with one hole (in every read that has it) in blank tape: the leader or trailer, or tape fed
// between blocks (blank on both sides, past other such frames). Blank tape is what fits there. Not where
// another read has it blank: against a hole, a blank reading is a character that may have lost its holes.
bool hole_in_blank_tape(const RestoreResult& out, const RestoreProblem& p) {
    if (!std::all_of(p.seen.begin(), p.seen.end(),
                     [&](const std::optional<Frame>& f) { return !f || hole_count(*f) == 1; }))
        return false;
    std::size_t at = static_cast<std::size_t>(*p.frame - 1);
    std::size_t l = at, r = at + 1;
    while (l > 0 && hole_count(out.frames[l - 1]) <= 1 && out.frames[l - 1] != blank_frame) --l;
    while (r < out.frames.size() && hole_count(out.frames[r]) <= 1 && out.frames[r] != blank_frame) ++r;
    bool blank_before = l == 0 || out.frames[l - 1] == blank_frame;
    bool blank_after = r == out.frames.size() || out.frames[r] == blank_frame;
    return blank_before && blank_after;
}

}  // namespace

bool code_does_not_fit(std::span<const Frame> frames, const FrameCode& code) {
    auto data = punched_part(frames);
    std::size_t bad = 0;
    for (Frame f : data) bad += is_bad_frame(code.kind(f));
    return data.size() >= 8 && bad * 4 > data.size();
}

// The rules the block around frame `anchor` breaks as written, the frames at places (image indices in
// that block) judged as the damaged ones (an error the block has anyway decides nothing).
Breaks judge_as_written(const RestoreResult& out, const RepairWorld& w, std::size_t anchor,
                        std::vector<std::size_t> places) {
    auto range = block_around(w.setup.code, out.frames, anchor);
    if (!range || !w.setup.nc) return {};
    std::erase_if(places, [&](std::size_t at) { return at < range->first || at >= range->second; });
    if (places.empty()) return {};
    BlockJudge judge(w.setup, out.frames, range->first, range->second, w.line_of(anchor), places);
    BlockTry as_written{std::vector<Frame>(judge.frames().begin(), judge.frames().end()), {}};
    for (std::size_t at : places) as_written.decided.push_back(at - range->first);
    Breaks breaks = judge.judge(as_written);
    std::erase(breaks, std::string(arc_closes));
    std::erase(breaks, std::string("arc"));
    return breaks;
}

// A vote put in doubt, why added to its reason; the frame written (or, left out, not) as the vote decided.
void put_in_doubt(RestoreResult& out, RestoreProblem& p, const std::string& why) {
    std::string reason = p.reason + "; but " + why + ", so it stays in doubt";
    if (p.frame) return set_status(out, p, FrameStatus::contested, p.written, std::move(reason));
    --out.counts[static_cast<std::size_t>(p.status)];
    ++out.counts[static_cast<std::size_t>(FrameStatus::contested)];
    ++out.contested_unwritten;
    p.status = FrameStatus::contested;
    p.reason = std::move(reason);
}

// Frames voted against a good reading whose block, as written, breaks the program's rules: the reads
// may have been paired at the wrong place, so they stay in doubt.
void doubt_votes_that_break_their_block(RestoreResult& out, const RepairWorld& w,
                                        std::span<RestoreProblem* const> outvoted) {
    for (std::size_t a = 0; a < outvoted.size();) {
        std::uint64_t line = w.line_of(static_cast<std::size_t>(*outvoted[a]->frame - 1));
        std::size_t b = a + 1;
        while (b < outvoted.size() && w.line_of(static_cast<std::size_t>(*outvoted[b]->frame - 1)) == line) ++b;
        std::vector<std::size_t> places;
        for (const RestoreProblem* p : outvoted.subspan(a, b - a))
            places.push_back(static_cast<std::size_t>(*p->frame - 1));
        Breaks breaks = judge_as_written(out, w, places.front(), places);
        if (!breaks.empty())
            for (RestoreProblem* p : outvoted.subspan(a, b - a))
                put_in_doubt(
                    out, *p,
                    "its block as written breaks " + joined(breaks) + ": the reads may be paired at the wrong place");
        a = b;
    }
}

// What the block a good frame was left out of breaks at that place without it ("N9999" among blocks
// numbered N99999), and whether it fits with the frame put back.
struct LeftOutJudged {
    Breaks without;
    bool fits_with = false;
};
LeftOutJudged judge_left_out(const RestoreResult& out, const RepairWorld& w, const RestoreProblem& p) {
    if (!w.setup.nc || out.frames.empty()) return {};
    const std::size_t at = static_cast<std::size_t>(p.after), first = std::min(at, out.frames.size() - 1);
    auto range = block_around(w.setup.code, out.frames, first);
    if (!range || at < range->first || at > range->second) return {};
    // The frame after the gap, whose word the left-out frame would stand in.
    std::vector<std::size_t> places{first};
    BlockJudge judge(w.setup, out.frames, range->first, range->second, w.line_of(first), places);
    auto judged = [&](std::size_t copies) {
        Breaks b = judge.judge(with_copies(judge.frames(), at - range->first, 0, copies, p.written));
        std::erase(b, std::string(arc_closes)), std::erase(b, std::string("arc"));
        return b;
    };
    Breaks without = judged(0);
    if (without.empty()) return {};  // most blocks: nothing to doubt, and no second try
    return {std::move(without), judged(1).empty()};
}

// A good frame one read has that the vote left out (the others have none there), where the block breaks
// the program's rules at that place without it: the frame may be the tape's, lost by the other reads (it
// fits), or the reads that disagree here misread something else; either way the place stays in doubt.
void doubt_left_outs_that_break_their_block(RestoreResult& out, const RepairWorld& w,
                                            std::span<RestoreProblem* const> left_out) {
    for (RestoreProblem* p : left_out) {
        auto judged = judge_left_out(out, w, *p);
        if (judged.without.empty()) continue;
        put_in_doubt(out, *p,
                     "without it its block breaks " + joined(judged.without) +
                         (judged.fits_with ? " and with it fits: it may be the tape's, lost by the other reads"
                                           : " where the reads disagree: one of them may have misread it"));
    }
}

// A good frame the vote left out: some read has it, not failing parity, and the most reads have none.
// (Not a copy of a run whose length the vote decided as a whole, nor blank tape or a rubout, which the
// text skips.)
bool left_out_good_reading(const FrameCode& code, const RestoreProblem& p) {
    if (p.frame || p.status != FrameStatus::extra || p.run_length) return false;
    return code.kind(p.written) == FrameKind::character &&
           std::any_of(p.seen.begin(), p.seen.end(), [&](const std::optional<Frame>& f) { return f == p.written; });
}

// Good readings that disagree (not on a run's length, which the vote decided as a whole), where every
// read that covers the place has a frame there: the block's rules may leave one. Where a read has none,
// the frame may be one read twice or a stain read as a frame, and "no frame" is a choice the readings
// do not offer: the rules would pick among the others (a space fits anywhere).
bool tie(const RestoreProblem& p) {
    if ((p.status != FrameStatus::contested && p.status != FrameStatus::unstable) || p.candidates.size() < 2 ||
        p.run_length)
        return false;
    for (std::size_t r = 0; r < p.seen.size(); ++r)
        if (p.covered[r] && !p.seen[r]) return false;
    return true;
}

// A frame the vote gave to the majority against another good reading (not one failing parity): flips
// fail parity, so such a disagreement is a stain, or reads paired at the wrong place (a frame read twice
// beside another lost).
bool outvoted_good_reading(const FrameCode& code, const RestoreProblem& p) {
    if (p.status != FrameStatus::voted || p.run_length) return false;
    return std::any_of(p.seen.begin(), p.seen.end(), [&](const std::optional<Frame>& f) {
        return f && *f != p.written && !is_bad_frame(code.kind(*f));
    });
}

void repair_unresolved(RestoreResult& out, const FrameCode& code, const RestoreOptions& o,
                       std::unique_ptr<RepairWorld> world) {
    std::vector<RestoreProblem*> open, outvoted, left_out;
    std::vector<std::size_t> doubtful;
    for (auto& p : out.problems) {
        // A frame left out (not written) puts in doubt the line it was left out of.
        if (!p.frame) {
            if (p.after < out.frames.size()) doubtful.push_back(static_cast<std::size_t>(p.after));
            if (left_out_good_reading(code, p)) left_out.push_back(&p);
            continue;
        }
        if (p.status != FrameStatus::clean) doubtful.push_back(static_cast<std::size_t>(*p.frame - 1));
        if (p.status == FrameStatus::unresolved || tie(p)) open.push_back(&p);
        if (outvoted_good_reading(code, p)) outvoted.push_back(&p);
    }
    if (open.empty() && outvoted.empty() && left_out.empty()) return;
    if (code_does_not_fit(out.frames, code)) {
        for (RestoreProblem* p : open)
            if (p->status == FrameStatus::unresolved)
                p->reason = "not repaired: most frames fail the code, so it is not the tape's";
        return;
    }
    if (!world) world = learn_world(out.frames, doubtful, code, o);
    doubt_votes_that_break_their_block(out, *world, outvoted);
    doubt_left_outs_that_break_their_block(out, *world, left_out);
    std::vector<RestoreProblem*> block;
    std::uint64_t block_line = 0;
    constexpr std::size_t most_damaged = 8;  // frames of one block tried together
    auto flush = [&] {
        if (!block.empty()) repair_block(*world, out, std::move(block), o.guess);
        block.clear();
    };
    for (RestoreProblem* p : open) {
        if (p->status == FrameStatus::unresolved && hole_in_blank_tape(out, *p)) {
            p->candidates = {blank_frame};
            set_status(out, *p, FrameStatus::inferred, blank_frame,
                       "a hole in blank tape (leader, trailer, or tape fed between blocks)");
            continue;
        }
        std::uint64_t line = world->line_of(static_cast<std::size_t>(*p->frame - 1));
        if (line != block_line || block.size() >= most_damaged) flush();
        block_line = line;
        block.push_back(p);
    }
    flush();
}

void number_lines(RestoreResult& out, const FrameCode& code) {
    std::uint64_t line = 1;
    std::size_t next = 0;
    for (std::size_t i = 0; i < out.frames.size() && next < out.problems.size(); ++i) {
        while (next < out.problems.size() && (!out.problems[next].frame || *out.problems[next].frame == i + 1)) {
            if (out.problems[next].frame) out.problems[next].line = line;
            ++next;
        }
        if (code.kind(out.frames[i]) == FrameKind::character && code.character(out.frames[i]) == '\n') ++line;
    }
}

}  // namespace tape::detail
