// How many times a frame of a run is punched, where the reads disagree (vote.hpp). A reader loses a
// frame or reads one twice at rates the reads themselves show; with those rates, and with how long the
// runs of that frame are elsewhere on the tape, each length the run may have is weighed by how likely
// it makes what every read saw. Leader and trailer are blank tape whose length no one needs: they
// follow the majority (the median read).
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>

#include "vote.hpp"

namespace tape::detail {
namespace {

constexpr std::size_t longest_run = 64;  // runs longer are counted as this long in the prior

// How often runs of each length stand on the tape, per frame, from the reference read's data.
class RunPrior {
public:
    RunPrior(std::span<const Frame> read) {
        auto data = punched_part(read);
        for (std::size_t i = 0; i < data.size();) {
            std::size_t j = i + 1;
            while (j < data.size() && data[j] == data[i]) ++j;
            ++count_[data[i]][std::min(j - i, longest_run)];
            ++total_[data[i]];
            i = j;
        }
    }
    /// own: the length the reference read has this run with (0: unknown). The run is left out of the
    /// counts: a frame the tape holds a few times would otherwise take the reference read's own slip
    /// ("%%" for "%") for the tape's habit.
    double log_chance(Frame f, std::size_t length, std::size_t own = 0) const {
        constexpr double pseudo = 0.5;
        std::size_t at = std::min(length, longest_run);
        double n = count_[f][at], total = static_cast<double>(total_[f]);
        if (own > 0 && total > 0) {
            total -= 1;
            if (std::min(own, longest_run) == at && n > 0) n -= 1;
        }
        return std::log((n + pseudo) / (total + pseudo * longest_run));
    }

private:
    std::array<std::array<std::uint32_t, longest_run + 1>, 256> count_{};
    std::array<std::uint64_t, 256> total_{};
};

// The good frame most heard in column c, if any.
std::optional<Frame> column_value(const VoteContext& v, std::size_t c) {
    std::optional<Frame> best;
    int best_count = 0;
    std::array<std::pair<Frame, int>, 8> seen{};
    std::size_t kinds = 0;
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        auto f = frame_at(v.a, v.reads, c, r);
        if (!f || !v.heard(c, r) || !v.good(*f)) continue;
        std::size_t k = 0;
        while (k < kinds && seen[k].first != *f) ++k;
        if (k == kinds) {
            if (kinds == seen.size()) continue;
            seen[kinds++] = {*f, 0};
        }
        if (++seen[k].second > best_count) best_count = seen[k].second, best = *f;
    }
    return best;
}

// Every frame heard in column c is value, or a misreading of it that fails parity.
bool only_copies_of(const VoteContext& v, std::size_t c, Frame value) {
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        auto f = frame_at(v.a, v.reads, c, r);
        if (!f || !v.heard(c, r) || *f == value) continue;
        if (!v.code || v.good(*f) || hole_count(*f ^ value) != 1) return false;
    }
    return true;
}

// The column beside the run on one side (before: the one before first; else the one at end), past up to
// a few columns that only a minority of the reads covering them have a frame in (another read's frame
// read twice, or its stain): a read lacking those lost nothing. SIZE_MAX at the tape's end.
std::size_t beside_column(const VoteContext& v, std::size_t first, std::size_t end, bool before) {
    constexpr std::size_t most_skipped = 4;
    auto minority = [&](std::size_t c) {
        std::size_t covering = 0, present = 0;
        for (std::size_t r = 0; r < v.a.reads(); ++r)
            if (v.a.covers(r, c)) ++covering, present += v.a.frame(c, r) != ReadAlignment::none;
        return present * 2 < covering;
    };
    std::size_t c = before ? first : end;
    for (std::size_t skipped = 0;; ++skipped) {
        if (before ? c == 0 : c >= v.a.columns()) return SIZE_MAX;
        std::size_t next = before ? c - 1 : c;
        if (skipped == most_skipped || !minority(next)) return next;
        c = before ? c - 1 : c + 1;
    }
}

