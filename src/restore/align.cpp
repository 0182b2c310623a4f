// Reads aligned to a reference read: unique anchors, chained, stretches between them by dynamic
// programming, then every read's frames placed in shared columns (tape/align.hpp).
#include "tape/align.hpp"

#include <algorithm>
#include <bit>
#include <string>

#include "tape/error.hpp"

namespace tape {
namespace {

using Pairs = std::vector<std::pair<std::int32_t, std::int32_t>>;  // (reference frame, read frame)

// Scores: a frame misread by one hole is still the same frame, so a substitution costs less than a
// gap on each side; a frame unlike any other (a stain) is still better in its column than as two gaps.
int score(Frame a, Frame b) {
    if (a == b) return 2;
    return std::popcount(static_cast<unsigned>(a ^ b)) == 1 ? -1 : -3;
}
constexpr int gap = -2;

// The rolling hashes of every run of k frames, sorted, with the runs that occur once kept.
std::vector<std::pair<std::uint64_t, std::int32_t>> unique_runs(std::span<const Frame> s, std::size_t k) {
    std::vector<std::pair<std::uint64_t, std::int32_t>> all;
    if (s.size() < k) return all;
    constexpr std::uint64_t base = 0x100000001B3ULL;
    std::uint64_t top = 1, h = 0;
    for (std::size_t i = 0; i + 1 < k; ++i) top *= base;
    all.reserve(s.size() - k + 1);
    std::size_t blanks = 0;  // a run of blank frames (leader) anchors nothing
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (i >= k) {
            h -= top * (s[i - k] + 1ULL);
            blanks -= s[i - k] == blank_frame;
        }
        h = h * base + (s[i] + 1ULL);
        blanks += s[i] == blank_frame;
        if (i + 1 >= k && blanks < k / 2) all.emplace_back(h, static_cast<std::int32_t>(i + 1 - k));
    }
    std::sort(all.begin(), all.end());
    std::size_t out = 0;
    for (std::size_t i = 0; i < all.size();) {
        std::size_t j = i + 1;
        while (j < all.size() && all[j].first == all[i].first) ++j;
        if (j == i + 1) all[out++] = all[i];
        i = j;
    }
    all.resize(out);
    return all;
}

// The longest chain of anchors increasing in both reads (patience sorting on the read's index).
Pairs chain(Pairs anchors) {
    std::sort(anchors.begin(), anchors.end());
    std::vector<std::size_t> tails, before(anchors.size());
    for (std::size_t a = 0; a < anchors.size(); ++a) {
        auto it = std::lower_bound(tails.begin(), tails.end(), anchors[a].second,
                                   [&](std::size_t t, std::int32_t j) { return anchors[t].second < j; });
        before[a] = it == tails.begin() ? SIZE_MAX : *(it - 1);
        if (it == tails.end())
            tails.push_back(a);
        else
            *it = a;
    }
    Pairs out;
    for (std::size_t a = tails.empty() ? SIZE_MAX : tails.back(); a != SIZE_MAX; a = before[a])
        out.push_back(anchors[a]);
    std::reverse(out.begin(), out.end());
    return out;
}

// Aligns ref[ri, ri + a) with read[rj, rj + b) by dynamic programming, appending the pairs that stand
// in one column. free_start / free_end: either side may leave its beginning / end unpaired at no cost
// (leaders of different length, a read that starts late or stops early).
void align_stretch(std::span<const Frame> ref, std::span<const Frame> read, std::size_t ri, std::size_t a,
                   std::size_t rj, std::size_t b, bool free_start, bool free_end, std::size_t max_cells, Pairs& out) {
    if (a == 0 || b == 0) return;
    // Where one side is free, only the part of the other that can meet it is looked at.
    if (free_start && a > b + 64) ri += a - (b + 64), a = b + 64;
    if (free_start && b > a + 64) rj += b - (a + 64), b = a + 64;
    if (free_end && a > b + 64) a = b + 64;
    if (free_end && b > a + 64) b = a + 64;
    if ((a + 1) * (b + 1) > max_cells) return;
    std::vector<std::uint8_t> trace((a + 1) * (b + 1));
    std::vector<int> prev(b + 1), row(b + 1);
    for (std::size_t j = 0; j <= b; ++j) {
        prev[j] = free_start ? 0 : static_cast<int>(j) * gap;
        trace[j] = 2;
    }
    int best = prev[b];
    std::size_t best_i = 0, best_j = b;
    for (std::size_t i = 1; i <= a; ++i) {
        row[0] = free_start ? 0 : static_cast<int>(i) * gap;
        trace[i * (b + 1)] = 1;
        Frame f = ref[ri + i - 1];
        for (std::size_t j = 1; j <= b; ++j) {
            int diag = prev[j - 1] + score(f, read[rj + j - 1]);
            int up = prev[j] + gap, left = row[j - 1] + gap;
            std::uint8_t t = 0;
            int s = diag;
            if (up > s) s = up, t = 1;
            if (left > s) s = left, t = 2;
            row[j] = s;
            trace[i * (b + 1) + j] = t;
        }
        if (free_end && row[b] > best) best = row[b], best_i = i, best_j = b;
        std::swap(prev, row);
    }
    std::size_t i = a, j = b;
    if (free_end) {
        for (std::size_t jj = 0; jj <= b; ++jj)
            if (prev[jj] > best) best = prev[jj], best_i = a, best_j = jj;
        i = best_i, j = best_j;
    }
    Pairs stretch;
    while (i > 0 && j > 0) {
        std::uint8_t t = trace[i * (b + 1) + j];
        if (t == 0) {
            stretch.emplace_back(static_cast<std::int32_t>(ri + i - 1), static_cast<std::int32_t>(rj + j - 1));
            --i, --j;
        } else if (t == 1) {
            --i;
        } else {
            --j;
        }
    }
    out.insert(out.end(), stretch.rbegin(), stretch.rend());
}

// The pairs of ref and read frames that stand in one column, in order.
Pairs pair_up(std::span<const Frame> ref, std::span<const Frame> read, const AlignOptions& o, double& anchored_share) {
    std::size_t k = std::max<std::size_t>(o.anchor_length, 4);
    auto rr = unique_runs(ref, k), dr = unique_runs(read, k);
    Pairs anchors;
    for (std::size_t x = 0, y = 0; x < rr.size() && y < dr.size();) {
        if (rr[x].first < dr[y].first)
            ++x;
        else if (dr[y].first < rr[x].first)
            ++y;
        else
            anchors.emplace_back(rr[x++].second, dr[y++].second);
    }
    // Each anchor's frames, checked (a hash may collide), become pairs on its diagonal.
    Pairs runs, chained = chain(std::move(anchors));
    // How much of what could anchor did: runs that occur once in each read, in order.
    std::size_t could = std::min(rr.size(), dr.size());
    anchored_share = could ? static_cast<double>(chained.size()) / static_cast<double>(could) : 0;
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

}  // namespace

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

ReadAlignment align_reads(std::span<const std::span<const Frame>> reads, const AlignOptions& o) {
    if (reads.empty()) throw Error(Errc::usage, "no reads to align");
    for (const auto& r : reads)
        if (r.size() >= static_cast<std::size_t>(INT32_MAX))
            throw Error(Errc::usage, "a read of 2^31 frames or more is too long to align");
    std::size_t ref = 0;
    for (std::size_t r = 1; r < reads.size(); ++r)
        if (reads[r].size() > reads[ref].size()) ref = r;
    if (reads[ref].empty()) throw Error(Errc::bad_image, "no read holds any frame");
    const std::size_t n = reads[ref].size();
    ReadAlignment out(reads.size(), ref);
    // For every read: its frame in each reference column, and its runs of frames between reference
    // frames (few: kept as a list, not a column each).
    struct Insert {
        std::size_t before;  // the reference frame they stand before (n: after the last)
        std::int32_t start, count;
    };
    std::vector<std::vector<std::int32_t>> at(reads.size());
    std::vector<std::vector<Insert>> inserts(reads.size());
    for (std::size_t r = 0; r < reads.size(); ++r) {
        at[r].assign(n, ReadAlignment::none);
        if (r == ref) {
            for (std::size_t i = 0; i < n; ++i) at[r][i] = static_cast<std::int32_t>(i);
            continue;
        }
        double anchored_share = 0;
        Pairs pairs = pair_up(reads[ref], reads[r], o, anchored_share);
        // Where a read has a frame twice (or the reference lost one of a run), its extra frame goes to
        // the end of the run of equal frames, the same place in every read: one column, not several.
        {
            const auto& rd = reads[r];
            std::vector<std::int32_t> match(rd.size(), ReadAlignment::none);
            for (auto [i, j] : pairs) match[static_cast<std::size_t>(j)] = i;
            for (std::size_t j = 0; j + 1 < rd.size(); ++j)
                if (match[j] == ReadAlignment::none && match[j + 1] != ReadAlignment::none && rd[j] == rd[j + 1])
                    std::swap(match[j], match[j + 1]);
            pairs.clear();
            for (std::size_t j = 0; j < rd.size(); ++j)
                if (match[j] != ReadAlignment::none) pairs.emplace_back(match[j], static_cast<std::int32_t>(j));
        }
        for (auto [i, j] : pairs) at[r][static_cast<std::size_t>(i)] = j;
        // Where the reference read a frame twice, every read's gap goes to the same place: the end of
        // the run of equal frames, so that the extra frame has one column, not one per read.
        const auto& rf = reads[ref];
        for (std::size_t i = 0; i + 1 < n; ++i)
            if (at[r][i] == ReadAlignment::none && at[r][i + 1] != ReadAlignment::none && rf[i] == rf[i + 1])
                std::swap(at[r][i], at[r][i + 1]);
        pairs.clear();
        std::size_t same = 0;
        // Shared punched frames: blank leader and trailer match on every tape and prove nothing.
        for (std::size_t i = 0; i < n; ++i)
            if (at[r][i] != ReadAlignment::none) {
                pairs.emplace_back(static_cast<std::int32_t>(i), at[r][i]);
                same += rf[i] != blank_frame && rf[i] == reads[r][static_cast<std::size_t>(at[r][i])];
            }
        auto punched = [](std::span<const Frame> s) {
            return static_cast<std::size_t>(
                std::count_if(s.begin(), s.end(), [](Frame f) { return f != blank_frame; }));
        };
        std::size_t shorter = std::min(punched(rf), punched(reads[r]));
        double shared = shorter ? static_cast<double>(same) / static_cast<double>(shorter) : 0;
        out.set_shared(r, shared);
        // Two programs share many characters wherever dynamic programming may pair them, but few long
        // runs that occur once in each; reads of one tape share both. A short tape with much damage
        // has few such runs left, but its frames still agree nearly all.
        if (anchored_share < o.min_shared && shared < 0.8)
            throw Error(Errc::bad_image, "read " + std::to_string(r + 1) + " shares runs of " +
                                             std::to_string(o.anchor_length) + " frames with read " +
                                             std::to_string(ref + 1) + " over only " +
                                             std::to_string(static_cast<int>(anchored_share * 100)) +
                                             "% of the runs that occur once in each" +
                                             ": they are reads of different tapes, or too damaged to align");
        // A read frame in no pair stands between the reference frames of the pairs around it.
        std::size_t p = 0;
        for (std::size_t j = 0; j < reads[r].size();) {
            while (p < pairs.size() && static_cast<std::size_t>(pairs[p].second) < j) ++p;
            if (p < pairs.size() && static_cast<std::size_t>(pairs[p].second) == j) {
                ++j;
                continue;
            }
            std::size_t before = p < pairs.size() ? static_cast<std::size_t>(pairs[p].first) : n;
            std::size_t to = p < pairs.size() ? static_cast<std::size_t>(pairs[p].second) : reads[r].size();
            inserts[r].push_back({before, static_cast<std::int32_t>(j), static_cast<std::int32_t>(to - j)});
            j = to;
        }
    }
    std::vector<std::int32_t> column(reads.size());
    std::vector<std::size_t> next(reads.size(), 0);  // each read's next insert
    std::vector<const Insert*> here(reads.size());
    for (std::size_t i = 0; i <= n; ++i) {
        std::int32_t extra = 0;
        for (std::size_t r = 0; r < reads.size(); ++r) {
            here[r] = next[r] < inserts[r].size() && inserts[r][next[r]].before == i ? &inserts[r][next[r]++] : nullptr;
            if (here[r]) extra = std::max(extra, here[r]->count);
        }
        for (std::int32_t t = 0; t < extra; ++t) {
            for (std::size_t r = 0; r < reads.size(); ++r)
                column[r] = here[r] && t < here[r]->count ? here[r]->start + t : ReadAlignment::none;
            out.add_column(column);
        }
        if (i == n) break;
        for (std::size_t r = 0; r < reads.size(); ++r) column[r] = at[r][i];
        out.add_column(column);
    }
    out.finish();
    return out;
}

}  // namespace tape
