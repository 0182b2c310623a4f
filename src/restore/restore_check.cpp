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
    const std::size_t offset = static_cast<std::size_t>(b.data() - r.frames.data());
    const Doubts d = doubts_of(r);
    std::vector<std::span<const Frame>> pair{a, b};
    ReadAlignment al = align_reads(pair, AlignOptions{.min_shared = 0, .drop_unrelated = false});
    auto matched = [&](std::size_t c) {
        std::int32_t t = al.frame(c, 0), o = al.frame(c, 1);
        return t != ReadAlignment::none && o != ReadAlignment::none &&
               a[static_cast<std::size_t>(t)] == b[static_cast<std::size_t>(o)];
    };
    std::size_t written_before = offset;  // output frames before this column
    std::size_t tape_at = 0;              // the tape frame of this column, or of the last one before it
    for (std::size_t c = 0; c < al.columns();) {
        if (matched(c)) {
            if (al.frame(c, 0) != ReadAlignment::none) tape_at = static_cast<std::size_t>(al.frame(c, 0));
            ++out.right, ++written_before, ++c;
            continue;
        }
        // A stretch of columns that do not match: a misread stretch is one place, in doubt where the report
        // puts a doubt anywhere in it (a frame, or frames left out at either end), else frame by frame.
        std::size_t end = c, from = written_before, to = written_before;
        bool stretch_doubt = false;
        for (; end < al.columns() && !matched(end); ++end)
            if (al.frame(end, 1) != ReadAlignment::none) {
                stretch_doubt |= d.frame[offset + static_cast<std::size_t>(al.frame(end, 1))];
                ++to;
            }
        for (std::size_t i = from; i <= to && i < d.after.size(); ++i) stretch_doubt |= d.after[i];
        for (; c < end; ++c) {
            std::int32_t t = al.frame(c, 0), o = al.frame(c, 1);
            if (t != ReadAlignment::none) tape_at = static_cast<std::size_t>(t);
            bool doubt = stretch_doubt;
            std::size_t output_at = written_before;
            if (o != ReadAlignment::none) {
                std::size_t i = offset + static_cast<std::size_t>(o);
                doubt |= run_in_doubt(r, d, i, i + 1, r.frames[i]);
                ++written_before;
            } else {
                Frame left_out = a[static_cast<std::size_t>(t)];
                doubt |= run_in_doubt(r, d, written_before, written_before, left_out);
            }
            (doubt ? out.flagged_at : out.silent_at)
                .push_back(static_cast<std::size_t>(a.data() - tape.data()) + tape_at);
            (doubt ? out.flagged_output : out.silent_output).push_back(output_at);
            ++(doubt ? out.flagged_wrong : out.silently_wrong);
        }
    }
    return out;
}

}  // namespace tape
