// Reads aligned to a reference read: unique anchors, chained, stretches between them by dynamic
// programming, then every read's frames placed in shared columns (tape/align.hpp).
#include "tape/align.hpp"

#include <algorithm>
#include <climits>
#include <string>

#include "hashed_runs.hpp"
#include "tape/error.hpp"

namespace tape {
namespace detail {

// One run in four is kept, chosen by its hash, so the same runs in every read: anchors a few frames
// apart cover the reads as well, at a quarter of the sorting.
Runs hashed_runs(std::span<const Frame> s, std::size_t k) {
    Runs all;
    if (s.size() < k) return all;
    constexpr std::uint64_t base = 0x100000001B3ULL;
    std::uint64_t top = 1, h = 0;
    for (std::size_t i = 0; i + 1 < k; ++i) top *= base;
    all.reserve((s.size() - k + 1) / 3);  // about one run in four is kept
    std::size_t blanks = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (i >= k) {
            h -= top * (s[i - k] + 1ULL);
            blanks -= s[i - k] == blank_frame;
        }
        h = h * base + (s[i] + 1ULL);
        blanks += s[i] == blank_frame;
        std::uint64_t mixed = (h ^ (h >> 29)) * 0xBF58476D1CE4E5B9ULL;
        if (i + 1 >= k && blanks < k / 2 && (mixed >> 62) == 0)
            all.emplace_back(h, static_cast<std::int32_t>(i + 1 - k));
    }
    std::sort(all.begin(), all.end());
    return all;
}

std::size_t anchor_length(const AlignOptions& o) { return std::max<std::size_t>(o.anchor_length, 4); }

}  // namespace detail

