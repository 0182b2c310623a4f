// Runs of equal frames whose length the reads disagree on, decided by the program's rules where one
// length breaks them (repair.hpp): "X-0040000" read with a zero more, where X words on this tape have
// seven digits, is decided by the word format, not by the odds of a lost or a doubled frame.
#include <algorithm>

#include "repair.hpp"
#include "repair_world.hpp"

namespace tape::detail {
namespace {

// The image as the verdicts make it, and where each column's frame stands (or would stand) in it.
struct Draft {
    std::vector<Frame> frames;
    std::vector<std::size_t> place;  // per column: its frame's index, or the index it would take
    std::vector<std::size_t> doubtful;
};

Draft draft(const VoteResult& vote) {
    Draft d;
    d.place.reserve(vote.verdicts.size());
    for (const auto& v : vote.verdicts) {
        d.place.push_back(d.frames.size());
        if (v.write && v.status != FrameStatus::clean) d.doubtful.push_back(d.frames.size());
        if (v.write) d.frames.push_back(v.written);
    }
    return d;
}

// The block holding the run with `copies` copies of its frame, and the copies' indices in it.
BlockTry with_copies(std::span<const Frame> block, std::size_t first_copy, std::size_t written, std::size_t copies,
                     Frame value) {
    BlockTry t{std::vector<Frame>(block.begin(), block.end()), {}};
    auto at = t.frames.begin() + static_cast<std::ptrdiff_t>(first_copy);
    t.frames.erase(at, at + static_cast<std::ptrdiff_t>(written));
    t.frames.insert(t.frames.begin() + static_cast<std::ptrdiff_t>(first_copy), copies, value);
    for (std::size_t k = 0; k < copies; ++k) t.decided.push_back(first_copy + k);
    return t;
}

std::string joined(const Breaks& b) {
    std::string s;
    for (const auto& r : b) s += (s.empty() ? "" : ", ") + r;
    return s;
}

}  // namespace

std::unique_ptr<RepairWorld> decide_runs_by_rules(const VoteContext& v, VoteResult& vote, const RestoreOptions& o) {
    auto open = [&](const RunDecision& d) { return !d.blank_end && d.length != d.alternative && d.length > 0; };
    if (std::none_of(vote.runs.begin(), vote.runs.end(), open)) return nullptr;
    Draft img = draft(vote);
    if (code_does_not_fit(img.frames, *v.code)) return nullptr;
    auto world = learn_world(img.frames, img.doubtful, *v.code, o);
    if (!world->setup.nc) return world;
    std::ptrdiff_t shift = 0;  // frames the runs decided so far added (+) or took out (-)
    for (std::size_t r = 0; r < vote.runs.size(); ++r) {
        RunDecision& d = vote.runs[r];
        if (!open(d)) continue;
        std::size_t first = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(img.place[d.first]) + shift);
        auto range = block_around(*v.code, img.frames, std::min(first, img.frames.size() - 1));
        if (!range || first + d.length > range->second) continue;
        std::vector<std::size_t> copies;
        for (std::size_t k = 0; k < d.length; ++k) copies.push_back(first + k);
        BlockJudge judge(world->setup, img.frames, range->first, range->second, world->line_of(first), copies);
        std::size_t local = first - range->first;
        Breaks kept = judge.judge(with_copies(judge.frames(), local, d.length, d.length, d.value));
        Breaks other = judge.judge(with_copies(judge.frames(), local, d.length, d.alternative, d.value));
        // The arc rule decides only where one of the two closes the arc.
        bool closes = std::erase(kept, std::string(arc_closes)) + std::erase(other, std::string(arc_closes)) > 0;
        if (!closes) std::erase(kept, std::string("arc")), std::erase(other, std::string("arc"));
        if (kept.empty() == other.empty()) continue;
        if (!kept.empty()) {
            std::swap(d.length, d.alternative);
            std::ptrdiff_t delta = static_cast<std::ptrdiff_t>(d.length) - static_cast<std::ptrdiff_t>(d.alternative);
            auto at = img.frames.begin() + static_cast<std::ptrdiff_t>(first);
            if (delta > 0)
                img.frames.insert(at, static_cast<std::size_t>(delta), d.value);
            else
                img.frames.erase(at, at - delta);
            for (auto& b : world->block_starts)
                if (b > first) b = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(b) + delta);
            shift += delta;
        }
        d.rule = joined(kept.empty() ? other : kept);
        revote_run(v, o, vote, r);
    }
    return world;
}

}  // namespace tape::detail