// No read heard in column c has a frame there: only reads that misread the stretch do.
bool stain_only(const VoteContext& v, std::size_t c) {
    for (std::size_t r = 0; r < v.a.reads(); ++r)
        if (v.heard(c, r) && v.a.frame(c, r) != ReadAlignment::none) return false;
    return true;
}

// Per read: the frames it has in columns [first, end), or -1 where it does not cover them all or was
// not heard on them.
// A read that lacks the frame beside the run too lost a stretch, not copies of this frame: it is not
// heard on the run either.
std::vector<long> copies_per_read(const VoteContext& v, std::size_t first, std::size_t end) {
    std::vector<long> out(v.a.reads(), -1);
    const std::size_t before = beside_column(v, first, end, true), after = beside_column(v, first, end, false);
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        if (!v.a.covers(r, first) || !v.a.covers(r, end - 1)) continue;
        if ((before != SIZE_MAX && v.a.frame(before, r) == ReadAlignment::none) ||
            (after != SIZE_MAX && v.a.frame(after, r) == ReadAlignment::none))
            continue;
        long n = 0;
        bool heard = true;
        for (std::size_t c = first; c < end; ++c) {
            heard &= v.heard(c, r);
            n += v.a.frame(c, r) != ReadAlignment::none;
        }
        if (heard) out[r] = n;
    }
    return out;
}

// "2 of 3 reads have 3 copies, 1 has 2".
std::string counts_text(const std::vector<long>& copies) {
    std::vector<std::pair<long, int>> by;
    std::size_t readers = 0;
    for (long n : copies) {
        if (n < 0) continue;
        ++readers;
        auto it = std::find_if(by.begin(), by.end(), [&](const auto& x) { return x.first == n; });
        if (it == by.end())
            by.emplace_back(n, 1);
        else
            ++it->second;
    }
    std::sort(by.begin(), by.end(), [](const auto& x, const auto& y) { return x.second > y.second; });
    std::string s;
    for (std::size_t i = 0; i < by.size(); ++i) {
        s += (i ? ", " : "") + std::to_string(by[i].second) + (i ? "" : " of " + std::to_string(readers) + " reads") +
             (i ? (by[i].second == 1 ? " has " : " have ") : (by[i].second == 1 ? " has " : " have ")) +
             std::to_string(by[i].first) + (by[i].first == 1 ? " copy" : " copies");
    }
    return s;
}

// Per read: how many frames beside the run (0, 1 or 2) it reads as the run's frame where most reads have
// another. The alignment paired each with the frame most reads have there, but it may as well be a copy
// of the run (and the other frame lost): "00 0000" against "00 4 000" is a drop of the 4, not a 4 read
// as 0 and a 0 lost. Such a read's count may be that much higher.
std::vector<long> copies_beside(const VoteContext& v, std::size_t first, std::size_t end, Frame value) {
    std::vector<long> out(v.a.reads(), 0);
    for (std::size_t c : {first - 1, end}) {
        if (c < v.data_from || c >= v.data_to || column_value(v, c) == value) continue;
        for (std::size_t r = 0; r < v.a.reads(); ++r) {
            auto f = frame_at(v.a, v.reads, c, r);
            out[r] += f && v.heard(c, r) && *f == value;
        }
    }
    return out;
}

// How likely a read that has `seen` copies, and up to `beside` more frames that may be copies, makes a
// run of `punched`: the likeliest of its possible counts (a read that may be either is not a witness
// for one length over the other).
double read_likelihood(long seen, long beside, std::size_t punched, const SlipRates& rates) {
    double best = 0;
    for (long k = 0; k <= beside; ++k)
        best = std::max(best, copies_likelihood(static_cast<std::size_t>(seen + k), punched, rates));
    return best;
}

// ", and 1 read has the frame beside it where the others have another: perhaps one more copy".
std::string beside_text(const std::vector<long>& beside) {
    auto n = std::count_if(beside.begin(), beside.end(), [](long x) { return x > 0; });
    if (n == 0) return "";
    return ", and " + std::to_string(n) + (n == 1 ? " read has" : " reads have") +
           " this frame beside it where the others have another: perhaps one more copy";
}

