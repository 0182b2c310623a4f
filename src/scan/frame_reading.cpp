// Frames from the sampled tracks (scan_geometry.hpp): a hole is punched when its centre and the ring
// inside its edge both look like the feed holes, blank when both look like paper; a speck of dust
// (smaller than a feed hole) darkens the centre only. Anything between is doubtful, and so is its frame.
#include <algorithm>
#include <cmath>

#include "scan/scan_geometry.hpp"

namespace tape::scan {
namespace {

float clamp01(float v) { return std::clamp(v, 0.0F, 1.0F); }

// The level a place at `offset` rows on one side gets, and which track that is (0: none).
int track_at(int offset, bool short_side, int tracks) {
    if (tracks == 8) return short_side ? (offset <= 3 ? 4 - offset : 0) : (offset <= 5 ? 3 + offset : 0);
    return short_side ? (offset <= 2 ? 3 - offset : 0) : (offset <= 3 ? 2 + offset : 0);
}

// Too little difference between paper and holes to tell them apart (grey levels).
constexpr float min_contrast = 12;

}  // namespace

ScanPoint hole_place(const FeedLine& line, std::size_t i, double rows, double across) {
    ScanPoint c = line.centre[i], t = line.along[i];
    double d = rows * across * line.pitch[i];
    return {c.x + t.y * d, c.y - t.x * d};
}

HoleReading read_hole(HoleLevel h) {
    if (!h.on_paper) return {false, 0};
    // Found away from its place on the grid: the hole is there, its frame less sure.
    float placed = clamp01((0.35F - h.shift) / 0.15F);
    float low = std::min(h.core, h.ring), high = std::max(h.core, h.ring);
    if (low >= 0.5F) return {true, std::min(placed, clamp01((low - 0.5F) / 0.25F))};
    if (high < 0.5F) return {false, clamp01((0.5F - high) / 0.25F)};
    if (h.ring < 0.5F && h.core >= 0.5F)  // a dark (or light) centre with paper around it: a speck
        return {false, clamp01((0.3F - h.ring) / 0.2F)};
    return {h.ring >= 0.5F, 0};  // the ring says hole, the centre paper: something half in the way
}

std::vector<ScannedFrame> read_frames(const FeedLine& line, std::span<const FrameSamples> samples, int tracks,
                                      bool track1_left, double across) {
    const std::size_t n = samples.size();
    std::vector<ScannedFrame> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const FrameSamples& s = samples[i];
        ScannedFrame& f = out[i];
        f.feed = line.centre[i];
        f.feed_seen = s.feed_seen;
        float least = 1;
        int least_track = 0;
        bool off_paper = false;
        for (int side = 0; side < 2; ++side) {
            bool left = side == 0, short_side = left == track1_left;
            for (int o = 1; o <= 5; ++o) {
                int t = track_at(o, short_side, tracks);
                if (t == 0) continue;
                const HoleLevel& level = left ? s.left[o - 1] : s.right[o - 1];
                HoleReading r = read_hole(level);
                f.hole[t - 1] = hole_place(line, i, left ? o : -o, across);
                if (r.punched) f.frame = static_cast<Frame>(f.frame | 1U << (t - 1));
                f.hole_confidence[t - 1] = r.confidence;
                if (r.confidence < least) least = r.confidence, least_track = t, off_paper = !level.on_paper;
            }
        }
        f.confidence = least;
        if (std::abs(s.paper - s.hole) < min_contrast) {
            f.confidence = 0;
            f.doubt = "too little contrast between the paper and the holes";
        } else if (!s.feed_seen) {
            f.confidence = std::min(f.confidence, 0.25F);
            f.doubt = "no feed hole seen here (placed between its neighbours)";
        } else if (least < doubt_below) {
            f.doubt = "track " + std::to_string(least_track) +
                      (off_paper ? ": no paper there (cut or torn)" : " is neither clearly punched nor clearly blank");
        }
    }
    // A feed hole away from the line through its neighbours: a tear, a blob of dirt read as the hole.
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (!line.seen[i] || !out[i].doubt.empty()) continue;
        ScanPoint a = line.centre[i - 1], b = line.centre[i + 1], c = line.centre[i];
        double off = std::hypot(c.x - (a.x + b.x) / 2, c.y - (a.y + b.y) / 2) / line.pitch[i];
        if (off > 0.2) {
            out[i].confidence = std::min(out[i].confidence, 0.25F);
            out[i].doubt = "its feed hole is off the line of the others";
        }
    }
    return out;
}

}  // namespace tape::scan
