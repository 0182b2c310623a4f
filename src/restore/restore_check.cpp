// A restoration scored against the tape its reads were made from (tape/restore.hpp).
#include <algorithm>

#include "tape/restore.hpp"

namespace tape {

bool in_doubt(FrameStatus s) {
    using S = FrameStatus;
    return s == S::inferred || s == S::contested || s == S::unstable || s == S::unresolved || s == S::missing;
}

RestoreCheck check_restore(std::span<const Frame> tape, const RestoreResult& r) {
    RestoreCheck out;
    auto a = punched_part(tape), b = punched_part(r.frames);
    out.exact = std::equal(a.begin(), a.end(), b.begin(), b.end());
    std::vector<std::span<const Frame>> pair{tape, r.frames};
    ReadAlignment al = align_reads(pair);
    std::vector<FrameStatus> status(r.frames.size(), FrameStatus::clean);
    for (const auto& p : r.problems)
        if (p.frame && *p.frame <= status.size()) status[*p.frame - 1] = p.status;
    // Frames not written but said to be in doubt, by the restored frame they follow.
    std::vector<std::uint64_t> doubted;
    for (const auto& p : r.problems)
        if (!p.frame && in_doubt(p.status)) doubted.push_back(p.after);
    auto data = punched_part(tape);
    const auto first = static_cast<std::int64_t>(data.data() - tape.data());
    const auto last = first + static_cast<std::int64_t>(data.size()) - 1;  // the last punched frame
    auto matched = [&](std::size_t c) {
        std::int32_t t = al.frame(c, 0), o = al.frame(c, 1);
        return t != ReadAlignment::none && o != ReadAlignment::none &&
               tape[static_cast<std::size_t>(t)] == r.frames[static_cast<std::size_t>(o)];
    };
    // A tape frame the output lacks next to an output frame in doubt is that frame, misread: the two
    // stand in columns of their own when they differ in more than one hole. So a frame left out counts
    // as in doubt when the stretch of columns that do not match around it holds a frame in doubt.
    std::vector<bool> stretch_doubted(al.columns(), false);
    for (std::size_t c = 0; c < al.columns();) {
        if (matched(c)) {
            ++c;
            continue;
        }
        std::size_t end = c;
        bool doubt = false;
        for (; end < al.columns() && !matched(end); ++end) {
            std::int32_t o = al.frame(end, 1);
            doubt |= o != ReadAlignment::none && in_doubt(status[static_cast<std::size_t>(o)]);
        }
        std::fill(stretch_doubted.begin() + static_cast<std::ptrdiff_t>(c),
                  stretch_doubted.begin() + static_cast<std::ptrdiff_t>(end), doubt);
        c = end;
    }
    // A frame left out in doubt after output frame `after` may stand anywhere in the run of equal
    // frames there: the alignment puts a gap at the end of a run.
    std::sort(doubted.begin(), doubted.end());
    auto doubted_here = [&](std::size_t c, std::uint64_t written_before) {
        std::int32_t t = al.frame(c, 0);
        for (auto d = std::upper_bound(doubted.begin(), doubted.end(), written_before); d != doubted.begin();) {
            std::uint64_t after = *--d;
            if (after == written_before) return true;
            // Output frames after..written_before - 1 (0-based) all equal to the frame left out.
            for (std::uint64_t i = after; i < written_before; ++i)
                if (t == ReadAlignment::none || r.frames[i] != tape[static_cast<std::size_t>(t)]) return false;
            return true;
        }
        return false;
    };
    std::uint64_t written_before = 0;
    std::int64_t tape_before = -1;  // the last tape frame met
    for (std::size_t c = 0; c < al.columns(); ++c) {
        std::int32_t t = al.frame(c, 0), o = al.frame(c, 1);
        if (o != ReadAlignment::none) ++written_before;
        if (t != ReadAlignment::none) tape_before = t;
        bool blank = (t == ReadAlignment::none || tape[static_cast<std::size_t>(t)] == blank_frame) &&
                     (o == ReadAlignment::none || r.frames[static_cast<std::size_t>(o)] == blank_frame);
        bool ends = t != ReadAlignment::none ? (t < first || t > last) : (tape_before < first || tape_before >= last);
        if (blank && ends && (t == ReadAlignment::none || o == ReadAlignment::none)) {
            ++out.blank_ends;
            continue;
        }
        if (matched(c)) {
            ++out.right;
            continue;
        }
        bool doubt = o != ReadAlignment::none ? in_doubt(status[static_cast<std::size_t>(o)])
                                              : !al.covers(1, c) ||  // the ends: reported as missing
                                                    stretch_doubted[c] || doubted_here(c, written_before);
        ++(doubt ? out.flagged_wrong : out.silently_wrong);
    }
    return out;
}

}  // namespace tape
