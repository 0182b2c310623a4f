// What is left out of the reads before they are aligned (read_cuts.hpp).
#include "read_cuts.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <optional>

#include "hashed_runs.hpp"

namespace tape::detail {
namespace {

// Of a stretch left out, this many frames are kept at each side: the vote still sees the stretch, and
// says where it was, as it would with all of it.
constexpr std::size_t margin = 1000;

// Moves a read's doubts (counted from 1) as its frames [from, to) (counted from 0) are left out: those
// in the stretch go, those after it move back; size: the read's frames after the cut.
void cut_doubts(std::vector<FrameDoubt>& runs, std::uint64_t from, std::uint64_t to, std::uint64_t size) {
    const std::uint64_t gone = to - from;
    std::vector<FrameDoubt> kept;
    for (auto d : runs) {
        std::uint64_t first = d.first <= from ? d.first : d.first > to ? d.first - gone : from + 1;
        std::uint64_t last = d.last > to ? d.last - gone : std::min(d.last, from);
        first = std::max<std::uint64_t>(first, 1), last = std::min(last, size);
        if (first > last) continue;
        d.first = first, d.last = last;
        kept.push_back(std::move(d));
    }
    runs = std::move(kept);
}

std::size_t blank_at(std::span<const Frame> r, bool start) {
    auto blank = [](Frame f) { return f == blank_frame; };
    return start ? static_cast<std::size_t>(std::find_if_not(r.begin(), r.end(), blank) - r.begin())
                 : static_cast<std::size_t>(std::find_if_not(r.rbegin(), r.rend(), blank) - r.rbegin());
}

// Blank frames a read has at an end beyond the longest blank end of the other reads, and the margin
// more, are left out: their length follows the majority of the reads in any case.
void trim_blank_ends(std::vector<std::span<const Frame>>& reads, std::vector<FrameDoubts>& doubts) {
    for (bool start : {true, false}) {
        std::vector<std::size_t> blank;
        for (const auto& r : reads) blank.push_back(std::min(blank_at(r, start), r.size()));
        for (std::size_t r = 0; r < reads.size(); ++r) {
            std::size_t others = 0;
            for (std::size_t k = 0; k < reads.size(); ++k)
                if (k != r) others = std::max(others, blank[k]);
            if (blank[r] <= others + margin || blank[r] == reads[r].size()) continue;
            const std::size_t cut = blank[r] - others - margin, before = reads[r].size();
            reads[r] = start ? reads[r].subspan(cut) : reads[r].first(before - cut);
            if (doubts.size() != reads.size()) continue;  // refused by the vote, as given
            cut_doubts(doubts[r].runs, start ? 0 : before - cut, start ? cut : before, before - cut);
        }
    }
}

// The runs a read shares with another read, each as (place in the read, hash).
using Places = std::vector<std::pair<std::int32_t, std::uint64_t>>;
void add_shared(const Runs& of, const Runs& in, Places& out) {
    std::size_t y = 0;
    for (const auto& [hash, place] : of) {
        while (y < in.size() && in[y].first < hash) ++y;
        if (y < in.size() && in[y].first == hash) out.emplace_back(place, hash);
    }
}

// Where read s has run h (its runs sorted by hash, then place).
std::pair<Runs::const_iterator, Runs::const_iterator> places_of(const Runs& runs, std::uint64_t h) {
    return {std::lower_bound(runs.begin(), runs.end(), std::make_pair(h, INT32_MIN)),
            std::upper_bound(runs.begin(), runs.end(), std::make_pair(h, INT32_MAX))};
}

// A run a read has more often than this says nothing of where it is (a line repeated, a run of spaces).
constexpr std::ptrdiff_t most_repeats = 8;

// From `at` (a run read r shares with read s), stepping by `step` through `with` (at most 64 times), the
// first run s has at most `most` times, or the last one looked at.
Places::const_iterator rare_from(const Runs& runs, const Places& with, Places::const_iterator at, int step,
                                 std::ptrdiff_t most) {
    for (int n = 0; n < 64; ++n) {
        auto [first, end] = places_of(runs, at->second);
        if (end - first <= most || (step < 0 ? at == with.begin() : at + 1 == with.end())) break;
        at += step;
    }
    return at;
}

// Whether a read whose runs are `runs` goes from the run `before` to the run `after` within `most`
// frames. A run it has many times decides nothing.
bool goes_on_past(const Runs& runs, std::uint64_t before, std::uint64_t after, std::size_t most) {
    auto [b0, b1] = places_of(runs, before);
    auto [a0, a1] = places_of(runs, after);
    if (b1 - b0 > most_repeats || a1 - a0 > most_repeats) return false;
    for (auto b = b0; b != b1; ++b)
        for (auto a = a0; a != a1; ++a)
            if (a->second > b->second && static_cast<std::size_t>(a->second - b->second) <= most) return true;
    return false;
}

// Whether read s (its runs; with: those read r shares with it, by place in r) lacks what r has between
// its places p and q: from the last run it shares with r before that stretch to the first after it, s
// has no more frames than r has there outside the stretch, and the margin. Each read is asked about its
// own runs: damage in one read does not hide a stretch another read lacks.
bool lacks(const Runs& runs, const Places& with, std::int32_t p, std::int32_t q) {
    auto after = std::lower_bound(with.begin(), with.end(), std::make_pair(q, std::uint64_t{0}));
    if (after == with.end() || after == with.begin()) return false;
    auto before = rare_from(runs, with, std::prev(after), -1, most_repeats);  // at p or before
    after = rare_from(runs, with, after, 1, most_repeats);
    const auto outside = static_cast<std::size_t>((p - before->first) + (after->first - q));
    return goes_on_past(runs, before->second, after->second, outside + margin);
}

using Stretch = std::pair<std::size_t, std::size_t>;  // [from, to) of a read

// The frames read r has before the first run it shares with the others (start) or after the last, where
// every other read has its own first (last) run shared with r once, and past it no more than its blank
// end, the margin and what r has between the two: a reader that ran on over other tape. All but the
// margin and what the others have there.
std::optional<Stretch> unmatched_end(std::size_t r, const CutReads& in, const std::vector<Runs>& runs,
                                     const std::vector<Places>& with, const Places& shared, std::size_t k, bool start) {
    if (shared.empty()) return std::nullopt;
    const auto place = static_cast<std::size_t>((start ? shared.front() : shared.back()).first);
    std::size_t others = 0;  // the most frames another read has past r's first (last) shared run
    for (std::size_t s = 0; s < runs.size(); ++s) {
        if (s == r) continue;
        if (with[s].empty()) return std::nullopt;
        const auto [mine, hash] =
            *rare_from(runs[s], with[s], start ? with[s].begin() : std::prev(with[s].end()), start ? 1 : -1, 1);
        auto [at, end] = places_of(runs[s], hash);
        if (end - at != 1) return std::nullopt;
        const auto there = static_cast<std::size_t>(at->second), between = start ? mine - place : place - mine;
        std::size_t past = start ? there : in.reads[s].size() - there - k;
        past = past > between ? past - between : 0;
        if (past > blank_at(in.reads[s], start) + margin) return std::nullopt;
        others = std::max(others, past);
    }
    const std::size_t size = in.reads[r].size(), mine = start ? place : size - place - k;
    if (mine < others + 2 * margin) return std::nullopt;
    const std::size_t cut = mine - others - margin;
    return start ? Stretch(0, cut) : Stretch(size - cut, size);
}

// The stretches of read r to leave out, in order: at its ends (unmatched_end), and between two runs it
// shares with the others, farther apart than two margins and as much again, that every other read
// lacks. k: the runs' length.
std::vector<Stretch> unmatched_in(std::size_t r, const CutReads& in, const std::vector<Runs>& runs, std::size_t k) {
    std::vector<Places> with(runs.size());
    Places shared;
    for (std::size_t s = 0; s < runs.size(); ++s) {
        if (s == r) continue;
        add_shared(runs[r], runs[s], with[s]);
        std::sort(with[s].begin(), with[s].end());
        shared.insert(shared.end(), with[s].begin(), with[s].end());
    }
    std::sort(shared.begin(), shared.end());
    shared.erase(std::unique(shared.begin(), shared.end()), shared.end());
    std::vector<Stretch> out;
    if (auto cut = unmatched_end(r, in, runs, with, shared, k, true)) out.push_back(*cut);
    for (std::size_t i = 1; i < shared.size(); ++i) {
        const std::int32_t p = shared[i - 1].first, q = shared[i].first;
        if (static_cast<std::size_t>(q - p) < k + 3 * margin) continue;
        bool others_lack = true;
        for (std::size_t s = 0; s < runs.size() && others_lack; ++s)
            others_lack = s == r || lacks(runs[s], with[s], p, q);
        if (others_lack)
            out.emplace_back(static_cast<std::size_t>(p) + k + margin, static_cast<std::size_t>(q) - margin);
    }
    if (auto cut = unmatched_end(r, in, runs, with, shared, k, false)) out.push_back(*cut);
    return out;
}

// Read r without the stretches cut (in order), kept in out, its doubts moved.
void cut_stretches(std::size_t r, const std::vector<Stretch>& cuts, CutReads& out, std::vector<FrameDoubts>& doubts) {
    const std::span<const Frame> read = out.reads[r];
    std::vector<Frame> frames;
    std::size_t from = 0, size = read.size();
    for (auto [cut_from, cut_to] : cuts) {
        frames.insert(frames.end(), read.begin() + static_cast<std::ptrdiff_t>(from),
                      read.begin() + static_cast<std::ptrdiff_t>(cut_from));
        from = cut_to;
        out.unmatched += cut_to - cut_from;
    }
    frames.insert(frames.end(), read.begin() + static_cast<std::ptrdiff_t>(from), read.end());
    // From the last cut back, so that the places of those before stay as they were.
    for (auto c = cuts.rbegin(); c != cuts.rend() && doubts.size() == out.reads.size(); ++c) {
        size -= c->second - c->first;
        cut_doubts(doubts[r].runs, c->first, c->second, size);
    }
    out.kept.push_back(std::move(frames));
    out.reads[r] = out.kept.back();
}

}  // namespace

CutReads cut_reads(std::span<const std::span<const Frame>> reads, std::vector<FrameDoubts>& doubts,
                   const AlignOptions& o) {
    CutReads out;
    out.reads.assign(reads.begin(), reads.end());
    if (reads.size() < 2) return out;
    trim_blank_ends(out.reads, doubts);
    // A stretch one read has is left out only where the reads that lack it outvote it: two at least.
    if (reads.size() < 3) return out;
    // A read holds such a stretch only where it is longer than another read by two margins or so: reads
    // of one tape alike in length are not hashed again (five reads of 10^6 frames: 1.2 s, 2.0 s with it).
    std::size_t shortest = SIZE_MAX, longest = 0;
    for (const auto& r : out.reads) shortest = std::min(shortest, r.size()), longest = std::max(longest, r.size());
    if (longest < shortest + 2 * margin) return out;
    const std::size_t k = anchor_length(o);
    std::vector<Runs> runs;
    for (const auto& r : out.reads) runs.push_back(hashed_runs(r, k));
    std::vector<std::vector<Stretch>> cuts(reads.size());
    for (std::size_t r = 0; r < reads.size(); ++r)
        if (out.reads[r].size() >= shortest + 2 * margin) cuts[r] = unmatched_in(r, out, runs, k);
    runs = {};
    out.kept.reserve(reads.size());  // reads points into them: never moved
    for (std::size_t r = 0; r < reads.size(); ++r)
        if (!cuts[r].empty()) cut_stretches(r, cuts[r], out, doubts);
    return out;
}

}  // namespace tape::detail
