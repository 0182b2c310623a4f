// The feed line followed on past the ends of its chain through the picture itself (scan_geometry.hpp).
// Where the feed holes are only a few pixels across (a photo of a whole tape), blur and JPEG leave some
// too faint to be blobs at one threshold; each is still darker (or lighter) than the paper round it. So
// the line goes on a frame at a time: the next hole looked for where the last steps point, taken where
// it is a hole with paper round it, and a place with none placed and counted; three in a row end it.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "scan/scan_geometry.hpp"

namespace tape::scan {
namespace {

constexpr int max_misses = 3;

// Levels of a round place: its centre, and a ring round it where paper should be.
float centre_at(const GreyView& g, ScanPoint c, double p) {
    float sum = g.at(c.x, c.y);
    for (int k = 0; k < 4; ++k) {
        double a = std::numbers::pi / 2 * k;
        sum += g.at(c.x + 0.08 * p * std::cos(a), c.y + 0.08 * p * std::sin(a));
    }
    return sum / 5;
}

float round_at(const GreyView& g, ScanPoint c, double r) {
    std::array<float, 8> v{};
    for (int k = 0; k < 8; ++k) {
        double a = std::numbers::pi / 4 * (k + 0.5);
        v[static_cast<std::size_t>(k)] = g.at(c.x + r * std::cos(a), c.y + r * std::sin(a));
    }
    std::sort(v.begin(), v.end());
    return (v[3] + v[4]) / 2;
}

struct Levels {
    float paper, hole;  // grey levels round the feed holes and at their centres
};

float median(std::vector<float> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// The levels of the last (up to) 8 feed holes seen at the line's end: light that falls unevenly changes
// both along the tape.
std::optional<Levels> levels_at_end(const GreyView& g, const FeedLine& line) {
    std::vector<float> paper, hole;
    for (std::size_t i = line.centre.size(); i-- > 0 && hole.size() < 8;) {
        if (!line.seen[i]) continue;
        double p = i > 0 ? std::hypot(line.centre[i].x - line.centre[i - 1].x, line.centre[i].y - line.centre[i - 1].y)
                         : std::hypot(line.centre[1].x - line.centre[0].x, line.centre[1].y - line.centre[0].y);
        hole.push_back(centre_at(g, line.centre[i], p));
        paper.push_back(round_at(g, line.centre[i], 0.45 * p));
    }
    if (hole.size() < 3) return std::nullopt;
    Levels l{median(paper), median(hole)};
    if (std::abs(l.paper - l.hole) < 12) return std::nullopt;
    return l;
}

// Where near q (within a fifth of a pitch) a feed hole is, if one is: the most hole-like place with paper round it.
std::optional<ScanPoint> hole_near(const GreyView& g, ScanPoint q, double p, const Levels& l) {
    const float contrast = l.paper - l.hole;
    double best = 0.6;
    std::optional<ScanPoint> found;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            ScanPoint c{q.x + dx * 0.1 * p, q.y + dy * 0.1 * p};
            double h = (l.paper - centre_at(g, c, p)) / contrast;
            if (h <= best) continue;
            double around = (l.paper - round_at(g, c, 0.45 * p)) / contrast;
            if (around < 0.3) best = h, found = c;
        }
    return found;
}

bool inside(const GreyView& g, ScanPoint c, double margin) {
    return c.x >= margin && c.y >= margin && c.x <= g.width - 1 - margin && c.y <= g.height - 1 - margin;
}

// Follows the line on past its last frame (its first when at_start), appending what it finds.
void follow(const GreyView& g, FeedLine& line, bool at_start) {
    if (at_start) {
        std::reverse(line.centre.begin(), line.centre.end());
        std::reverse(line.seen.begin(), line.seen.end());
    }
    int misses = 0;
    while (line.centre.size() >= 4 && misses < max_misses) {
        // The step over the last 8 frames (3 at least): one hole misplaced does not turn the line.
        const std::size_t n = line.centre.size(), k = std::min<std::size_t>(8, n - 1);
        ScanPoint last = line.centre[n - 1], back = line.centre[n - 1 - k];
        ScanPoint step{(last.x - back.x) / static_cast<double>(k), (last.y - back.y) / static_cast<double>(k)};
        double p = std::hypot(step.x, step.y);
        ScanPoint q{last.x + step.x, last.y + step.y};
        auto l = levels_at_end(g, line);
        if (!l || !(p > 0) || !inside(g, q, 0.5 * p)) break;
        auto hole = hole_near(g, q, p, *l);
        line.centre.push_back(hole ? *hole : q);
        line.seen.push_back(hole.has_value());
        misses = hole ? 0 : misses + 1;
    }
    while (!line.seen.empty() && !line.seen.back()) line.centre.pop_back(), line.seen.pop_back();
    if (at_start) {
        std::reverse(line.centre.begin(), line.centre.end());
        std::reverse(line.seen.begin(), line.seen.end());
    }
}

}  // namespace

void extend_line(const GreyView& picture, FeedLine& line) {
    if (std::count(line.seen.begin(), line.seen.end(), true) < 4 || picture.width <= 0 || picture.height <= 0) return;
    follow(picture, line, false);
    follow(picture, line, true);
    set_directions(line);
}

}  // namespace tape::scan

namespace tape::scan {

bool strip_goes_on(const GreyView& picture, const FeedLine& line, bool at_start) {
    FeedLine l = line;
    if (at_start) {
        std::reverse(l.centre.begin(), l.centre.end());
        std::reverse(l.seen.begin(), l.seen.end());
    }
    auto levels = levels_at_end(picture, l);
    const std::size_t n = l.centre.size();
    if (!levels || n < 4) return false;
    ScanPoint last = l.centre[n - 1], back = l.centre[n - 4];
    ScanPoint t{(last.x - back.x) / 3, (last.y - back.y) / 3}, across{t.y, -t.x};
    // Between the rows, a frame on: paper there is another frame, the strip going on where its holes were
    // lost (a tape ends half a frame past its last feed hole).
    int paper = 0, looked = 0;
    for (double v : {-2.5, -1.5, 1.5, 2.5}) {
        ScanPoint q{last.x + t.x + across.x * v, last.y + t.y + across.y * v};
        if (!inside(picture, q, 1)) return false;  // the picture ends first: said as cut there
        ++looked;
        paper += (levels->paper - picture.at(q.x, q.y)) / (levels->paper - levels->hole) < 0.5F;
    }
    return paper * 4 >= looked * 3;  // holes nearby may blur into one
}

}  // namespace tape::scan
