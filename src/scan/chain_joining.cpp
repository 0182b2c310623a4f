// The parts of one strip's row of feed holes joined across a place where the holes are not seen (a
// smear, a label stuck on, a finger) (scan_geometry.hpp). A part is joined when it lies on the line's
// continuation a whole number of frames away: the frames between are then placed, and read as doubtful.
// A part of the line whose distance is no whole number of frames is not joined: it is named, never lost.
#include <algorithm>
#include <cmath>

#include "scan/scan_geometry.hpp"

namespace tape::scan {
namespace {

constexpr double longest_gap = 60;  // frames: beyond this a part is too far to count the frames between

struct End {
    ScanPoint at, out;  // the last hole, and the unit direction going on past it
    double pitch;
};

ScanPoint centre(const Blob& b) { return {b.x, b.y}; }

// The chain's end (its last blob when last, else its first), looking out of it, over up to 6 holes.
End end_of(std::span<const Blob> blobs, const FeedChain& c, bool last) {
    const std::size_t n = c.blobs.size(), k = std::min<std::size_t>(6, n - 1);
    std::size_t a = last ? n - 1 - k : k, b = last ? n - 1 : 0;
    std::size_t frames = 0;
    for (std::size_t i = std::min(a, b) + 1; i <= std::max(a, b); ++i) frames += c.missing_before[i] + 1U;
    ScanPoint p = centre(blobs[c.blobs[a]]), q = centre(blobs[c.blobs[b]]);
    double dx = q.x - p.x, dy = q.y - p.y, len = std::hypot(dx, dy);
    if (!(len > 0) || frames == 0) return {q, {0, 0}, c.pitch};
    return {q, {dx / len, dy / len}, len / static_cast<double>(frames)};
}

// Frames from end to blob, when blob lies on the line's continuation: along it, a whole number of pitches.
std::optional<std::size_t> frames_to(const End& e, const Blob& b, bool& ambiguous) {
    double dx = b.x - e.at.x, dy = b.y - e.at.y;
    double along = dx * e.out.x + dy * e.out.y, across = std::abs(-dx * e.out.y + dy * e.out.x);
    if (along < 0.5 * e.pitch || along > longest_gap * e.pitch || across > 0.3 * e.pitch + 0.01 * along)
        return std::nullopt;
    double k = along / e.pitch;
    if (std::abs(k - std::round(k)) > 0.2) {
        ambiguous = true;
        return std::nullopt;
    }
    return static_cast<std::size_t>(std::lround(k));
}

FeedChain turned(FeedChain c) {
    std::reverse(c.blobs.begin(), c.blobs.end());
    // missing_before[i] belongs between blobs i-1 and i: turned, it moves to the blob after the gap.
    std::vector<std::uint8_t> m(c.missing_before.size(), 0);
    for (std::size_t i = 1; i < m.size(); ++i) m[m.size() - i] = c.missing_before[i];
    c.missing_before = m;
    return c;
}

// main with part joined at one end, gap frames on; part's first hole is the one facing the gap.
void append(FeedChain& main, FeedChain part, std::size_t gap, bool at_end) {
    if (!at_end) main = turned(std::move(main));
    part.missing_before[0] = static_cast<std::uint8_t>(gap - 1);
    main.blobs.insert(main.blobs.end(), part.blobs.begin(), part.blobs.end());
    main.missing_before.insert(main.missing_before.end(), part.missing_before.begin(), part.missing_before.end());
    if (!at_end) main = turned(std::move(main));
}

}  // namespace

FeedChain join_parts(std::span<const Blob> blobs, std::span<const FeedChain> chains, std::size_t pick,
                     std::vector<std::size_t>& unjoined) {
    FeedChain main = chains[pick];
    std::vector<bool> used(chains.size(), false);
    used[pick] = true;
    auto alike = [&](const FeedChain& c) { return c.pitch < 1.2 * main.pitch && main.pitch < 1.2 * c.pitch; };
    for (bool joined = true; joined;) {
        joined = false;
        for (std::size_t k = 0; k < chains.size() && !joined; ++k) {
            if (used[k] || !alike(chains[k]) || !feed_like(chains[k])) continue;
            for (bool at_end : {true, false}) {
                End e = end_of(blobs, main, at_end);
                bool ambiguous = false;
                // The part's nearer end faces the gap: it joins as it runs, or turned.
                auto first = frames_to(e, blobs[chains[k].blobs.front()], ambiguous);
                auto last = frames_to(e, blobs[chains[k].blobs.back()], ambiguous);
                if (!first && !last) continue;
                bool keep = first && (!last || *first < *last);
                std::size_t gap = keep ? *first : *last;
                if (gap > 255) continue;  // counted in a byte; longest_gap keeps it far below
                append(main, keep ? chains[k] : turned(chains[k]), gap, at_end);
                used[k] = joined = true;
                break;
            }
        }
    }
    // Parts on the line that could not be counted in: said, so that nothing is lost without a word.
    for (std::size_t k = 0; k < chains.size(); ++k) {
        if (used[k] || !alike(chains[k]) || !feed_like(chains[k])) continue;
        for (bool at_end : {true, false}) {
            bool ambiguous = false;
            frames_to(end_of(blobs, main, at_end), blobs[chains[k].blobs.front()], ambiguous);
            frames_to(end_of(blobs, main, at_end), blobs[chains[k].blobs.back()], ambiguous);
            if (ambiguous) {
                unjoined.push_back(k);
                break;
            }
        }
    }
    main.pitch = chains[pick].pitch;
    main.hole_ratio = chains[pick].hole_ratio;
    return main;
}

}  // namespace tape::scan
