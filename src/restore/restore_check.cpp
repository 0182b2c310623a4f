// A restoration scored against the tape its reads were made from (tape/restore.hpp), by the counting
// rules of restoring's figures: the data only (first to last punched frame), a frame left out or added
// in a run of equal frames in doubt when any copy of the run is, and a stretch of frames that do not
// match in doubt when the report doubts anything in it.
#include <algorithm>

#include "tape/restore.hpp"

namespace tape {
namespace {

// What the report says of each output frame of the data, and of the frames it left out.
struct Doubts {
    std::vector<bool> frame;  // per output frame: in doubt
    std::vector<bool> after;  // per output frame count before: a frame left out there is in doubt
};

Doubts doubts_of(const RestoreResult& r) {
    Doubts d{std::vector<bool>(r.frames.size(), false), std::vector<bool>(r.frames.size() + 1, false)};
    for (const auto& p : r.problems) {
        if (!in_doubt(p.status)) continue;
        if (p.frame && *p.frame >= 1 && *p.frame <= r.frames.size())
            d.frame[*p.frame - 1] = true;
        else if (!p.frame && p.after <= r.frames.size())
            d.after[p.after] = true;
    }
    return d;
}

// The run of equal frames around output frame i (or, for a frame left out after `written` frames,
// around that place): in doubt when any copy is, or a frame left out in it is.
bool run_in_doubt(const RestoreResult& r, const Doubts& d, std::size_t from, std::size_t to, Frame value) {
    while (from > 0 && r.frames[from - 1] == value) --from;
    while (to < r.frames.size() && r.frames[to] == value) ++to;
    for (std::size_t i = from; i < to; ++i)
        if (d.frame[i]) return true;
    for (std::size_t i = from; i <= to; ++i)
        if (d.after[i]) return true;
    return false;
}

// Where the tape (from i) and the output (from j) agree again after they differ: the nearest place,
// by the fewest frames skipped on both sides, from which `agree` frames match (or both end alike). The
// output is compared with the tape so, frame by frame, not by unique anchors: a tape that holds its
// programs twice has no run of frames that occurs once.
std::pair<std::size_t, std::size_t> resync(std::span<const Frame> a, std::size_t i, std::span<const Frame> b,
                                           std::size_t j) {
    constexpr std::size_t agree = 16, reach = 512;
    auto match_from = [&](std::size_t x, std::size_t y) {
        std::size_t n = std::min({agree, a.size() - x, b.size() - y});
        if (n < agree && a.size() - x != b.size() - y) return false;
        return std::equal(a.begin() + static_cast<std::ptrdiff_t>(x), a.begin() + static_cast<std::ptrdiff_t>(x + n),
                          b.begin() + static_cast<std::ptrdiff_t>(y));
    };
    std::size_t left_a = a.size() - i, left_b = b.size() - j;
    for (std::size_t d = 1; d <= 2 * reach; ++d)
        for (std::size_t di = d > reach ? d - reach : 0; di <= std::min(d, reach); ++di) {
            std::size_t dj = d - di;
            if (di <= left_a && dj <= left_b && match_from(i + di, j + dj)) return {di, dj};
        }
    return {std::min(reach, left_a), std::min(reach, left_b)};
}

// Scores the output against the tape a stretch of difference at a time (check_restore).
class Scorer {
public:
    Scorer(std::span<const Frame> tape, std::span<const Frame> output, std::size_t tape_offset,
           std::size_t output_offset, const RestoreResult& r, RestoreCheck& out)
        : a_(tape), b_(output), tape_offset_(tape_offset), offset_(output_offset), r_(r), d_(doubts_of(r)), out_(out) {}

    void run() {
        std::size_t i = 0, j = 0;
        while (i < a_.size() || j < b_.size()) {
            if (i < a_.size() && j < b_.size() && a_[i] == b_[j]) {
                ++out_.right, ++i, ++j;
                continue;
            }
            auto [di, dj] = resync(a_, i, b_, j);
            difference(i, di, j, dj);
            i += di, j += dj;
        }
    }

private:
    using Column = std::pair<std::int32_t, std::int32_t>;  // tape frame, output frame (or none), from i / j