// The length of a data run by likelihood: every length from the fewest copies a read has to the most.
// The length of the run the reference read has where run d stands (0: none there): the one its prior
// counted, found in the read's own frames, which may reach past the run's columns.
std::size_t reference_run(const VoteContext& v, const RunDecision& d) {
    const std::size_t r = v.a.reference();
    const auto& read = v.reads[r];
    for (std::size_t c = d.first; c < d.end; ++c) {
        std::int32_t i = v.a.frame(c, r);
        if (i == ReadAlignment::none || read[static_cast<std::size_t>(i)] != d.value) continue;
        std::size_t from = static_cast<std::size_t>(i), to = from + 1;
        while (from > 0 && read[from - 1] == d.value) --from;
        while (to < read.size() && read[to] == d.value) ++to;
        return to - from;
    }
    return 0;
}

void weigh_lengths(const VoteContext& v, const RunPrior& prior, const std::vector<long>& copies,
                   const std::vector<long>& beside, RunDecision& d) {
    long lo = LONG_MAX, hi = 0;
    for (std::size_t r = 0; r < copies.size(); ++r)
        if (copies[r] >= 0) lo = std::min(lo, copies[r]), hi = std::max(hi, copies[r] + beside[r]);
    lo = std::max(lo, 1L);
    double best = -INFINITY, second = -INFINITY;
    const std::size_t own = reference_run(v, d);
    for (long n = lo; n <= std::max(hi, lo); ++n) {
        double score = prior.log_chance(d.value, static_cast<std::size_t>(n), own);
        for (std::size_t r = 0; r < copies.size(); ++r)
            if (copies[r] >= 0)
                score += std::log(read_likelihood(copies[r], beside[r], static_cast<std::size_t>(n), v.rates[r]));
        if (score > best) {
            second = best, d.alternative = d.length;
            best = score, d.length = static_cast<std::size_t>(n);
        } else if (score > second) {
            second = score, d.alternative = static_cast<std::size_t>(n);
        }
    }
    d.odds = second == -INFINITY ? INFINITY : std::exp(std::min(best - second, 700.0));
    if (second == -INFINITY) d.alternative = d.length;
}

// Leader or trailer: the length the median read has.
void median_length(const std::vector<long>& copies, RunDecision& d) {
    std::vector<long> n;
    for (long x : copies)
        if (x > 0) n.push_back(x);
    std::sort(n.begin(), n.end());
    d.length = n.empty() ? 0 : static_cast<std::size_t>(n[(n.size() - 1) / 2]);
    d.alternative = d.length;
    d.odds = INFINITY;
}

// A column beside a run whose frames all fail parity one hole from its value, where some read that
// covers it has no frame: a copy of the run's frame misread, which the alignment could not pair.
bool misread_copy(const VoteContext& v, std::size_t c, Frame value) {
    bool any = false, lacking = false;
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        if (!v.a.covers(r, c)) continue;
        auto f = frame_at(v.a, v.reads, c, r);
        if (!f) {
            lacking = true;
            continue;
        }
        if (!v.heard(c, r) || !v.code || v.good(*f) || hole_count(*f ^ value) != 1) return false;
        any = true;
    }
    return any && lacking;
}

// Per read for a stretch of leader or trailer: its frames there (reads with none are left out).
std::vector<long> frames_per_read(const VoteContext& v, std::size_t first, std::size_t end) {
    std::vector<long> out(v.a.reads(), -1);
    for (std::size_t c = first; c < end; ++c)
        for (std::size_t r = 0; r < v.a.reads(); ++r)
            if (v.a.frame(c, r) != ReadAlignment::none) out[r] = std::max(out[r], 0L) + 1;
    return out;
}

}  // namespace

