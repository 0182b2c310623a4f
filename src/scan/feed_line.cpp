// The feed line of a strip (scan_geometry.hpp): one place per frame from a chain of feed holes, the
// places of holes not seen put between their neighbours; and the line's shape (skew, bow, bend).
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>

#include "scan/scan_geometry.hpp"

namespace tape::scan {
namespace {

constexpr double degrees = 180 / std::numbers::pi;

ScanPoint point(const Blob& b) { return {b.x, b.y}; }

// The unit vector from a to b (along x for equal points).
ScanPoint unit(ScanPoint a, ScanPoint b) {
    double dx = b.x - a.x, dy = b.y - a.y, n = std::hypot(dx, dy);
    return n > 0 ? ScanPoint{dx / n, dy / n} : ScanPoint{1, 0};
}

// The direction of the line at each frame, over a window of 2w + 1 frames, as an angle in radians,
// unwrapped so that neighbouring frames differ by less than half a turn.
std::vector<double> angles(const FeedLine& line, std::size_t w) {
    const std::size_t n = line.centre.size();
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t a = i > w ? i - w : 0, b = std::min(n - 1, i + w);
        auto u = unit(line.centre[a], line.centre[b]);
        out[i] = std::atan2(u.y, u.x);
        if (i > 0) {
            while (out[i] - out[i - 1] > std::numbers::pi) out[i] -= 2 * std::numbers::pi;
            while (out[i] - out[i - 1] < -std::numbers::pi) out[i] += 2 * std::numbers::pi;
        }
    }
    return out;
}

}  // namespace

FeedLine feed_line(std::span<const Blob> blobs, const FeedChain& chain) {
    FeedLine line;
    for (std::size_t i = 0; i < chain.blobs.size(); ++i) {
        ScanPoint here = point(blobs[chain.blobs[i]]);
        if (i > 0) {
            ScanPoint before = line.centre.back();
            int missing = chain.missing_before[i];
            for (int k = 1; k <= missing; ++k) {
                double t = static_cast<double>(k) / (missing + 1);
                line.centre.push_back({before.x + (here.x - before.x) * t, before.y + (here.y - before.y) * t});
                line.seen.push_back(false);
            }
        }
        line.centre.push_back(here);
        line.seen.push_back(true);
    }
    const std::size_t n = line.centre.size();
    if (n >= 2) {
        // The image's natural order: left to right, or top to bottom for a strip nearer upright.
        double dx = line.centre.back().x - line.centre.front().x, dy = line.centre.back().y - line.centre.front().y;
        if (std::abs(dx) >= std::abs(dy) ? dx < 0 : dy < 0) {
            std::reverse(line.centre.begin(), line.centre.end());
            std::reverse(line.seen.begin(), line.seen.end());
        }
    }
    set_directions(line);
    if (n == 1) line.pitch[0] = chain.pitch;
    return line;
}

void set_directions(FeedLine& line) {
    // Over 9 frames: at a phone's 8 px a frame, a feed hole's centre off by half a pixel turns a line
    // over 5 frames enough to miss track 8; a bow bends a tape far more slowly than that.
    constexpr std::size_t w = 4;
    const std::size_t n = line.centre.size();
    line.along.clear();
    line.pitch.clear();
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t a = i > w ? i - w : 0, b = std::min(n - 1, i + w);
        line.along.push_back(unit(line.centre[a], line.centre[b]));
        double d = std::hypot(line.centre[b].x - line.centre[a].x, line.centre[b].y - line.centre[a].y);
        line.pitch.push_back(b > a ? d / static_cast<double>(b - a) : 1);
    }
}

LineShape line_shape(const FeedLine& line, int width, int height) {
    LineShape s;
    const std::size_t n = line.centre.size();
    if (n < 2) return s;
    std::vector<double> p(line.pitch);
    std::nth_element(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(n / 2), p.end());
    s.pitch = p[n / 2];
    // The straight line through the centres (principal axis), then the largest distance from it.
    double mx = 0, my = 0;
    for (auto c : line.centre) mx += c.x, my += c.y;
    mx /= static_cast<double>(n), my /= static_cast<double>(n);
    double sxx = 0, syy = 0, sxy = 0;
    for (auto c : line.centre)
        sxx += (c.x - mx) * (c.x - mx), syy += (c.y - my) * (c.y - my), sxy += (c.x - mx) * (c.y - my);
    double theta = 0.5 * std::atan2(2 * sxy, sxx - syy);
    double skew = theta * degrees;
    while (skew > 45) skew -= 90;
    while (skew < -45) skew += 90;
    s.skew_deg = skew;
    for (auto c : line.centre)
        s.bow_px = std::max(s.bow_px, std::abs(-(c.x - mx) * std::sin(theta) + (c.y - my) * std::cos(theta)));
    auto a = angles(line, 5);
    auto [lo, hi] = std::minmax_element(a.begin(), a.end());
    s.bend_deg = (*hi - *lo) * degrees;
    // A strip whose end hole is within a pitch and a half of the picture's edge runs off it there.
    auto cut = [&](ScanPoint c, ScanPoint out) {
        double m = 1.5 * s.pitch;
        ScanPoint q{c.x + out.x * m, c.y + out.y * m};
        return q.x < 0 || q.y < 0 || q.x > width - 1 || q.y > height - 1;
    };
    s.start_cut = cut(line.centre.front(), {-line.along.front().x, -line.along.front().y});
    s.end_cut = cut(line.centre.back(), line.along.back());
    return s;
}

std::pair<std::size_t, std::size_t> straight_run(const FeedLine& line, double max_bend_deg) {
    const std::size_t n = line.centre.size();
    if (n == 0) return {0, 0};
    auto a = angles(line, 5);
    const double limit = max_bend_deg / degrees;
    // The longest window whose largest and smallest angle differ by at most limit (two monotonic queues).
    std::deque<std::size_t> lo, hi;
    std::size_t best_first = 0, best_last = 0, first = 0;
    for (std::size_t i = 0; i < n; ++i) {
        while (!lo.empty() && a[lo.back()] >= a[i]) lo.pop_back();
        while (!hi.empty() && a[hi.back()] <= a[i]) hi.pop_back();
        lo.push_back(i), hi.push_back(i);
        while (a[hi.front()] - a[lo.front()] > limit) {
            ++first;
            if (lo.front() < first) lo.pop_front();
            if (hi.front() < first) hi.pop_front();
        }
        if (i + 1 - first > best_last - best_first) best_first = first, best_last = i + 1;
    }
    return {best_first, best_last};
}

FeedLine sub_line(const FeedLine& line, std::size_t first, std::size_t last) {
    FeedLine out;
    auto d = [](std::size_t i) { return static_cast<std::ptrdiff_t>(i); };
    out.centre.assign(line.centre.begin() + d(first), line.centre.begin() + d(last));
    out.seen.assign(line.seen.begin() + d(first), line.seen.begin() + d(last));
    out.along.assign(line.along.begin() + d(first), line.along.begin() + d(last));
    out.pitch.assign(line.pitch.begin() + d(first), line.pitch.begin() + d(last));
    return out;
}

}  // namespace tape::scan
