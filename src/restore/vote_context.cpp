// What the vote knows besides the alignment (vote.hpp): where reads misread or slipped, which frames
// they doubt, where the data lies, and how often each read loses a frame or reads one twice.
#include <algorithm>

#include "tape/error.hpp"
#include "vote.hpp"

namespace tape::detail {
namespace {

// Per column and read: the read doubts the frame it has there.
std::vector<std::uint8_t> doubted_frames(const ReadAlignment& a, const std::vector<FrameDoubts>& doubts) {
    if (doubts.empty()) return {};
    if (doubts.size() != a.reads())
        throw Error(Errc::usage, "doubts given for " + std::to_string(doubts.size()) + " reads, but there are " +
                                     std::to_string(a.reads()));
    std::vector<std::uint8_t> out(a.columns() * a.reads(), 0);
    for (std::size_t r = 0; r < a.reads(); ++r) {
        std::vector<std::pair<std::uint64_t, std::uint64_t>> runs;
        for (const auto& d : doubts[r].runs) runs.emplace_back(d.first, d.last);
        std::sort(runs.begin(), runs.end());
        for (std::size_t c = 0; c < a.columns(); ++c) {
            std::int32_t i = a.frame(c, r);
            if (i == ReadAlignment::none) continue;
            std::uint64_t frame = static_cast<std::uint64_t>(i) + 1;
            auto it = std::upper_bound(runs.begin(), runs.end(), std::make_pair(frame, UINT64_MAX));
            if (it != runs.begin() && std::prev(it)->second >= frame) out[c * a.reads() + r] = 1;
        }
    }
    return out;
}

// A column of data: most reads heard there punched it (a tie of two: a good frame of more than one
// hole, so that one stain in one of two leaders does not start the data).
bool punched_column(const VoteContext& v, std::size_t c) {
    std::size_t punched = 0, blank = 0;
    bool good_punched = false;
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        auto f = frame_at(v.a, v.reads, c, r);
        if (!f || !v.heard(c, r)) continue;
        if (hole_count(*f) > 1) {
            ++punched;
            good_punched |= v.good(*f);
        } else {
            ++blank;
        }
    }
    return punched > blank || (punched == blank && punched > 0 && good_punched);
}

// Two reads heard here have the same punched frame: the data certainly goes so far.
bool backed_data(const VoteContext& v, std::size_t c) {
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        auto f = frame_at(v.a, v.reads, c, r);
        if (!f || !v.heard(c, r) || hole_count(*f) < 2) continue;
        for (std::size_t s = r + 1; s < v.a.reads(); ++s)
            if (frame_at(v.a, v.reads, c, s) == f && v.heard(c, s)) return true;
    }
    return false;
}

// The columns of data: from the first to the last column two reads back (or that one read alone
// punched, when it is the only read), widened by frames that follow them closely where no other read
// covers the tape: the end of the data that only one read reached. A stain in one read's trailer, past
// blank tape, is not data.
void data_columns(VoteContext& v) {
    constexpr std::size_t close = 8;
    std::size_t related = 0;
    for (std::size_t r = 0; r < v.a.reads(); ++r) related += v.a.related(r);
    auto data = [&](std::size_t c) { return punched_column(v, c) && (related <= 1 || backed_data(v, c)); };
    std::size_t from = v.a.columns(), to = 0;
    for (std::size_t c = 0; c < v.a.columns(); ++c)
        if (data(c)) from = std::min(from, c), to = c + 1;
    if (from >= to) {  // nothing backed: every punched column
        for (std::size_t c = 0; c < v.a.columns(); ++c)
            if (punched_column(v, c)) from = std::min(from, c), to = c + 1;
        if (from >= to) from = to = 0;
    }
    auto alone = [&](std::size_t c) {
        std::size_t covering = 0;
        for (std::size_t r = 0; r < v.a.reads(); ++r) covering += v.a.covers(r, c);
        return covering <= 1;
    };
    for (std::size_t c = to, last = to; c < v.a.columns() && c - last <= close && alone(c); ++c)
        if (punched_column(v, c)) to = c + 1, last = c + 1;
    for (std::size_t c = from, last = from; c-- > 0 && last - c <= close + 1 && alone(c);)
        if (punched_column(v, c)) from = c, last = c;
    v.data_from = from, v.data_to = to;
}

// Per read: how often it lost a frame most other reads have, and had one most others lack, per frame,
// with one of each added so that a clean read is not taken for a perfect one.
std::vector<SlipRates> slip_rates(const VoteContext& v) {
    const std::size_t n = v.a.reads();
    std::vector<double> drops(n, 0), twice(n, 0), frames(n, 0);
    for (std::size_t c = v.data_from; c < v.data_to; ++c) {
        std::size_t with = 0, covering = 0;
        for (std::size_t r = 0; r < n; ++r)
            if (v.a.covers(r, c) && v.heard(c, r)) ++covering, with += v.a.frame(c, r) != ReadAlignment::none;
        for (std::size_t r = 0; r < n; ++r) {
            if (!v.a.covers(r, c) || !v.heard(c, r)) continue;
            bool has = v.a.frame(c, r) != ReadAlignment::none;
            std::size_t others_with = with - has, others = covering - 1;
            frames[r] += has;
            if (others == 0) continue;
            if (has && others_with * 2 < others) twice[r] += 1;
            if (!has && others_with * 2 > others) drops[r] += 1;
            if (others_with * 2 == others) (has ? twice[r] : drops[r]) += 0.5;  // two reads: either slipped
        }
    }
    std::vector<SlipRates> out(n);
    for (std::size_t r = 0; r < n; ++r) {
        double base = frames[r] + 1000;
        out[r] = {std::clamp((drops[r] + 1) / base, 1e-7, 0.2), std::clamp((twice[r] + 1) / base, 1e-7, 0.2)};
    }
    return out;
}

}  // namespace

VoteContext make_vote_context(const ReadAlignment& a, Reads reads, const RestoreOptions& o) {
    VoteContext v{a, reads, o.code, {}, {}, {}, 0, 0, {}, {}};
    v.garbled = garbled_stretches(a, reads, o.code);
    v.tangled = slips_in_several_reads(a, reads);
    v.doubted = doubted_frames(a, o.doubts);
    data_columns(v);
    v.rates = slip_rates(v);
    v.alone.assign(a.columns(), ReadAlignment::none);
    for (std::size_t c = 0; c < a.columns(); ++c) {
        std::size_t with = 0;
        for (std::size_t r = 0; r < a.reads(); ++r)
            if (a.frame(c, r) != ReadAlignment::none) ++with, v.alone[c] = static_cast<std::int32_t>(r);
        if (with != 1) v.alone[c] = ReadAlignment::none;
    }
    return v;
}

}  // namespace tape::detail
