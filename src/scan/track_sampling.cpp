// Each frame's tracks sampled in the picture (scan_geometry.hpp). A place is measured against the
// paper around it and the backing seen through the feed holes nearby, so that light that falls unevenly,
// tinted or stained paper, and a dark or a light backing read alike: 0 is paper, 1 is a hole.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "scan/blob_grid.hpp"
#include "scan/scan_geometry.hpp"

namespace tape::scan {
namespace {

constexpr double core_radius = 0.12;  // of the points averaged at a hole's centre, in pitches
constexpr double ring_radius = 0.25;  // inside a code hole (radius 0.36) and outside a feed hole (0.23)
constexpr double feed_core = 0.08;
constexpr int side_offsets = 5;
constexpr double edge_from = 2.5, edge_to = 8.0, edge_step = 0.25;  // where the paper's edge is looked for
constexpr int edge_samples = static_cast<int>((edge_to - edge_from) / edge_step) + 1;

template <std::size_t N>
float median_of(std::array<float, N> v, std::size_t n = N) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n / 2),
                     v.begin() + static_cast<std::ptrdiff_t>(n));
    return v[n / 2];
}

float median_of(std::vector<float> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// Local coordinates at one frame: u along the tape, v across (positive to the left, looking along).
struct Frame2 {
    ScanPoint c, t, n;
    double p, a;  // pitch along, and across as a multiple of it
    ScanPoint at(double u, double v) const {
        return {c.x + (t.x * u + n.x * v * a) * p, c.y + (t.y * u + n.y * v * a) * p};
    }
};

Frame2 frame_at(const FeedLine& line, std::size_t i, double across) {
    ScanPoint t = line.along[i];
    return {line.centre[i], t, ScanPoint{t.y, -t.x}, line.pitch[i], across};
}

float mean_at(const GreyView& g, const Frame2& f, double u, double v, double r, int points) {
    ScanPoint c = f.at(u, v);
    float sum = g.at(c.x, c.y);
    for (int k = 0; k < points; ++k) {
        double a = 2 * std::numbers::pi * (k + 0.5) / points;
        ScanPoint q = f.at(u + r * std::cos(a), v + r * std::sin(a) / f.a);
        sum += g.at(q.x, q.y);
    }
    return sum / static_cast<float>(points + 1);
}

float ring_at(const GreyView& g, const Frame2& f, double u, double v, double r) {
    float sum = 0;
    for (int k = 0; k < 8; ++k) {
        double a = 2 * std::numbers::pi * (k + 0.5) / 8;
        ScanPoint q = f.at(u + r * std::cos(a), v + r * std::sin(a) / f.a);
        sum += g.at(q.x, q.y);
    }
    return sum / 8;
}

// One place of a code hole: its levels, the paper right around it, and how far it was moved onto a blob.
struct RawHole {
    float core = 0, ring = 0, paper = 0, shift = 0;
    std::array<float, 2> beside{};  // between it and the rows next to it: always paper on a whole tape
};

// What one frame gives before it is compared with its neighbours: raw grey levels.
struct RawFrame {
    float paper = 0, feed = -1;  // feed < 0: no feed hole seen here
    float feed_ring = 0;         // where the blobs missed the feed hole: the level inside its edge
    RawHole hole[2][side_offsets];
    float edge[2][edge_samples]{};
};

// The paper right around a place: the middle of the points between it and its diagonal neighbours and
// between it and the rows beside it, where no hole can be (a speck on one, or the tape's end beyond two,
// does not count).
float paper_around(const GreyView& g, const Frame2& f, double v, std::array<float, 2>& beside) {
    std::array<float, 6> p{};
    std::size_t k = 0;
    for (double du : {-0.5, 0.5})
        for (double dv : {-0.5, 0.5}) {
            ScanPoint q = f.at(du, v + dv);
            p[k++] = g.at(q.x, q.y);
        }
    for (double dv : {-0.5, 0.5}) {
        ScanPoint q = f.at(0, v + dv);
        beside[k - 4] = p[k] = g.at(q.x, q.y);
        ++k;
    }
    std::sort(p.begin(), p.end());
    return (p[2] + p[3]) / 2;
}

RawHole sample_hole(const GreyView& g, const Frame2& f, double v, const Grid& grid, std::span<const Blob> blobs) {
    RawHole h;
    ScanPoint q = f.at(0, v);
    auto p = static_cast<float>(f.p);
    std::uint32_t b =
        nearest_blob(grid, blobs, static_cast<float>(q.x), static_cast<float>(q.y), 0.35F * p, 0.5F * p, p);
    Frame2 at = f;
    if (b != UINT32_MAX) {
        h.shift = std::hypot(blobs[b].x - static_cast<float>(q.x), blobs[b].y - static_cast<float>(q.y)) / p;
        at.c = {blobs[b].x - (q.x - f.c.x), blobs[b].y - (q.y - f.c.y)};
    }
    h.core = mean_at(g, at, 0, v, core_radius, 4);
    h.ring = ring_at(g, at, 0, v, ring_radius);
    h.paper = paper_around(g, f, v, h.beside);
    return h;
}

RawFrame sample_raw(const GreyView& g, const FeedLine& line, std::size_t i, double across, const Grid& grid,
                    std::span<const Blob> blobs) {
    RawFrame r;
    Frame2 f = frame_at(line, i, across);
    if (line.seen[i])
        r.feed = mean_at(g, f, 0, 0, feed_core, 4);
    else
        r.feed_ring = mean_at(g, f, 0, 0, 0.12, 6);
    // The paper between the rows and the frames, where no hole can be.
    std::array<float, 12> paper{};
    std::size_t k = 0;
    for (double u : {-0.5, 0.5})
        for (double v : {-2.5, -1.5, -0.5, 0.5, 1.5, 2.5}) {
            ScanPoint q = f.at(u, v);
            paper[k++] = g.at(q.x, q.y);
        }
    r.paper = median_of(paper);
    for (int s = 0; s < 2; ++s) {
        double sign = s == 0 ? 1 : -1;  // 0: left, 1: right
        for (int o = 0; o < side_offsets; ++o) r.hole[s][o] = sample_hole(g, f, sign * (o + 1), grid, blobs);
        for (int e = 0; e < edge_samples; ++e) {
            ScanPoint q = f.at(0.5, sign * (edge_from + e * edge_step));
            r.edge[s][e] = g.at(q.x, q.y);
        }
    }
    return r;
}

// The first place, going out from the feed line, from which on the picture is no longer paper: the
// paper's edge, in pitches; 0 when it is not seen.
float edge_of(const float* levels, float paper, float contrast) {
    for (int e = 0; e + 1 < edge_samples; ++e) {
        float h0 = (paper - levels[e]) / contrast, h1 = (paper - levels[e + 1]) / contrast;
        if (h0 > 0.5F && h1 > 0.5F) return static_cast<float>(edge_from + (e - 0.5) * edge_step);
    }
    return 0;
}

HoleLevel level_of(const RawHole& h, float frame_paper, float hole) {
    float contrast = h.paper - hole;
    HoleLevel l;
    l.shift = h.shift;
    // Round the place, paper that looks more like the backing than like paper: the paper is not there (a
    // cut corner, a tear). Ink and stains darken paper the other way, or less.
    float toward_hole = frame_paper == hole ? 0 : (frame_paper - h.paper) / (frame_paper - hole);
    l.on_paper = toward_hole < 0.5F;
    if (std::abs(contrast) < 1) contrast = contrast < 0 ? -1.0F : 1.0F;
    l.core = (h.paper - h.core) / contrast;
    l.ring = (h.paper - h.ring) / contrast;
    return l;
}

}  // namespace