namespace {

using detail::anchor_length;
using detail::hashed_runs;
using detail::Runs;

using Pairs = std::vector<std::pair<std::int32_t, std::int32_t>>;  // (reference frame, read frame)

// Scores: a frame misread by one hole is still the same frame, so it stays in its column; frames
// that differ more are a stain or a splice read as other frames, and stand apart from the frames the
// others read there (two gaps cost less). A gap costs most where it opens: a reader loses or adds a
// stretch at once, so one run of gaps is likelier than several, and two good reads then place a
// frame that has an equal neighbour the same way whatever damage lies further back. Frames lost next
// to frames added are one misread stretch, kept together: a gap of one kind opens a little cheaper
// next to a gap of the other.
int score(Frame a, Frame b) {
    if (a == b) return 4;
    unsigned x = a ^ b;
    return (x & (x - 1)) == 0 ? -2 : -18;  // one hole apart
}
constexpr int gap_open = -8;    // the first frame of a run of gaps
constexpr int gap_extend = -2;  // each further one
constexpr int gap_switch = -7;  // a run of gaps of one kind opening next to one of the other

// A run that occurs as many times in both reads (and no more than this) pairs its occurrences in
// order: a program punched twice, or sections repeated in it, still anchor where each copy stands.
constexpr std::size_t most_repeats = 8;

// The anchors of two reads (pairs of runs that stand for the same place of the tape), sorted, and
// how many runs could have anchored: those of each read that occur at most most_repeats times.
Pairs matching_runs(const Runs& rr, const Runs& dr, std::size_t& could, Pairs& repeated) {
    Pairs anchors;
    std::size_t ref_could = 0, read_could = 0;
    auto group_end = [](const Runs& v, std::size_t i) {
        std::size_t j = i + 1;
        while (j < v.size() && v[j].first == v[i].first) ++j;
        return j;
    };
    std::size_t x = 0, y = 0;
    while (x < rr.size() || y < dr.size()) {
        std::size_t xe = x < rr.size() ? group_end(rr, x) : x, ye = y < dr.size() ? group_end(dr, y) : y;
        bool take_x = x < rr.size() && (y >= dr.size() || rr[x].first <= dr[y].first);
        bool take_y = y < dr.size() && (x >= rr.size() || dr[y].first <= rr[x].first);
        if (take_x && xe - x <= most_repeats) ref_could += xe - x;
        if (take_y && ye - y <= most_repeats) read_could += ye - y;
        if (take_x && take_y && xe - x == ye - y && xe - x <= most_repeats)
            for (std::size_t t = 0; t < xe - x; ++t)
                (xe - x == 1 ? anchors : repeated).emplace_back(rr[x + t].second, dr[y + t].second);
        if (take_x) x = xe;
        if (take_y) y = ye;
    }
    could = std::min(ref_could, read_could);
    std::sort(anchors.begin(), anchors.end());
    std::sort(repeated.begin(), repeated.end());
    return anchors;
}

// Runs that occur more than once anchor only on the diagonals the unique runs around them keep, give or
// take the few frames a reader drops or doubles in between: where one read damaged one copy and the
// other another, pairing copies in order would pair different places, and in a program of blocks alike
// but for a digit (a drilling pattern) a copy one block away is as near as a block is long. Where no run
// is unique (a program punched twice, and nothing else), they anchor alone.
Pairs with_repeats(const Pairs& unique, const Pairs& repeated) {
    if (unique.empty()) return repeated;
    Pairs out = unique;
    for (auto [i, j] : repeated) {
        auto next = std::lower_bound(unique.begin(), unique.end(), std::make_pair(i, INT32_MIN));
        std::int64_t d = static_cast<std::int64_t>(j) - i, low = INT64_MAX, high = INT64_MIN, far = 0;
        for (auto n : {next, next == unique.begin() ? unique.end() : std::prev(next)}) {
            if (n == unique.end()) continue;
            std::int64_t nd = static_cast<std::int64_t>(n->second) - n->first;
            low = std::min(low, nd), high = std::max(high, nd);
            far = std::max<std::int64_t>(far, std::abs(static_cast<std::int64_t>(n->first) - i));
        }
        std::int64_t slack = 2 + far / 256;  // drops and doubles at 1 % of frames drift a read about this much
        if (d >= low - slack && d <= high + slack) out.emplace_back(i, j);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Anchors on one diagonal whose runs touch or overlap, as one: where both reads run alike.
struct Segment {
    std::int32_t i, j, last_i;          // the first anchor, and where the last one starts
    std::size_t first_anchor, anchors;  // in the sorted anchors
    std::int64_t diagonal() const { return static_cast<std::int64_t>(j) - i; }
};

std::vector<Segment> segments_of(const Pairs& anchors, std::int32_t k) {
    std::vector<Segment> out;
    for (std::size_t a = 0; a < anchors.size(); ++a) {
        auto [i, j] = anchors[a];
        if (!out.empty()) {
            Segment& s = out.back();
            if (j - i == s.diagonal() && i > s.last_i && i <= s.last_i + k) {
                s.last_i = i, ++s.anchors;
                continue;
            }
        }
        out.push_back({i, j, i, a, 1});
    }
    return out;
}

// The best chain of segments increasing in both reads. Each segment gains the frames its runs cover
// beyond the segment before; a change of diagonal between two costs a frame for each frame it shifts:
// a reader drops or doubles a frame or a few, so reads drift slowly, while a run that happens to recur
// nearby (the next of several lines alike, once damage made one copy unique in each read) jumps by a
// line and back, and is left out; a stretch torn out shifts once, and what follows it pays for that.
Pairs chain(const Pairs& anchors, std::int32_t k) {
    std::vector<Segment> seg = segments_of(anchors, k);
    constexpr std::size_t lookback = 64;
    constexpr std::int64_t shift_cost = 2, frames_per_point = 1;
    std::vector<std::int64_t> score(seg.size());
    std::vector<std::size_t> before(seg.size(), SIZE_MAX);
    std::size_t best = SIZE_MAX;
    for (std::size_t s = 0; s < seg.size(); ++s) {
        const std::int64_t end = seg[s].last_i + k;
        score[s] = end - seg[s].i;
        for (std::size_t t = s > lookback ? s - lookback : 0; t < s; ++t) {
            if (seg[t].i >= seg[s].i || seg[t].j >= seg[s].j || seg[t].last_i + k >= end) continue;
            std::int64_t shift = seg[s].diagonal() - seg[t].diagonal();
            std::int64_t gain = score[t] + end - std::max<std::int64_t>(seg[s].i, seg[t].last_i + k) -
                                (shift ? shift_cost + (shift < 0 ? -shift : shift) / frames_per_point : 0);
            if (gain > score[s]) score[s] = gain, before[s] = t;
        }
        if (best == SIZE_MAX || score[s] > score[best]) best = s;
    }
    Pairs out;
    for (std::size_t s = best; s != SIZE_MAX; s = before[s])
        for (std::size_t a = seg[s].first_anchor + seg[s].anchors; a-- > seg[s].first_anchor;) {
            auto [i, j] = anchors[a];
            if (j - i == seg[s].diagonal()) out.emplace_back(i, j);
        }
    std::reverse(out.begin(), out.end());
    return out;
}

// The dynamic programming's three states: a pair (M), a ref frame alone (X), a read frame alone (Y).
enum : std::uint8_t { M = 0, X = 1, Y = 2 };

// The best of the three states' scores, and which it is.
int best3(int m, int x, int y, std::uint8_t& from) {
    from = M;
    int s = m;
    if (x > s) s = x, from = X;
    if (y > s) s = y, from = Y;
    return s;
}

// From cell (i, j) in state back to the table's start, appending the pairs that stand in one column in
// order. cell(i, j): the trace byte there (the state before M, X and Y in its bits 0-1, 2-3 and 4-5).
template <typename Cell>
void trace_back(std::size_t i, std::size_t j, std::uint8_t state, std::size_t ri, std::size_t rj, Pairs& out,
                Cell cell) {
    const std::size_t first = out.size();  // the pairs come last first: turned once all are in
    while (i > 0 && j > 0) {
        std::uint8_t t = cell(i, j);
        if (state == M) {
            out.emplace_back(static_cast<std::int32_t>(ri + i - 1), static_cast<std::int32_t>(rj + j - 1));
            state = t & 3, --i, --j;
        } else if (state == X) {
            state = (t >> 2) & 3, --i;
        } else {
            state = (t >> 4) & 3, --j;
        }
    }
    std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

// A stretch between anchors too long for the whole table (no run anchors it: a long repetitive part,
// or reads that disagree long): the same alignment within a band around its diagonal, as wide as the
// reads' lengths there differ and a little more, so that time and memory grow with its length only.
void align_banded(std::span<const Frame> ref, std::span<const Frame> read, std::size_t ri, std::size_t a,
                  std::size_t rj, std::size_t b, Pairs& out) {
    constexpr int never = INT_MIN / 4;
    const std::size_t w = (a > b ? a - b : b - a) + 96, width = 2 * w + 1;
    auto lo = [&](std::size_t i) {
        std::size_t c = i * b / a;
        return c > w ? c - w : 0;
    };
    auto hi = [&](std::size_t i) { return std::min(b, i * b / a + w); };
    auto run = [](std::size_t len) { return gap_open + static_cast<int>(len - 1) * gap_extend; };
    std::vector<std::uint8_t> trace((a + 1) * width);
    std::vector<int> pm(b + 1, never), px(b + 1, never), py(b + 1, never), cm(b + 1, never), cx(b + 1, never),
        cy(b + 1, never);
    pm[0] = 0;
    for (std::size_t j = 1; j <= hi(0); ++j) py[j] = run(j);
    for (std::size_t i = 1; i <= a; ++i) {
        const std::size_t l = lo(i), h = hi(i);
        if (l == 0) cm[0] = never, cy[0] = never, cx[0] = run(i);
        const Frame f = ref[ri + i - 1];
        for (std::size_t j = std::max<std::size_t>(l, 1); j <= h; ++j) {
            std::uint8_t fm, fx, fy;
            cm[j] = best3(pm[j - 1], px[j - 1], py[j - 1], fm) + score(f, read[rj + j - 1]);
            cx[j] = best3(pm[j] + gap_open, px[j] + gap_extend, py[j] + gap_switch, fx);
            cy[j] = best3(cm[j - 1] + gap_open, cx[j - 1] + gap_switch, cy[j - 1] + gap_extend, fy);
            trace[i * width + (j - l)] = static_cast<std::uint8_t>(fm | fx << 2 | fy << 4);
        }
        // Beside this row's band, as far as the next row reads: nothing.
        if (l > 0) cm[l - 1] = cx[l - 1] = cy[l - 1] = never;
        for (std::size_t j = h + 1; j <= hi(i + 1); ++j) cm[j] = cx[j] = cy[j] = never;
        std::swap(pm, cm), std::swap(px, cx), std::swap(py, cy);
    }
    std::uint8_t state;
    best3(pm[b], px[b], py[b], state);
    trace_back(a, b, state, ri, rj, out, [&](std::size_t i, std::size_t j) { return trace[i * width + (j - lo(i))]; });
}

// Aligns ref[ri, ri + a) with read[rj, rj + b) by dynamic programming with gaps that cost most where
// they open (Gotoh), appending the pairs that stand in one column. free_start / free_end: either side
// may leave its beginning / end unpaired at no cost (leaders of different length, a read that starts
// late or stops early).
void align_stretch(std::span<const Frame> ref, std::span<const Frame> read, std::size_t ri, std::size_t a,
                   std::size_t rj, std::size_t b, bool free_start, bool free_end, std::size_t max_cells, Pairs& out) {
    if (a == 0 || b == 0) return;
    // Where one side is free, only the part of the other that can meet it is looked at.
    if (free_start && a > b + 64) ri += a - (b + 64), a = b + 64;
    if (free_start && b > a + 64) rj += b - (a + 64), b = a + 64;
    if (free_end && a > b + 64) a = b + 64;
    if (free_end && b > a + 64) b = a + 64;
    if ((a + 1) * (b + 1) > max_cells) {
        // Banded where the band stays within bounds; beyond, the frames stand in columns of their own.
        std::size_t band = 2 * ((a > b ? a - b : b - a) + 96) + 1;
        if (!free_start && !free_end && max_cells > 0 && (a + 1) * band <= 4 * max_cells)
            align_banded(ref, read, ri, a, rj, b, out);
        return;
    }
    // States: a pair (M), a reference frame unpaired (X), a read frame unpaired (Y). A cell's trace
    // holds where each state came from: bits 0-1 for M, 2-3 for X, 4-5 for Y.
    constexpr int never = INT_MIN / 4;
    auto run = [](std::size_t len) { return gap_open + static_cast<int>(len - 1) * gap_extend; };
    // Scratch kept between calls: the stretches between anchors are many and mostly a few frames long.
    thread_local std::vector<std::uint8_t> trace;
    thread_local std::vector<int> pm, px, py, cm, cx, cy;
    trace.assign((a + 1) * (b + 1), 0);
    pm.assign(b + 1, never), px.assign(b + 1, never), py.assign(b + 1, never);
    cm.assign(b + 1, 0), cx.assign(b + 1, 0), cy.assign(b + 1, 0);
    pm[0] = 0;
    for (std::size_t j = 1; j <= b; ++j) py[j] = free_start ? 0 : run(j);
    int best = never;
    std::size_t best_i = a, best_j = b;
    std::uint8_t best_state = M;
    auto consider = [&](int m, int x, int y, std::size_t i, std::size_t j) {
        std::uint8_t from;
        int s = best3(m, x, y, from);
        if (s > best) best = s, best_i = i, best_j = j, best_state = from;
    };
    if (free_end) consider(pm[b], px[b], py[b], 0, b);
    for (std::size_t i = 1; i <= a; ++i) {
        cm[0] = never, cy[0] = never, cx[0] = free_start ? 0 : run(i);
        Frame f = ref[ri + i - 1];
        for (std::size_t j = 1; j <= b; ++j) {
            std::uint8_t fm, fx, fy;
            cm[j] = best3(pm[j - 1], px[j - 1], py[j - 1], fm) + score(f, read[rj + j - 1]);
            cx[j] = best3(pm[j] + gap_open, px[j] + gap_extend, py[j] + gap_switch, fx);
            cy[j] = best3(cm[j - 1] + gap_open, cx[j - 1] + gap_switch, cy[j - 1] + gap_extend, fy);
            trace[i * (b + 1) + j] = static_cast<std::uint8_t>(fm | fx << 2 | fy << 4);
        }
        if (free_end) consider(cm[b], cx[b], cy[b], i, b);
        std::swap(pm, cm), std::swap(px, cx), std::swap(py, cy);
    }
    if (free_end) {
        for (std::size_t j = 0; j <= b; ++j) consider(pm[j], px[j], py[j], a, j);
    } else {
        best3(pm[b], px[b], py[b], best_state);
    }
    trace_back(best_i, best_j, best_state, ri, rj, out,
               [&](std::size_t i, std::size_t j) { return trace[i * (b + 1) + j]; });
}

// The pairs of ref and read frames that stand in one column, in order.
// ref_runs: hashed_runs(ref, anchor_length(o)).
Pairs pair_up(std::span<const Frame> ref, const Runs& ref_runs, std::span<const Frame> read, const AlignOptions& o,
              double& anchored_share) {
    const std::size_t k = anchor_length(o);
    std::size_t could = 0;
    Pairs repeated;
    Pairs unique = matching_runs(ref_runs, hashed_runs(read, k), could, repeated);
    Pairs runs, chained = chain(with_repeats(chain(unique, static_cast<std::int32_t>(k)), repeated),
                                static_cast<std::int32_t>(k));
    // How much of what could anchor did: runs that occur as often in each read, in order.
    anchored_share = could ? std::min(1.0, static_cast<double>(chained.size()) / static_cast<double>(could)) : 0;
    // Each anchor's frames, checked (a hash may collide), become pairs on its diagonal.
    std::int32_t last_i = -1, last_j = -1;
    for (auto [i, j] : chained)
        for (std::int32_t t = 0; t < static_cast<std::int32_t>(k); ++t)
            if (i + t > last_i && j + t > last_j && ref[i + t] == read[j + t]) {
                runs.emplace_back(i + t, j + t);
                last_i = i + t, last_j = j + t;
            }
    Pairs out;
    out.reserve(read.size());
    std::size_t pi = 0, pj = 0;  // the next unpaired frame of each
    for (std::size_t r = 0; r <= runs.size(); ++r) {
        bool end = r == runs.size();
        std::size_t ni = end ? ref.size() : static_cast<std::size_t>(runs[r].first);
        std::size_t nj = end ? read.size() : static_cast<std::size_t>(runs[r].second);
        align_stretch(ref, read, pi, ni - pi, pj, nj - pj, r == 0, end, o.max_cells, out);
        if (end) break;
        out.push_back(runs[r]);
        pi = ni + 1, pj = nj + 1;
    }
    return out;
}

// partner[k] is the index of frame k's partner on the other side, or none. A frame with no partner
// (a gap on the other side) just before an equal frame that has one moves to after it, so that the gap
// of a frame read twice, or lost from a run, stands at the end of the run of equal frames: the same
// place in every read, one column. A gap next to unpaired frames of the other side is part of a
// misread stretch, and the last of a run of gaps part of a stretch lost: they stay where they are.
void gaps_to_end_of_runs(std::span<const Frame> side, std::vector<std::int32_t>& partner) {
    std::int32_t last = -1;  // the partner of the last paired frame
    for (std::size_t k = 0; k + 1 < side.size(); ++k) {
        if (partner[k] == ReadAlignment::none && partner[k + 1] == last + 1 && side[k] == side[k + 1] &&
            (k == 0 || partner[k - 1] != ReadAlignment::none))
            std::swap(partner[k], partner[k + 1]);
        if (partner[k] != ReadAlignment::none) last = partner[k];
    }
}

// Every reference frame's partner in read (or none), from the pairs, gaps moved to the ends of runs on
// both sides (a read that has a frame twice, and a reference that has).
std::vector<std::int32_t> partners(std::span<const Frame> ref, std::span<const Frame> read, const Pairs& pairs) {
    std::vector<std::int32_t> match(read.size(), ReadAlignment::none);
    for (auto [i, j] : pairs) match[static_cast<std::size_t>(j)] = i;
    gaps_to_end_of_runs(read, match);
    std::vector<std::int32_t> at(ref.size(), ReadAlignment::none);
    for (std::size_t j = 0; j < read.size(); ++j)
        if (match[j] != ReadAlignment::none) at[static_cast<std::size_t>(match[j])] = static_cast<std::int32_t>(j);
    gaps_to_end_of_runs(ref, at);
    return at;
}

// A run of read frames that no reference frame is paired with: they stand before reference frame
// `before` (the reference's length: after its last).
struct Insert {
    std::size_t before;
    std::int32_t start, count;
};

std::vector<Insert> inserts_of(const std::vector<std::int32_t>& at, std::size_t read_size) {
    std::vector<Insert> out;
    std::size_t j = 0;
    for (std::size_t i = 0; i <= at.size(); ++i) {
        if (i < at.size() && at[i] == ReadAlignment::none) continue;
        std::size_t to = i < at.size() ? static_cast<std::size_t>(at[i]) : read_size;
        if (to > j) out.push_back({i, static_cast<std::int32_t>(j), static_cast<std::int32_t>(to - j)});
        j = std::max(j, to + 1);
    }
    return out;
}

// Appends the columns: one per reference frame, and before it the reads' inserts, the t-th frame of
// every read's insert in one column. offset[r] is added to read r's frame indices.
void add_columns(ReadAlignment& out, std::size_t n, const std::vector<std::vector<std::int32_t>>& at,
                 const std::vector<std::vector<Insert>>& inserts, std::span<const std::int32_t> offset) {
    const std::size_t reads = at.size();
    std::vector<std::int32_t> column(reads);
    std::vector<std::size_t> next(reads, 0);  // each read's next insert
    std::vector<const Insert*> here(reads);
    auto global = [&](std::size_t r, std::int32_t i) { return i == ReadAlignment::none ? i : i + offset[r]; };
    for (std::size_t i = 0; i <= n; ++i) {
        std::int32_t extra = 0;
        for (std::size_t r = 0; r < reads; ++r) {
            here[r] = next[r] < inserts[r].size() && inserts[r][next[r]].before == i ? &inserts[r][next[r]++] : nullptr;
            if (here[r]) extra = std::max(extra, here[r]->count);
        }
        for (std::int32_t t = 0; t < extra; ++t) {
            for (std::size_t r = 0; r < reads; ++r)
                column[r] = here[r] && t < here[r]->count ? global(r, here[r]->start + t) : ReadAlignment::none;
            out.add_column(column);
        }
        if (i == n) break;
        for (std::size_t r = 0; r < reads; ++r) column[r] = global(r, at[r][i]);
        out.add_column(column);
    }
}

// The reads' frames in a stretch where they disagree, aligned again around the read that agrees best
// with the others there: the global reference may have garbled just this stretch, and frames other
// reads have right would then stand in columns of their own, one per read, and be outvoted.
void realign_window(std::span<const std::span<const Frame>> reads, std::span<const std::int32_t> lo,
                    std::span<const std::int32_t> len, ReadAlignment& out) {
    const std::size_t n_reads = reads.size();
    std::vector<std::span<const Frame>> seq(n_reads);
    for (std::size_t r = 0; r < n_reads; ++r)
        seq[r] = reads[r].subspan(static_cast<std::size_t>(lo[r]), static_cast<std::size_t>(len[r]));
    auto pairs_of = [&](std::size_t c, std::size_t r) {
        Pairs p;
        align_stretch(seq[c], seq[r], 0, seq[c].size(), 0, seq[r].size(), false, false, SIZE_MAX, p);
        return p;
    };
    // The centre: the read that aligns best with all the others (the sum of the alignments' scores).
    auto total = [&](std::size_t c, std::size_t r, const Pairs& p) {
        int sum = 0;
        std::int32_t pi = -1, pj = -1;
        auto gaps = [&](std::int32_t from, std::int32_t to) {
            return to > from ? gap_open + (to - from - 1) * gap_extend : 0;
        };
        for (auto [i, j] : p) {
            sum += score(seq[c][static_cast<std::size_t>(i)], seq[r][static_cast<std::size_t>(j)]);
            sum += gaps(pi + 1, i) + gaps(pj + 1, j);
            pi = i, pj = j;
        }
        return sum + gaps(pi + 1, static_cast<std::int32_t>(seq[c].size())) +
               gaps(pj + 1, static_cast<std::int32_t>(seq[r].size()));
    };
    std::size_t centre = 0;
    int best = INT_MIN;
    std::vector<std::vector<Pairs>> all(n_reads, std::vector<Pairs>(n_reads));
    for (std::size_t c = 0; c < n_reads; ++c) {
        int sum = 0;
        for (std::size_t r = 0; r < n_reads; ++r) {
            if (r == c) continue;
            all[c][r] = pairs_of(c, r);
            sum += total(c, r, all[c][r]);
        }
        if (sum > best) best = sum, centre = c;
    }
    std::vector<std::vector<std::int32_t>> at(n_reads);
    std::vector<std::vector<Insert>> inserts(n_reads);
    for (std::size_t r = 0; r < n_reads; ++r) {
        if (r == centre) {
            at[r].resize(seq[r].size());
            for (std::size_t i = 0; i < seq[r].size(); ++i) at[r][i] = static_cast<std::int32_t>(i);
        } else {
            at[r] = partners(seq[centre], seq[r], all[centre][r]);
            inserts[r] = inserts_of(at[r], seq[r].size());
        }
    }
    add_columns(out, seq[centre].size(), at, inserts, lo);
}

// The alignment with every stretch where the reads disagree aligned again (realign_window). Stretches
// at a read's start or end, and long ones (a leader, a torn stretch), are kept as they are.
// The end of the stretch of disagreement starting at column c. A frame that happens to equal a neighbour
// can stand solid inside one slip (a stain read as "39" next to a real "39"): short solid runs between
// disagreements are part of the stretch.
std::size_t stretch_end(std::span<const std::span<const Frame>> reads, const ReadAlignment& a, std::size_t c) {
    constexpr std::size_t bridged = 2;
    auto solid = [&](std::size_t x) { return unanimous(a, reads, x); };
    std::size_t end = c;
    for (;;) {
        while (end < a.columns() && !solid(end)) ++end;
        std::size_t next = end;
        while (next < a.columns() && next - end <= bridged && solid(next)) ++next;
        if (next == end || next >= a.columns() || next - end > bridged) return end;
        end = next;
    }
}

ReadAlignment refine(std::span<const std::span<const Frame>> reads, const ReadAlignment& a) {
    constexpr std::int32_t longest = 64;
    const std::size_t n_reads = a.reads();
    ReadAlignment out(n_reads, a.reference());
    out.take_read_facts(a);
    out.reserve(a.columns() + a.columns() / 64);
    auto solid = [&](std::size_t c) { return unanimous(a, reads, c); };
    std::vector<std::int32_t> column(n_reads), lo(n_reads), len(n_reads);
    auto copy = [&](std::size_t c) {
        for (std::size_t r = 0; r < n_reads; ++r) column[r] = a.frame(c, r);
        out.add_column(column);
    };
    for (std::size_t c = 0; c < a.columns();) {
        if (solid(c)) {
            copy(c++);
            continue;
        }
        std::size_t end = stretch_end(reads, a, c);
        // Every read covers the whole stretch, or none of it; each has a few frames in it.
        bool simple = true;
        for (std::size_t r = 0; r < n_reads && simple; ++r) {
            bool in = a.covers(r, c), whole = a.covers(r, end - 1) && c > a.first_column(r) && end < a.end_column(r);
            if (in != a.covers(r, end - 1) || (in && !whole)) simple = false;
            lo[r] = 0, len[r] = 0;
            for (std::size_t x = c; x < end && simple; ++x) {
                std::int32_t i = a.frame(x, r);
                if (i == ReadAlignment::none) continue;
                if (len[r] == 0) lo[r] = i;
                ++len[r];
            }
            if (len[r] > longest) simple = false;
        }
        std::size_t with_frames = 0;
        for (std::size_t r = 0; r < n_reads; ++r) with_frames += len[r] > 0;
        if (!simple || with_frames < 2) {
            for (; c < end; ++c) copy(c);
            continue;
        }
        std::vector<std::span<const Frame>> covering;
        std::vector<std::size_t> which;
        std::vector<std::int32_t> clo, clen;
        for (std::size_t r = 0; r < n_reads; ++r)
            if (a.covers(r, c))
                which.push_back(r), covering.push_back(reads[r]), clo.push_back(lo[r]), clen.push_back(len[r]);
        ReadAlignment local(which.size(), 0);
        realign_window(covering, clo, clen, local);
        for (std::size_t x = 0; x < local.columns(); ++x) {
            std::fill(column.begin(), column.end(), ReadAlignment::none);
            for (std::size_t k = 0; k < which.size(); ++k) column[which[k]] = local.frame(x, k);
            out.add_column(column);
        }
        c = end;
    }
    out.finish();
    return out;
}

// Dynamic programming sets a frame that differs in more than one hole apart from the frame another
// read has there (two gaps). Where the reads that have frames in a run of columns and those that have
// frames in the next run are the two halves of the reads covering them, and the runs are as long,
// the reads saw different frames in the same places: those columns are one.
ReadAlignment merge_substitutions(const ReadAlignment& a) {
    const std::size_t n = a.reads();
    ReadAlignment out(n, a.reference());
    out.take_read_facts(a);
    out.reserve(a.columns());
    auto same_reads = [&](std::size_t x, std::size_t y) {
        for (std::size_t r = 0; r < n; ++r)
            if ((a.frame(x, r) == ReadAlignment::none) != (a.frame(y, r) == ReadAlignment::none)) return false;
        return true;
    };
    auto halves = [&](std::size_t x, std::size_t y) {
        for (std::size_t r = 0; r < n; ++r) {
            bool in_x = a.frame(x, r) != ReadAlignment::none, in_y = a.frame(y, r) != ReadAlignment::none;
            bool covers = a.covers(r, x) && a.covers(r, y);
            if ((in_x && in_y) || (covers && !in_x && !in_y) || (!covers && (in_x || in_y))) return false;
        }
        return true;
    };
    std::vector<std::int32_t> column(n);
    for (std::size_t c = 0; c < a.columns();) {
        std::size_t run = c + 1;
        while (run < a.columns() && same_reads(c, run)) ++run;
        std::size_t len = run - c, next = run;
        while (next < a.columns() && next - run < len && same_reads(run, next)) ++next;
        if (next - run == len && (next == a.columns() || !same_reads(run, next)) && halves(c, run)) {
            for (std::size_t k = 0; k < len; ++k) {
                for (std::size_t r = 0; r < n; ++r) {
                    std::int32_t i = a.frame(c + k, r);
                    column[r] = i != ReadAlignment::none ? i : a.frame(run + k, r);
                }
                out.add_column(column);
            }
            c = next;
            continue;
        }
        for (; c < run; ++c) {
            for (std::size_t r = 0; r < n; ++r) column[r] = a.frame(c, r);
            out.add_column(column);
        }
    }
    out.finish();
    return out;
}

}  // namespace

bool unanimous(const ReadAlignment& a, std::span<const std::span<const Frame>> reads, std::size_t column) {
    std::optional<Frame> first;
    for (std::size_t r = 0; r < a.reads(); ++r) {
        if (!a.covers(r, column)) continue;
        auto f = frame_at(a, reads, column, r);
        if (!f || (first && *first != *f)) return false;
        first = f;
    }
    return true;
}

void ReadAlignment::add_column(std::span<const std::int32_t> column) {
    cells_.insert(cells_.end(), column.begin(), column.end());
}

void ReadAlignment::finish() {
    first_.assign(reads_, columns());
    end_.assign(reads_, 0);
    for (std::size_t c = 0; c < columns(); ++c)
        for (std::size_t r = 0; r < reads_; ++r)
            if (frame(c, r) != none) {
                first_[r] = std::min(first_[r], c);
                end_[r] = c + 1;
            }
    for (std::size_t r = 0; r < reads_; ++r)
        if (first_[r] > end_[r]) first_[r] = end_[r];
}

namespace {

// Every read set against one reference read: its frame in each reference column, its runs of frames
// between reference frames (few: kept as a list, not a column each), and how much it shares.
struct AgainstReference {
    std::size_t ref = 0;
    std::vector<std::vector<std::int32_t>> at;
    std::vector<std::vector<Insert>> inserts;
    std::vector<double> shared, anchored;
    std::vector<bool> related;
    std::size_t unrelated = 0;
};

std::size_t punched_count(std::span<const Frame> s) {
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](Frame f) { return f != blank_frame; }));
}

AgainstReference against(std::span<const std::span<const Frame>> reads, std::size_t ref, const AlignOptions& o) {
    AgainstReference out;
    const std::size_t n_reads = reads.size(), n = reads[ref].size();
    out.ref = ref;
    out.at.resize(n_reads), out.inserts.resize(n_reads);
    out.shared.assign(n_reads, 1.0), out.anchored.assign(n_reads, 1.0), out.related.assign(n_reads, true);
    const auto& rf = reads[ref];
    const Runs ref_runs = n_reads > 1 ? hashed_runs(rf, anchor_length(o)) : Runs{};
    for (std::size_t r = 0; r < n_reads; ++r) {
        // The reference, and reads identical to it (a tape read twice without a fault), stand frame by
        // frame in its columns.
        if (r == ref || std::equal(rf.begin(), rf.end(), reads[r].begin(), reads[r].end())) {
            out.at[r].resize(n);
            for (std::size_t i = 0; i < n; ++i) out.at[r][i] = static_cast<std::int32_t>(i);
            continue;
        }
        out.at[r] = partners(rf, reads[r], pair_up(rf, ref_runs, reads[r], o, out.anchored[r]));
        std::size_t same = 0;
        // Shared punched frames: blank leader and trailer match on every tape and prove nothing.
        for (std::size_t i = 0; i < n; ++i)
            if (out.at[r][i] != ReadAlignment::none)
                same += rf[i] != blank_frame && rf[i] == reads[r][static_cast<std::size_t>(out.at[r][i])];
        std::size_t shorter = std::min(punched_count(rf), punched_count(reads[r]));
        out.shared[r] = shorter ? static_cast<double>(same) / static_cast<double>(shorter) : 0;
        // Two programs share many characters wherever dynamic programming may pair them, but few long
        // runs that occur as often in each; reads of one tape share both. A short tape with much damage
        // has few such runs left, but its frames still agree nearly all.
        if (out.anchored[r] < o.min_shared && out.shared[r] < 0.8) {
            out.related[r] = false;
            ++out.unrelated;
            out.at[r].assign(n, ReadAlignment::none);
            continue;
        }
        out.inserts[r] = inserts_of(out.at[r], reads[r].size());
    }
    return out;
}

// The reference: the longest read, unless it is related to fewer than half of the others (it is the
// read of another tape); then the longest of those it is not related to, and so on.
AgainstReference choose_reference(std::span<const std::span<const Frame>> reads, const AlignOptions& o) {
    std::vector<std::size_t> order(reads.size());
    for (std::size_t r = 0; r < reads.size(); ++r) order[r] = r;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return reads[x].size() > reads[y].size(); });
    AgainstReference best = against(reads, order.front(), o);
    constexpr std::size_t most_tries = 3;
    for (std::size_t tries = 1; tries < most_tries && best.unrelated * 2 > reads.size() - 1; ++tries) {
        auto next = std::find_if(order.begin(), order.end(), [&](std::size_t r) { return !best.related[r]; });
        if (next == order.end()) break;
        AgainstReference other = against(reads, *next, o);
        if (other.unrelated >= best.unrelated) break;
        best = std::move(other);
    }
    return best;
}