    // tape[i, i + di) against output[j, j + dj), aligned as reads are aligned.
    std::vector<Column> columns(std::size_t i, std::size_t di, std::size_t j, std::size_t dj) const {
        std::vector<Column> c;
        if (di == 0 || dj == 0) {
            for (std::size_t k = 0; k < di; ++k) c.emplace_back(static_cast<std::int32_t>(k), ReadAlignment::none);
            for (std::size_t k = 0; k < dj; ++k) c.emplace_back(ReadAlignment::none, static_cast<std::int32_t>(k));
            return c;
        }
        std::vector<std::span<const Frame>> pair{a_.subspan(i, di), b_.subspan(j, dj)};
        ReadAlignment al = align_reads(pair, AlignOptions{.min_shared = 0, .drop_unrelated = false});
        for (std::size_t k = 0; k < al.columns(); ++k) c.emplace_back(al.frame(k, 0), al.frame(k, 1));
        return c;
    }

    // A stretch where they differ: frames that match inside it are right; each run of columns that do not
    // match is one place, in doubt where the report doubts anything in it or frames left out at its ends
    // (else frame by frame, a run of equal frames in doubt where any copy is).
    void difference(std::size_t i, std::size_t di, std::size_t j, std::size_t dj) {
        auto cols = columns(i, di, j, dj);
        auto matched = [&](const Column& c) {
            return c.first != ReadAlignment::none && c.second != ReadAlignment::none &&
                   a_[i + static_cast<std::size_t>(c.first)] == b_[j + static_cast<std::size_t>(c.second)];
        };
        std::size_t written = offset_ + j;  // output frames before the column
        std::size_t tape_at = i ? i - 1 : 0;
        for (std::size_t k = 0; k < cols.size();) {
            if (matched(cols[k])) {
                ++out_.right, ++written, tape_at = i + static_cast<std::size_t>(cols[k].first), ++k;
                continue;
            }
            std::size_t end = k, to = written;
            bool doubt = false;
            for (; end < cols.size() && !matched(cols[end]); ++end)
                if (cols[end].second != ReadAlignment::none) doubt |= d_.frame[to++];
            for (std::size_t x = written; x <= to && x < d_.after.size(); ++x) doubt |= d_.after[x];
            // Frames only left out: the place between two output frames, in doubt where either is.
            if (to == written)
                doubt |= (written > 0 && d_.frame[written - 1]) || (written < d_.frame.size() && d_.frame[written]);
            for (; k < end; ++k) wrong(i, j, cols[k], doubt, written, tape_at);
        }
    }

    void wrong(std::size_t i, std::size_t j, const Column& c, bool doubt, std::size_t& written, std::size_t& tape_at) {
        if (c.first != ReadAlignment::none) tape_at = i + static_cast<std::size_t>(c.first);
        std::size_t output_at = written;
        if (c.second != ReadAlignment::none) {
            std::size_t o = offset_ + j + static_cast<std::size_t>(c.second);
            doubt |= run_in_doubt(r_, d_, o, o + 1, r_.frames[o]);
            ++written;
        } else {
            doubt |= run_in_doubt(r_, d_, written, written, a_[tape_at]);
        }
        (doubt ? out_.flagged_at : out_.silent_at).push_back(tape_offset_ + tape_at);
        (doubt ? out_.flagged_output : out_.silent_output).push_back(output_at);
        ++(doubt ? out_.flagged_wrong : out_.silently_wrong);
    }

    std::span<const Frame> a_, b_;
    std::size_t tape_offset_, offset_;
    const RestoreResult& r_;
    const Doubts d_;
    RestoreCheck& out_;
};

}  // namespace

bool in_doubt(FrameStatus s) {
    using S = FrameStatus;
    return s == S::guessed || s == S::contested || s == S::unstable || s == S::unresolved || s == S::missing;
}

RestoreCheck check_restore(std::span<const Frame> tape, const RestoreResult& r) {
    RestoreCheck out;
    auto a = punched_part(tape), b = punched_part(r.frames);
    out.exact = std::equal(a.begin(), a.end(), b.begin(), b.end());
    out.blank_ends = static_cast<std::uint64_t>(
        std::abs(static_cast<long long>(a.data() - tape.data()) - static_cast<long long>(b.data() - r.frames.data())) +
        std::abs(
            static_cast<long long>(tape.size() - a.size() - static_cast<std::size_t>(a.data() - tape.data())) -
            static_cast<long long>(r.frames.size() - b.size() - static_cast<std::size_t>(b.data() - r.frames.data()))));
    if (a.empty() || b.empty()) {
        out.silently_wrong = a.size() + b.size();
        return out;
    }
    Scorer scorer(a, b, static_cast<std::size_t>(a.data() - tape.data()),
                  static_cast<std::size_t>(b.data() - r.frames.data()), r, out);
    scorer.run();
    return out;
}

}  // namespace tape
