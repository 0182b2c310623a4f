// The tape drawn as pixels at its true size (tape/render.hpp): paper, code holes 1.83 mm and feed holes
// 1.17 mm across, 2.54 mm apart, the backing showing through the holes and around the strips. Every
// pixel is traced back to the flat strip (turned by the skew, bent by the bow), so the picture has the
// geometry a scanner would see, edges smoothed over a pixel.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "tape/error.hpp"
#include "tape/render.hpp"

namespace tape {
namespace {

constexpr double pitch = 2.54, code_radius = 0.915, feed_radius = 0.585, strip_gap = 5;

// Where the rows lie across a strip seen from its front (track 8 or 5 on top), in millimetres.
struct Rows {
    double width, top;  // tape width; first row's distance from the top edge
    int count, feed;    // rows, and the feed row's index
    int track(int row) const {
        return count == 9 ? (row < feed ? 8 - row : 9 - row) : (row < feed ? 5 - row : 6 - row);
    }
};
Rows rows_for(int tracks) { return tracks == 8 ? Rows{25.4, pitch, 9, 5} : Rows{17.46, 0.94 * pitch, 6, 3}; }

struct Stain {
    double x, y, rx, ry, strength;
};

struct Layout {
    Rows rows;
    std::span<const Frame> frames;
    std::size_t per_strip;
    double margin, width, height;  // of the flat layout, mm
    bool mirror;
    std::vector<Stain> stains;

    std::size_t strips() const { return frames.empty() ? 1 : (frames.size() + per_strip - 1) / per_strip; }
    double strip_length(std::size_t s) const {
        return static_cast<double>(std::min(per_strip, frames.size() - std::min(frames.size(), s * per_strip))) * pitch;
    }
};

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

// How much of the pixel at layout point (x, y) is paper (0..1): inside a strip and outside its holes.
double paper_at(const Layout& l, double x, double y, double px_mm) {
    double yy = y - l.margin;
    if (yy < -1) return 0;
    auto s = static_cast<std::size_t>(std::max(0.0, std::floor(yy / (l.rows.width + strip_gap))));
    if (s >= l.strips()) return 0;
    double v = yy - static_cast<double>(s) * (l.rows.width + strip_gap), u = x - l.margin, len = l.strip_length(s);
    double inside = clamp01(std::min(v, l.rows.width - v) / px_mm + 0.5) * clamp01(std::min(u, len - u) / px_mm + 0.5);
    if (inside <= 0) return 0;
    if (l.mirror) v = l.rows.width - v;
    auto k = static_cast<std::size_t>(std::clamp(std::floor(u / pitch), 0.0, len / pitch - 1));
    int row = static_cast<int>(std::lround((v - l.rows.top) / pitch));
    if (row < 0 || row >= l.rows.count) return inside;
    double du = u - (static_cast<double>(k) + 0.5) * pitch, dv = v - (l.rows.top + row * pitch);
    double radius = 0;
    if (row == l.rows.feed)
        radius = feed_radius;
    else if (has_track(l.frames[s * l.per_strip + k], l.rows.track(row)))
        radius = code_radius;
    if (radius == 0) return inside;
    return inside * (1 - clamp01((radius - std::hypot(du, dv)) / px_mm + 0.5));
}

double stain_at(const Layout& l, double x, double y) {
    double keep = 1;
    for (const auto& s : l.stains) {
        double d = std::hypot((x - s.x) / s.rx, (y - s.y) / s.ry);
        if (d < 1) keep *= 1 - s.strength * (1 - d * d);
    }
    return keep;
}

std::vector<Stain> make_stains(const RasterOptions& o, double width, double height) {
    std::mt19937_64 rng(o.seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Stain> out;
    for (int i = 0; i < o.stains; ++i)
        out.push_back({o.margin_mm + u(rng) * (width - 2 * o.margin_mm),
                       o.margin_mm + u(rng) * (height - 2 * o.margin_mm), 2 + 8 * u(rng), 2 + 6 * u(rng),
                       0.08 + 0.22 * u(rng)});
    return out;
}

void check(const RasterOptions& o) {
    if (!(o.dpi >= 10 && o.dpi <= 4800)) throw Error(Errc::usage, "a resolution of 10 to 4800 dpi");
    if (o.tracks != 5 && o.tracks != 8) throw Error(Errc::usage, "tape has 5 or 8 tracks");
    if (!(std::abs(o.skew_deg) <= 45) || !(std::abs(o.bow_mm) <= 100) || !(o.margin_mm >= 0 && o.margin_mm <= 500) ||
        !(o.strip_mm == 0 || (o.strip_mm >= pitch && o.strip_mm <= 100000)) || o.stains < 0 || o.stains > 1000)
        throw Error(Errc::usage, "skew, bow, margin, strip length or stains out of range");
}

std::uint8_t channel(std::uint32_t rgb, int c) { return static_cast<std::uint8_t>(rgb >> (16 - 8 * c) & 0xFF); }

}  // namespace

Picture render_picture(std::span<const Frame> frames, const RasterOptions& o) {
    check(o);
    Layout l{rows_for(o.tracks), frames, 0, o.margin_mm, 0, 0, o.mirror, {}};
    l.per_strip = o.strip_mm > 0 ? std::max<std::size_t>(1, static_cast<std::size_t>(o.strip_mm / pitch))
                                 : std::max<std::size_t>(1, frames.size());
    double longest = static_cast<double>(std::min(l.per_strip, std::max<std::size_t>(frames.size(), 1))) * pitch;
    l.width = longest + 2 * o.margin_mm;
    l.height = static_cast<double>(l.strips()) * (l.rows.width + strip_gap) - strip_gap + 2 * o.margin_mm;
    l.stains = make_stains(o, l.width, l.height);
    const double th = o.skew_deg * std::numbers::pi / 180, c = std::cos(th), s = std::sin(th);
    const double px_mm = 25.4 / o.dpi;
    double pw = l.width * std::abs(c) + l.height * std::abs(s) + 2 * std::abs(o.bow_mm);
    double ph = l.width * std::abs(s) + l.height * std::abs(c) + 2 * std::abs(o.bow_mm);
    double wpx = std::ceil(pw / px_mm), hpx = std::ceil(ph / px_mm);
    if (wpx * hpx > static_cast<double>(max_picture_pixels))
        throw Error(Errc::usage,
                    "the picture would have " + std::to_string(static_cast<std::uint64_t>(wpx * hpx)) +
                        " pixels, more than 2^30: draw fewer frames, shorter strips or a lower resolution");
    Picture p{static_cast<int>(wpx), static_cast<int>(hpx), 3, {}};
    p.pixels.resize(static_cast<std::size_t>(p.width) * p.height * 3);
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            // Back from the picture to the flat layout: unturn, then unbend.
            double X = (x + 0.5) * px_mm - pw / 2, Y = (y + 0.5) * px_mm - ph / 2;
            double lx = X * c + Y * s + l.width / 2, ly = -X * s + Y * c + l.height / 2;
            double t = (lx - o.margin_mm) / longest * 2 - 1;
            ly -= o.bow_mm * (1 - t * t);
            double paper = paper_at(l, lx, ly, px_mm), keep = paper > 0 ? stain_at(l, lx, ly) : 1;
            std::uint8_t* px = p.at(x, y);
            for (int k = 0; k < 3; ++k) {
                double back = channel(o.backing, 2 - k),
                       front = channel(o.paper, 2 - k) * (k == 0 ? keep * keep : keep);
                px[k] = static_cast<std::uint8_t>(std::lround(back + (front - back) * paper));
            }
        }
    return p;
}

}  // namespace tape