std::string percent_text(double share) { return std::to_string(static_cast<int>(share * 100)) + "%"; }

}  // namespace

UnrelatedRead::UnrelatedRead(std::size_t read, std::size_t reference, double anchored)
    : Error(Errc::bad_image, "read " + std::to_string(read + 1) + " shares runs of frames with read " +
                                 std::to_string(reference + 1) + " over only " + percent_text(anchored) +
                                 " of the runs that occur as often in each: they are reads of different tapes, or "
                                 "too damaged to align"),
      read_(read),
      reference_(reference),
      anchored_(anchored) {}

ReadAlignment align_reads(std::span<const std::span<const Frame>> reads, const AlignOptions& o) {
    if (reads.empty()) throw Error(Errc::usage, "no reads to align");
    for (std::size_t r = 0; r < reads.size(); ++r)
        if (reads[r].size() > max_tape_frames)
            throw Error(Errc::usage, "read " + std::to_string(r + 1) + " has " + std::to_string(reads[r].size()) +
                                         " frames, more than the " + std::to_string(max_tape_frames) +
                                         " (254 km of tape) reads are aligned to");
    if (std::all_of(reads.begin(), reads.end(), [](std::span<const Frame> r) { return r.empty(); }))
        throw Error(Errc::bad_image, "no read holds any frame");
    AgainstReference w = choose_reference(reads, o);
    if (w.unrelated > 0 && !o.drop_unrelated)
        for (std::size_t r = 0; r < reads.size(); ++r)
            if (!w.related[r]) throw UnrelatedRead(r, w.ref, w.anchored[r]);
    ReadAlignment out(reads.size(), w.ref);
    std::size_t inserted = 0;  // frames standing between reference frames: at most this many more columns
    for (const auto& ins : w.inserts)
        for (const auto& i : ins) inserted += static_cast<std::size_t>(i.count);
    out.reserve(reads[w.ref].size() + inserted);
    for (std::size_t r = 0; r < reads.size(); ++r) {
        out.set_shared(r, w.related[r] ? w.shared[r] : 0);
        out.set_related(r, w.related[r]);
    }
    std::vector<std::int32_t> no_offset(reads.size(), 0);
    add_columns(out, reads[w.ref].size(), w.at, w.inserts, no_offset);
    out.finish();
    if (reads.size() - w.unrelated == 1) return out;
    // Memory: no more than two alignments at a time (5 reads of 10^6 frames: 20 MB each).
    w = {};
    ReadAlignment refined = refine(reads, out);
    out = ReadAlignment(0, 0);
    return merge_substitutions(refined);
}

}  // namespace tape
