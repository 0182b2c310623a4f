// Restoration: a vote per aligned column, then single-hole repair of what no read has right, checked
// against the grammar of the block it stands in (tape/restore.hpp).
#include "tape/restore.hpp"

#include <algorithm>
#include <array>

#include "repair.hpp"

namespace tape {
namespace {

bool good(const std::optional<FrameCode>& code, Frame f) { return !code || !is_bad_frame(code->kind(f)); }

struct Tally {
    Frame value;
    int count;
    bool good;
};

// Per read and column: the read garbled this stretch. Where a read has frames no other read backs
// next to places where it lacks frames the others have (a stain read as other frames, or a splice),
// its frames there are misreadings and its gaps say nothing: it is not heard on whether a frame
// stands there. A frame is backed when another read has the same, or one hole from it (the same
// frame misread), or when it is the only good one among frames failing parity.
std::vector<std::uint8_t> garbled_stretches(const ReadAlignment& a, std::span<const std::span<const Frame>> reads,
                                            const std::optional<FrameCode>& code) {
    const std::size_t n = a.reads();
    auto at = [&](std::size_t c, std::size_t r) { return frame_at(a, reads, c, r); };
    auto backed = [&](std::size_t c, std::size_t r, Frame f) {
        bool others = false, others_good = false;
        for (std::size_t s = 0; s < n; ++s) {
            if (s == r) continue;
            auto g = at(c, s);
            if (!g) continue;
            if (hole_count(*g ^ f) <= 1) return true;
            others = true;
            others_good |= good(code, *g);
        }
        return others && !others_good && good(code, f);
    };
    // A frame that happens to equal its neighbour may split one garbled stretch in two (a stain read
    // as "33" next to a real "33"); stretches this close are one.
    constexpr std::size_t bridged = 2;
    struct Stretch {
        std::size_t read, start, end;
        bool unbacked = false, absent = false;
        std::size_t failing = 0;  // frames failing parity
    };
    std::vector<Stretch> garbled_ones;
    for (std::size_t r = 0; r < n; ++r) {
        std::vector<Stretch> stretches;
        for (std::size_t c = a.first_column(r); c < a.end_column(r);) {
            // A stretch where the read's frames are not backed, or it has none while others have.
            Stretch z{r, c, c};
            for (; c < a.end_column(r); ++c) {
                auto f = at(c, r);
                if (f && backed(c, r, *f)) break;
                z.unbacked |= f.has_value();
                z.failing += f && !good(code, *f);
                // Absent where most other reads have a frame; a frame one other read alone has (read
                // twice) says nothing of this read.
                if (!f) {
                    std::size_t with = 0, without = 0;
                    for (std::size_t s = 0; s < n; ++s)
                        if (s != r && a.covers(s, c)) (at(c, s) ? with : without) += 1;
                    z.absent |= with > without;
                }
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
        for (const auto& z : stretches)
            if (z.unbacked && z.absent) garbled_ones.push_back(z);
    }
    std::vector<std::uint8_t> garbled(a.columns() * n, 0);
    for (const auto& z : garbled_ones)
        for (std::size_t x = z.start; x < z.end; ++x) garbled[x * n + z.read] = 1;
    // Where every read garbled the same stretch by that measure (two reads, one of them stained), parity
    // tells them apart: a read whose frames there all hold parity is heard when another's fail it.
    if (!code) return garbled;
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
    return garbled;
}

// Per column: more than one read lost or added frames in the stretch of disagreement it stands in.
// There one read's slip can hide another's, so whether a frame stands in such a column is never
// decided silently by a vote.
std::vector<bool> slips_in_several_reads(const ReadAlignment& a, std::span<const std::span<const Frame>> reads) {
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

// Among good readings tied at the top of the tally (sorted: good first, most first): the one that a
// reading failing parity is one hole from, when that is true of just one.
std::optional<Frame> leaning(const std::vector<Tally>& tally) {
    std::optional<Frame> out;
    for (const auto& t : tally) {
        if (!t.good || t.count != tally.front().count) continue;
        bool near = std::any_of(tally.begin(), tally.end(),
                                [&](const Tally& bad) { return !bad.good && hole_count(bad.value ^ t.value) == 1; });
        if (!near) continue;
        if (out) return std::nullopt;
        out = t.value;
    }
    return out;
}

// True when the frame read r has at index i is also its neighbour in that read: a frame read twice
// looks so, and so does a frame punched twice.
bool repeated(std::span<const Frame> read, std::size_t i) {
    return (i > 0 && read[i - 1] == read[i]) || (i + 1 < read.size() && read[i + 1] == read[i]);
}

}  // namespace

std::string_view status_name(FrameStatus s) {
    static constexpr std::array<std::string_view, frame_status_count> names = {
        "clean", "voted", "inferred", "contested", "unstable", "unresolved", "missing", "extra"};
    return names[static_cast<std::size_t>(s)];
}

bool RestoreResult::complete() const {
    return count(FrameStatus::contested) + count(FrameStatus::unstable) + count(FrameStatus::unresolved) +
               count(FrameStatus::missing) ==
           0;
}

double frame_distance_cm(std::uint64_t frame) { return frame == 0 ? 0 : static_cast<double>(frame - 1) * 0.254; }

RestoreResult restore(std::span<const std::span<const Frame>> reads, const RestoreOptions& o) {
    ReadAlignment a = align_reads(reads, o.align);
    RestoreResult out;
    out.reference = a.reference();
    for (std::size_t r = 0; r < a.reads(); ++r) out.shared.push_back(a.shared(r));
    std::vector<std::size_t> unresolved;  // problems to try to repair once the whole image stands
    std::vector<Tally> tally;
    const std::vector<std::uint8_t> garbled = garbled_stretches(a, reads, o.code);
    const std::vector<bool> tangled = slips_in_several_reads(a, reads);
    // The columns from the first to the last where a read has a frame of more than one hole (one hole
    // in blank tape is more likely a misread blank).
    std::size_t punched_from = a.columns(), punched_to = 0;
    for (std::size_t c = 0; c < a.columns(); ++c)
        for (std::size_t r = 0; r < a.reads(); ++r)
            if (hole_count(frame_at(a, reads, c, r).value_or(blank_frame)) > 1) {
                punched_from = std::min(punched_from, c);
                punched_to = c + 1;
            }
    // Per column: the one read that has a frame there, or none.
    std::vector<std::int32_t> alone(a.columns(), ReadAlignment::none);
    for (std::size_t c = 0; c < a.columns(); ++c) {
        std::size_t with = 0;
        for (std::size_t r = 0; r < a.reads(); ++r)
            if (a.frame(c, r) != ReadAlignment::none) ++with, alone[c] = static_cast<std::int32_t>(r);
        if (with != 1) alone[c] = ReadAlignment::none;
    }
    // Every read that covers column c and lacks a frame there has frames in the columns beside it: it
    // lost one frame (or the others read one twice), not a stretch.
    auto lone_gaps = [&](std::size_t c) {
        for (std::size_t r = 0; r < a.reads(); ++r) {
            if (!a.covers(r, c) || a.frame(c, r) != ReadAlignment::none) continue;
            if ((c > 0 && a.covers(r, c - 1) && a.frame(c - 1, r) == ReadAlignment::none) ||
                (c + 1 < a.columns() && a.covers(r, c + 1) && a.frame(c + 1, r) == ReadAlignment::none))
                return false;
        }
        return true;
    };
    auto alone_beside = [&](std::size_t c) {  // the read alone here is alone in a neighbouring column too
        return alone[c] != ReadAlignment::none &&
               ((c > 0 && alone[c - 1] == alone[c]) || (c + 1 < a.columns() && alone[c + 1] == alone[c]));
    };
    for (std::size_t c = 0; c < a.columns(); ++c) {
        tally.clear();
        // present: frames heard here; lost: reads that cover this place, are heard, and have no frame.
        std::size_t present = 0, covering = 0, lost = 0, unheard = 0;
        bool repeat = false;  // a read has this frame next to an equal one
        for (std::size_t r = 0; r < a.reads(); ++r) {
            if (!a.covers(r, c)) continue;
            ++covering;
            bool heard = !garbled[c * a.reads() + r];
            std::int32_t i = a.frame(c, r);
            if (i == ReadAlignment::none) {
                ++(heard ? lost : unheard);
                continue;
            }
            if (!heard) {
                ++unheard;
                continue;
            }
            ++present;
            Frame f = reads[r][static_cast<std::size_t>(i)];
            repeat |= repeated(reads[r], static_cast<std::size_t>(i));
            auto t = std::find_if(tally.begin(), tally.end(), [&](const Tally& x) { return x.value == f; });
            if (t == tally.end())
                tally.push_back({f, 1, good(o.code, f)});
            else
                ++t->count;
        }
        // Whether a frame stands here at all is weighed by the good readings: a frame failing parity
        // may be a misread of this frame or garbage a stain put between two (the reads' alignment
        // cannot tell inside a burst), so it counts for neither side.
        std::size_t present_good = 0, good_values = 0;
        for (const auto& t : tally) {
            present_good += t.good ? static_cast<std::size_t>(t.count) : 0;
            good_values += t.good;
        }
        std::sort(tally.begin(), tally.end(),
                  [](const Tally& x, const Tally& y) { return x.good != y.good ? x.good : x.count > y.count; });
        const std::optional<Frame> reference_frame = frame_at(a, reads, c, a.reference());
        auto problem = [&](FrameStatus s, Frame written, std::string reason, bool dropped) {
            RestoreProblem p;
            p.status = s;
            p.column = c;
            p.written = written;
            p.reason = std::move(reason);
            for (std::size_t r = 0; r < a.reads(); ++r) {
                p.seen.push_back(frame_at(a, reads, c, r));
                p.covered.push_back(a.covers(r, c));
            }
            if (!dropped) p.frame = out.frames.size() + 1;
            p.after = out.frames.size();
            out.problems.push_back(std::move(p));
        };
        if (tally.empty()) {  // only reads that garbled this stretch have a frame here
            Frame seen = 0;   // the first read's that has a frame here
            for (std::size_t r = a.reads(); r-- > 0;) seen = frame_at(a, reads, c, r).value_or(seen);
            FrameStatus s = tangled[c] ? FrameStatus::contested : FrameStatus::extra;
            problem(s, seen,
                    tangled[c] ? "only reads that misread this stretch have a frame here, and more than one read "
                                 "slipped in it: not written, but nothing decides"
                               : "a misreading: the read that has this frame lacks frames the others have next to "
                                 "it, so it read a stain or splice as other frames; not written",
                    true);
            ++out.counts[static_cast<std::size_t>(s)];
            continue;
        }
        FrameStatus s;
        bool half_dropped = false;
        Frame written = tally.front().value;
        std::string reason;
        // Blank tape past the end of most reads: leader or trailer that one read has longer (a frame
        // read twice there has nothing to align by). The length most reads have is kept.
        // (Leader and trailer are blank tape whose length no one needs: the reads disagree on it, and
        // a read that started later or stopped sooner did not see all of it; never in doubt.)
        bool in_blank_ends = c < punched_from || c >= punched_to;
        bool lone_blank_end = a.reads() > 1 && tally.size() == 1 && tally.front().value == blank_frame &&
                              ((covering < a.reads() && present * 2 <= a.reads()) || in_blank_ends);
        const std::size_t lost_here = lost;  // by reads that cover this place
        if (lone_blank_end && covering < a.reads()) lost = a.reads() - present;
        if (tally.front().good) present = present_good;
        // A frame read twice equals its neighbour; one that does not, only one read has, and that read
        // read well around it, the others lost (or a splice put it there): nothing decides.
        // (Several such frames in a row are a stretch one read misread: the others losing every one
        // of them is far less likely.)
        bool lone_unlike_neighbours = present == 1 && lost > 1 && tally.front().good && !repeat &&
                                      tally.front().value != blank_frame && !lone_blank_end && !alone_beside(c);
        if (lone_blank_end && present >= lost) {
            s = lost_here + unheard == 0 ? FrameStatus::clean : FrameStatus::voted;
            reason = "blank leader or trailer, of a length the reads disagree on: written";
        } else if (lone_unlike_neighbours) {
            s = FrameStatus::contested;
            reason = "1 of " + std::to_string(covering) +
                     " reads has this frame, not as a neighbour read twice: the others lost it, or a splice "
                     "put it there; written";
        } else if (present < lost && (present <= 1 || good_values > 1 || !tally.front().good || lone_blank_end)) {
            s = FrameStatus::extra;
            reason = std::to_string(present) + " of " + std::to_string(covering) +
                     " reads have this frame: read twice or a splice, not written";
        } else if (present < lost) {
            // Two reads or more agree on a frame the others lack: read twice by both, or lost by the
            // others, which is as likely. Written, and said.
            s = FrameStatus::contested;
            reason = std::to_string(present) + " of " + std::to_string(covering) +
                     " reads agree on this frame and the others have none: lost by them, or read twice; not "
                     "written, as most reads have none";
        } else if (!tally.front().good) {
            s = FrameStatus::unresolved;  // repaired below if exactly one change fits
            written = reference_frame.value_or(written);
            reason = "no read has a good frame here";
        } else if (tally.size() == 1 && lost == 0 && unheard == 0) {
            s = FrameStatus::clean;
        } else if (unheard > 0 && present == 1 && lost == 0) {
            s = FrameStatus::contested;
            reason = "1 of " + std::to_string(covering) +
                     " reads has this frame and the others misread this stretch: written, but nothing backs it";
        } else if (present == lost) {
            // A frame like its neighbour may be one read twice; one unlike them cannot be.
            s = FrameStatus::contested;
            // (A read lacking a whole stretch, torn or slipped, is decided as one: written.)
            half_dropped = repeat && !alone_beside(c) && tally.front().value != blank_frame && lone_gaps(c);
            reason = half_dropped ? "half the reads that cover this place have a frame here, half do not; like its "
                                    "neighbour, it may be read twice: not written"
                     : repeat     ? "half the reads that cover this place have a frame here, half do not; the others "
                                    "lack a stretch here: written"
                                  : "half the reads that cover this place have a frame here, half do not; unlike its "
                                    "neighbours, it cannot be read twice: written";
        } else if (lost > 0 && repeat && good_values == 1) {
            // Reads disagree on how many times a frame is punched: one lost a copy, or the others read
            // it twice, and the frame's neighbours cannot tell which.
            s = FrameStatus::contested;
            reason = std::to_string(present) + " of " + std::to_string(covering) +
                     " reads have this frame once more than the others: lost by them, or read twice; written";
        } else if (tally.size() == 1 || !tally[1].good || tally[0].count > tally[1].count) {
            s = FrameStatus::voted;
            reason = tally.size() > 1 && !tally[1].good && tally[0].count <= tally[1].count
                         ? "the only good reading (the others fail parity)"
                         : std::to_string(tally[0].count) + " of " + std::to_string(covering) + " reads agree";
        } else {
            bool all_differ = present >= 3 && tally.size() == present;
            s = all_differ ? FrameStatus::unstable : FrameStatus::contested;
            if (reference_frame && good(o.code, *reference_frame)) written = *reference_frame;
            reason = all_differ ? "every read saw something else"
                                : "good readings disagree and nothing decides; the reference read's is written";
            // A reading failing parity one hole from just one of the tied good readings leans to it.
            if (auto lean = leaning(tally); lean && !all_differ) {
                written = *lean;
                reason =
                    "good readings disagree; a reading failing parity is one hole from this one, which "
                    "is written";
            }
        }
        if (tangled[c] && !lone_blank_end && (s == FrameStatus::extra || (s == FrameStatus::voted && lost > 0))) {
            reason = std::to_string(present) + " of " + std::to_string(covering) +
                     " reads have this frame, and more than one read slipped in this stretch: " +
                     (s == FrameStatus::extra ? "not written" : "written") + ", but nothing decides";
            s = FrameStatus::contested;
        }
        bool dropped =
            half_dropped ||
            (present < lost && (s == FrameStatus::extra || (s == FrameStatus::contested && !lone_unlike_neighbours)));
        ++out.counts[static_cast<std::size_t>(s)];
        if (s != FrameStatus::clean) {
            if (s == FrameStatus::unresolved) unresolved.push_back(out.problems.size());
            problem(s, written, std::move(reason), dropped);
        }
        if (!dropped) out.frames.push_back(written);
    }
    if (o.code) {
        detail::repair_unresolved(out, unresolved, *o.code, o.dialect, o.spec);
        detail::number_lines(out, *o.code);
    }
    // The ends: a tape is punched with blank leader and trailer; where no read has one, its end may
    // be missing (every read started late, or stopped early).
    auto add_missing = [&](bool start) {
        RestoreProblem p;
        p.status = FrameStatus::missing;
        p.frame = start ? 1 : out.frames.size();
        p.column = start ? 0 : a.columns() - 1;
        p.reason = start ? "no read starts with leader: the start of the tape may be missing; read it again "
                           "from before its first punched frame"
                         : "no read ends with trailer: the end of the tape may be missing; read it again to "
                           "past its last punched frame";
        ++out.counts[static_cast<std::size_t>(FrameStatus::missing)];
        if (start)
            out.problems.insert(out.problems.begin(), std::move(p));
        else
            out.problems.push_back(std::move(p));
    };
    // Leader is blank tape, or (DEC binary tapes) a run of one frame, such as track 8 alone.
    auto leader_like = [&](bool start) {
        constexpr std::size_t run = 10;
        if (out.frames.empty()) return true;
        Frame end = start ? out.frames.front() : out.frames.back();
        if (end == blank_frame) return true;
        if (out.frames.size() < run) return false;
        for (std::size_t i = 0; i < run; ++i)
            if ((start ? out.frames[i] : out.frames[out.frames.size() - 1 - i]) != end) return false;
        return true;
    };
    if (!leader_like(true)) {
        out.missing_start = 1;
        add_missing(true);
    }
    if (!leader_like(false)) {
        out.missing_end = 1;
        add_missing(false);
    }
    return out;
}

}  // namespace tape