float GreyView::at(double x, double y) const {
    if (width <= 0 || height <= 0 || !pixels) return 0;
    if (!(x >= 0)) x = 0;  // also NaN
    if (!(y >= 0)) y = 0;
    x = std::min(x, static_cast<double>(width - 1));
    y = std::min(y, static_cast<double>(height - 1));
    int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
    float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
    auto px = [&](int xx, int yy) { return static_cast<float>(pixels[yy * stride + xx]); };
    float top = px(x0, y0) + (px(x1, y0) - px(x0, y0)) * fx;
    float bottom = px(x0, y1) + (px(x1, y1) - px(x0, y1)) * fx;
    return top + (bottom - top) * fy;
}

std::vector<FrameSamples> sample_frames(const GreyView& g, const FeedLine& line, double across,
                                        std::span<const Blob> blobs) {
    const std::size_t n = line.centre.size();
    Grid grid(blobs, std::max(2.0F, static_cast<float>(line.pitch.empty() ? 2 : line.pitch[n / 2])));
    std::vector<RawFrame> raw(n);
    for (std::size_t i = 0; i < n; ++i) raw[i] = sample_raw(g, line, i, across, grid, blobs);
    std::vector<float> feeds;
    for (const auto& r : raw)
        if (r.feed >= 0) feeds.push_back(r.feed);
    const float all_feed = median_of(feeds);
    std::vector<FrameSamples> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        // Paper and hole levels over the neighbouring frames: one speck or one stain does not set them.
        std::array<float, 5> paper{};
        std::array<float, 7> feed{};
        std::size_t np = 0, nf = 0;
        for (std::size_t j = i > 3 ? i - 3 : 0; j < std::min(n, i + 4); ++j) {
            if (j + 2 >= i && j <= i + 2) paper[np++] = raw[j].paper;
            if (raw[j].feed >= 0) feed[nf++] = raw[j].feed;
        }
        FrameSamples& s = out[i];
        s.paper = median_of(paper, np);
        s.hole = nf ? median_of(feed, nf) : all_feed;
        float contrast = s.paper - s.hole;
        if (std::abs(contrast) < 1) contrast = contrast < 0 ? -1.0F : 1.0F;
        // A feed hole the blobs missed (joined to a neighbour, or dimmed) is still seen by its level.
        s.feed_seen = line.seen[i] || (s.paper - raw[i].feed_ring) / contrast > 0.6F;
        for (int o = 0; o < side_offsets; ++o) {
            s.left[o] = level_of(raw[i].hole[0][o], s.paper, s.hole);
            s.right[o] = level_of(raw[i].hole[1][o], s.paper, s.hole);
        }
        s.left_edge = edge_of(raw[i].edge[0], s.paper, contrast);
        s.right_edge = edge_of(raw[i].edge[1], s.paper, contrast);
    }
    return out;
}

