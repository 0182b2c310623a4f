// Where reads misread a stretch (a stain or splice read as other frames) and where several reads
// slipped in one stretch: what the vote must not hear, and where it must not decide alone (vote.hpp).
#include <algorithm>

#include "vote.hpp"

namespace tape::detail {
namespace {

// A stretch of columns where a read's frames are backed by no other read.
struct Stretch {
    std::size_t read, start, end;
    bool unbacked = false, absent = false;
    std::size_t failing = 0;  // frames failing parity
};

bool good_frame(const std::optional<FrameCode>& code, Frame f) { return !code || !is_bad_frame(code->kind(f)); }

// A frame is backed when another read has the same, or one hole from it (the same frame misread), or
// when it is the only good one among frames failing parity.
bool backed(const ReadAlignment& a, Reads reads, const std::optional<FrameCode>& code, std::size_t c, std::size_t r,
            Frame f) {
    bool others = false, others_good = false;
    for (std::size_t s = 0; s < a.reads(); ++s) {
        if (s == r) continue;
        auto g = frame_at(a, reads, c, s);
        if (!g) continue;
        if (hole_count(*g ^ f) <= 1) return true;
        others = true;
        others_good |= good_frame(code, *g);
    }
    return others && !others_good && good_frame(code, f);
}

// Absent where most other reads have a frame; a frame one other read alone has (read twice) says
// nothing of this read.
bool absent_where_others_have(const ReadAlignment& a, std::size_t c, std::size_t r) {
    std::size_t with = 0, without = 0;
    for (std::size_t s = 0; s < a.reads(); ++s)
        if (s != r && a.covers(s, c)) (a.frame(c, s) != ReadAlignment::none ? with : without) += 1;
    return with > without;
}

// The read's stretches where its frames are not backed, or it has none while others have.
std::vector<Stretch> unbacked_stretches(const ReadAlignment& a, Reads reads, const std::optional<FrameCode>& code,
                                        std::size_t r) {
    // A frame that happens to equal its neighbour may split one garbled stretch in two (a stain read
    // as "33" next to a real "33"); stretches this close are one.
    constexpr std::size_t bridged = 2;
    std::vector<Stretch> stretches;
    for (std::size_t c = a.first_column(r); c < a.end_column(r);) {
        Stretch z{r, c, c};
        for (; c < a.end_column(r); ++c) {
            auto f = frame_at(a, reads, c, r);
            if (f && backed(a, reads, code, c, r, *f)) break;
            // A frame equal to its neighbour in the read is a frame read twice, not a stain's.
            z.unbacked |= f.has_value() && !repeated(reads[r], static_cast<std::size_t>(a.frame(c, r)));
            z.failing += f && !good_frame(code, *f);
            if (!f) z.absent |= absent_where_others_have(a, c, r);
        }
        z.end = c;
        if (z.end > z.start) {
            if (!stretches.empty() && z.start - stretches.back().end <= bridged) {
                auto& last = stretches.back();
                last.end = z.end, last.unbacked |= z.unbacked, last.absent |= z.absent;
                last.failing += z.failing;
            } else {
                stretches.push_back(z);
            }
        }
        if (c == z.start) ++c;
    }
    return stretches;
}

// Where every read garbled the same stretch by that measure (two reads, one of them stained), parity
// tells them apart: a read whose frames there all hold parity is heard when another's fail it.
void hear_reads_that_hold_parity(const ReadAlignment& a, const std::vector<Stretch>& garbled_ones,
                                 std::vector<std::uint8_t>& garbled) {
    const std::size_t n = a.reads();
    auto others_garbled = [&](const Stretch& z) {
        bool failing = false;
        for (const auto& o : garbled_ones)
            if (o.read != z.read && o.start < z.end && z.start < o.end) failing |= o.failing > 0;
        if (!failing) return false;
        for (std::size_t x = z.start; x < z.end; ++x)
            for (std::size_t s = 0; s < n; ++s)
                if (s != z.read && a.covers(s, x) && !garbled[x * n + s]) return false;
        return true;
    };
    std::vector<const Stretch*> heard;
    for (const auto& z : garbled_ones)
        if (z.failing == 0 && others_garbled(z)) heard.push_back(&z);
    for (const Stretch* z : heard)
        for (std::size_t x = z->start; x < z->end; ++x) garbled[x * n + z->read] = 0;
}

}  // namespace

// A read garbled a stretch where it has frames no other read backs next to places where it lacks frames
// the others have: its frames there are misreadings and its gaps say nothing.
std::vector<std::uint8_t> garbled_stretches(const ReadAlignment& a, Reads reads, const std::optional<FrameCode>& code) {
    const std::size_t n = a.reads();
    std::vector<Stretch> garbled_ones;
    for (std::size_t r = 0; r < n; ++r)
        for (const auto& z : unbacked_stretches(a, reads, code, r))
            if (z.unbacked && z.absent) garbled_ones.push_back(z);
    std::vector<std::uint8_t> garbled(a.columns() * n, 0);
    for (const auto& z : garbled_ones)
        for (std::size_t x = z.start; x < z.end; ++x) garbled[x * n + z.read] = 1;
    if (code) hear_reads_that_hold_parity(a, garbled_ones, garbled);
    return garbled;
}

// Per column: more than one read lost or added frames in the stretch of disagreement it stands in.
// There one read's slip can hide another's, so whether a frame stands in such a column is never
// decided silently by a vote.
std::vector<bool> slips_in_several_reads(const ReadAlignment& a, Reads reads) {
    const std::size_t n = a.reads();
    std::vector<bool> out(a.columns(), false);
    auto solid = [&](std::size_t c) { return unanimous(a, reads, c); };
    std::vector<bool> slipped(n);
    for (std::size_t c = 0; c < a.columns();) {
        if (solid(c)) {
            ++c;
            continue;
        }
        std::size_t end = c;
        std::fill(slipped.begin(), slipped.end(), false);
        for (; end < a.columns() && !solid(end); ++end) {
            std::size_t covering = 0, present = 0;
            for (std::size_t r = 0; r < n; ++r)
                if (a.covers(r, end)) ++covering, present += a.frame(end, r) != ReadAlignment::none;
            // A read slipped here when it is with the minority on whether a frame stands here (with a
            // tie, every read did).
            for (std::size_t r = 0; r < n; ++r) {
                if (!a.covers(r, end)) continue;
                bool has = a.frame(end, r) != ReadAlignment::none;
                std::size_t with = has ? present : covering - present;
                if (with * 2 <= covering) slipped[r] = true;
            }
        }
        bool several = std::count(slipped.begin(), slipped.end(), true) >= 2;
        for (; c < end; ++c) out[c] = several;
    }
    return out;
}

}  // namespace tape::detail