double copies_likelihood(std::size_t seen, std::size_t punched, const SlipRates& rates) {
    const double n = static_cast<double>(punched), l = static_cast<double>(seen);
    const double pd = rates.drop, pb = rates.twice, ps = 1 - pd - pb;
    double sum = 0;
    // d copies lost, b read twice: seen = punched - d + b.
    for (double d = std::max(0.0, n - l); 2 * d <= 2 * n - l; ++d) {
        double b = l - n + d;
        if (b < 0 || d + b > n) continue;
        sum += std::exp(std::lgamma(n + 1) - std::lgamma(d + 1) - std::lgamma(b + 1) - std::lgamma(n - d - b + 1) +
                        d * std::log(pd) + b * std::log(pb) + (n - d - b) * std::log(ps));
    }
    return std::max(sum, 1e-300);
}

namespace {

// One past the last column of the run of value from column c (the columns only a stain stands in do not
// end it: the frames on either side of the stain are one run; nor does a column whose only frames are
// misread copies of value, one read's copy read twice and misread: "**.**" beside "****").
std::size_t run_end(const VoteContext& v, std::size_t c, Frame value) {
    std::size_t end = c + 1;
    for (std::size_t next = end; next < v.data_to;) {
        while (next < v.data_to && !column_value(v, next) && stain_only(v, next)) ++next;
        if (next == v.data_to || !only_copies_of(v, next, value)) break;
        if (auto heard = column_value(v, next); heard && *heard != value) break;
        end = ++next;
    }
    return end;
}

// The decision on columns [first, end) of value, or nullopt where there is nothing to decide: every read
// has a frame in every column, most reads have none of it (frames a few reads have, read twice or a
// stain, are voted a column at a time), or fewer than two reads cover it whole.
std::optional<RunDecision> decide_run(const VoteContext& v, const RunPrior& prior, std::size_t first, std::size_t end,
                                      Frame value) {
    RunDecision d;
    d.first = first, d.end = end, d.value = value;
    auto copies = copies_per_read(v, first, end);
    if (std::all_of(copies.begin(), copies.end(),
                    [&](long x) { return x < 0 || static_cast<std::size_t>(x) == end - first; }))
        return std::nullopt;
    d.readers = static_cast<std::size_t>(std::count_if(copies.begin(), copies.end(), [](long x) { return x >= 0; }));
    auto none = static_cast<std::size_t>(std::count(copies.begin(), copies.end(), 0L));
    if (none * 2 > d.readers || d.readers < 2) return std::nullopt;
    auto beside = copies_beside(v, first, end, value);
    weigh_lengths(v, prior, copies, beside, d);
    d.how = counts_text(copies) + beside_text(beside);
    return d;
}

}  // namespace

std::vector<RunDecision> decide_runs(const VoteContext& v) {
    std::vector<RunDecision> out;
    const RunPrior prior(v.reads[v.a.reference()]);
    auto add_end = [&](std::size_t first, std::size_t end) {
        if (end <= first) return;
        RunDecision d;
        d.first = first, d.end = end, d.value = blank_frame;
        d.blank_end = true;
        auto copies = frames_per_read(v, first, end);
        median_length(copies, d);
        d.readers = static_cast<std::size_t>(std::count_if(copies.begin(), copies.end(), [](long x) { return x > 0; }));
        out.push_back(std::move(d));
    };
    add_end(0, v.data_from);
    for (std::size_t c = v.data_from; c < v.data_to;) {
        auto value = column_value(v, c);
        if (!value || !only_copies_of(v, c, *value)) {
            ++c;
            continue;
        }
        std::size_t end = run_end(v, c, *value);
        bool misread_before = c > v.data_from && (out.empty() || out.back().end < c) && misread_copy(v, c - 1, *value);
        if (misread_before) --c;
        if (end < v.data_to && misread_copy(v, end, *value)) ++end;
        if (end - c >= 2)
            if (auto d = decide_run(v, prior, c, end, *value)) out.push_back(std::move(*d));
        c = end;
    }
    add_end(v.data_to, v.a.columns());
    return out;
}

}  // namespace tape::detail