double across_scale(std::span<const Blob> blobs, const FeedLine& line) {
    const std::size_t n = line.centre.size();
    if (n < 2) return 1;
    // Frames by their distance along the straight line from the first to the last.
    ScanPoint a = line.centre.front(), b = line.centre.back();
    double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (!(len > 0)) return 1;
    dx /= len, dy /= len;
    std::vector<double> at(n);
    for (std::size_t i = 0; i < n; ++i) at[i] = (line.centre[i].x - a.x) * dx + (line.centre[i].y - a.y) * dy;
    std::vector<float> ratios;
    for (const auto& blob : blobs) {
        double u = (blob.x - a.x) * dx + (blob.y - a.y) * dy;
        auto it = std::lower_bound(at.begin(), at.end(), u);
        std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(it - at.begin()), n - 1);
        if (i > 0 && std::abs(at[i - 1] - u) < std::abs(at[i] - u)) --i;
        Frame2 f = frame_at(line, i, 1);
        double rx = blob.x - f.c.x, ry = blob.y - f.c.y;
        double along = (rx * f.t.x + ry * f.t.y) / f.p, acr = std::abs(rx * f.n.x + ry * f.n.y) / f.p;
        // Code holes only (larger than the feed holes), near their frame, one to five rows out.
        if (std::abs(along) > 0.3 || acr < 0.6 || acr > 5.6 || blob.diameter < 0.6 * f.p) continue;
        double rows = std::round(acr);
        if (std::abs(acr / rows - 1) < 0.2) ratios.push_back(static_cast<float>(acr / rows));
    }
    if (ratios.size() < 8) return 1;
    return std::clamp(static_cast<double>(median_of(ratios)), 0.8, 1.25);
}

TrackSide track_side(std::span<const FrameSamples> samples, int tracks) {
    // The paper reaches 4 pitches beyond the feed line on the side of tracks 1-3 and 6 on the other
    // (25.4 mm tape); 5-track tape (17.46 mm): about 2.9 and 3.9.
    const double near_edge = tracks == 8 ? 4.0 : 2.94, far_edge = tracks == 8 ? 6.0 : 3.94;
    const int near_rows = tracks == 8 ? 3 : 2;
    std::vector<float> left, right;
    std::size_t holes[2] = {0, 0};
    for (const auto& s : samples) {
        if (s.left_edge > 0) left.push_back(s.left_edge);
        if (s.right_edge > 0) right.push_back(s.right_edge);
        // Holes beyond the rows the short side has, where the paper still is.
        for (int o = near_rows; o < tracks - near_rows; ++o) {
            if ((s.left_edge == 0 || o + 1 < s.left_edge - 0.5) && read_hole(s.left[o]).punched &&
                read_hole(s.left[o]).confidence >= doubt_below)
                ++holes[0];
            if ((s.right_edge == 0 || o + 1 < s.right_edge - 0.5) && read_hole(s.right[o]).punched &&
                read_hole(s.right[o]).confidence >= doubt_below)
                ++holes[1];
        }
    }
    TrackSide out;
    const bool edges_seen = left.size() * 2 > samples.size() && right.size() * 2 > samples.size();
    if (edges_seen) {
        double l = median_of(left), r = median_of(right);
        auto fits = [](double near, double far, double a, double b) {
            return std::abs(a - near) < 0.6 && std::abs(b - far) < 0.6;
        };
        if (fits(near_edge, far_edge, l, r) || fits(near_edge, far_edge, r, l)) {
            out.decided = true;
            out.track1_left = l < r;
            out.reason = "the paper's edges (" + std::to_string(static_cast<int>(std::lround(std::min(l, r) * 2.54))) +
                         " and " + std::to_string(static_cast<int>(std::lround(std::max(l, r) * 2.54))) +
                         " mm from the feed line)";
        }
    }
    if (holes[0] != holes[1] &&
        (holes[0] == 0 || holes[1] == 0 || std::max(holes[0], holes[1]) >= 10 * std::min(holes[0], holes[1]))) {
        bool by_holes = holes[1] > holes[0];  // tracks beyond the short side's rows on the right: track 1 left
        if (out.decided && by_holes != out.track1_left) {
            out.decided = false;
            out.reason = "the paper's edges and the holes disagree on which side holds track 1";
            return out;
        }
        if (!out.decided) {
            out.decided = true;
            out.track1_left = by_holes;
            out.reason = std::to_string(std::max(holes[0], holes[1])) + " holes beyond the " +
                         std::to_string(near_rows) + " rows on the other side of the feed line";
        }
    }
    if (!out.decided && out.reason.empty())
        out.reason = holes[0] && holes[1] ? "holes beyond the third row on both sides of the feed line"
                                          : "no holes beyond the rows nearest the feed line, and no paper edges seen";
    return out;
}

}  // namespace tape::scan
