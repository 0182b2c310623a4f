// The final check of a restoration (vote.hpp): no stretch that most reads hold is left out of the
// image. Where the alignment set such a stretch apart (each read's copy in columns of its own, every
// column then outvoted), it is written as one of those reads has it, and in doubt.
#include <algorithm>

#include "vote.hpp"

namespace tape::detail {
namespace {

constexpr std::size_t shared_run = 4;  // frames two copies of a stretch share at least, in a row

// The frames read r has in columns [first, end), with their columns.
std::vector<std::pair<Frame, std::size_t>> frames_in(const VoteContext& v, std::size_t r, std::size_t first,
                                                     std::size_t end) {
    std::vector<std::pair<Frame, std::size_t>> out;
    for (std::size_t c = first; c < end; ++c)
        if (auto f = frame_at(v.a, v.reads, c, r)) out.emplace_back(*f, c);
    return out;
}

// True when x and y hold the same shared_run frames in a row somewhere.
bool share_a_run(const std::vector<std::pair<Frame, std::size_t>>& x,
                 const std::vector<std::pair<Frame, std::size_t>>& y) {
    for (std::size_t i = 0; i + shared_run <= x.size(); ++i)
        for (std::size_t j = 0; j + shared_run <= y.size(); ++j) {
            std::size_t k = 0;
            while (k < shared_run && x[i + k].first == y[j + k].first) ++k;
            if (k == shared_run) return true;
        }
    return false;
}

// A stretch of columns none of which is written: when most reads that cover it hold copies that agree,
// the copy of the read that agrees with most others is written, in doubt.
void check_stretch(const VoteContext& v, VoteResult& out, std::size_t first, std::size_t end) {
    constexpr std::size_t longest = 4096;  // beyond this a stretch is a torn piece, not a misplaced copy
    if (end - first < shared_run || end - first > longest) return;
    std::vector<std::vector<std::pair<Frame, std::size_t>>> copies;
    std::size_t covering = 0;
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        if (!v.a.covers(r, first) || !v.a.covers(r, end - 1)) continue;
        ++covering;
        auto f = frames_in(v, r, first, end);
        if (f.size() >= shared_run) copies.push_back(std::move(f));
    }
    std::size_t best = 0, best_agree = 0;
    for (std::size_t i = 0; i < copies.size(); ++i) {
        std::size_t agree = 1;
        for (std::size_t j = 0; j < copies.size(); ++j) agree += j != i && share_a_run(copies[i], copies[j]);
        if (agree > best_agree) best_agree = agree, best = i;
    }
    if (best_agree < 2 || best_agree * 2 <= covering) return;
    for (const auto& [frame, c] : copies[best]) {
        Verdict& d = out.verdicts[c];
        d.write = true;
        d.written = frame;
        d.status = FrameStatus::contested;
        RestoreProblem& p = out.problems[static_cast<std::size_t>(d.problem)];
        p.status = FrameStatus::contested;
        p.written = frame;
        p.run_length = false;
        p.reason = std::to_string(best_agree) + " of " + std::to_string(covering) +
                   " reads hold this stretch, but the alignment set their copies apart: written as one of them has "
                   "it, in doubt";
    }
}

}  // namespace

void keep_stretches_most_reads_hold(const VoteContext& v, VoteResult& out) {
    for (std::size_t c = 0; c < out.verdicts.size();) {
        if (out.verdicts[c].write) {
            ++c;
            continue;
        }
        std::size_t end = c;
        while (end < out.verdicts.size() && !out.verdicts[end].write) ++end;
        check_stretch(v, out, c, end);
        c = end;
    }
}

}  // namespace tape::detail
