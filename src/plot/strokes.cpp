#include "plot/strokes.hpp"

#include <cmath>

namespace tape::plot {
namespace {

std::int32_t quarter(double v) { return static_cast<std::int32_t>(std::lround(v * 4)); }

// Under these a point adds nothing to the picture (units: pixels or points).
constexpr double drop_under = 0.5, off_line = 0.15, direction_after = 2;

}  // namespace

std::size_t Strokes::KeyHash::operator()(const std::array<std::int32_t, 6>& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (auto v : k) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
}

std::uint16_t Strokes::style(Layer layer, const PlotStyle& style) {
    auto key = std::make_pair(static_cast<std::uint8_t>(static_cast<int>(layer) * 2 + style.dashed), style.rgb);
    auto [it, added] = style_index_.emplace(key, static_cast<std::uint16_t>(plan_.styles.size()));
    if (added) {
        plan_.styles.push_back(style);
        layer_of_.push_back(layer);
        open_.emplace_back();
    }
    return it->second;
}

bool Strokes::seen(std::uint16_t style, Xy a, Xy b) {
    std::array<std::int32_t, 6> k{style, 0, quarter(a.x), quarter(a.y), quarter(b.x), quarter(b.y)};
    if (std::make_pair(k[4], k[5]) < std::make_pair(k[2], k[3])) std::swap(k[2], k[4]), std::swap(k[3], k[5]);
    return !drawn_.insert(k).second;
}

void Strokes::count(std::uint32_t move) {
    if (move == last_counted_) return;
    last_counted_ = move;
    ++plan_.moves_drawn;
}

void Strokes::close(Open& o, Built& into) {
    if (!o.open) return;
    o.open = false;
    if (o.points.size() < 4) return o.points.clear();  // a single point: nothing was drawn
    o.stroke.first = static_cast<std::uint32_t>(into.points.size() / 2);
    o.stroke.count = static_cast<std::uint32_t>(o.points.size() / 2);
    into.points.insert(into.points.end(), o.points.begin(), o.points.end());
    into.strokes.push_back(o.stroke);
    o.points.clear();
}

void Strokes::start(Open& o, std::uint16_t style, std::uint32_t move, Xy a) {
    o.open = true;
    o.stroke = PlotStroke{.style = style, .move = move, .last_move = move};
    o.points = {static_cast<float>(a.x), static_cast<float>(a.y)};
    o.end = a;
    o.pending = o.has_dir = false;
}

// b after the polyline's last point: in line with the last segment it moves that segment's end.
void Strokes::add_point(Open& o, Xy b) {
    std::size_t n = o.points.size();
    double x1 = o.points[n - 2], y1 = o.points[n - 1];
    if (n >= 4) {
        double x0 = o.points[n - 4], y0 = o.points[n - 3];
        double dx = o.has_dir ? o.dir_x : x1 - x0, dy = o.has_dir ? o.dir_y : y1 - y0, len = std::hypot(dx, dy);
        double off = len > 0 ? std::abs((b.x - x0) * dy - (b.y - y0) * dx) / len : 0;
        bool ahead = (b.x - x1) * dx + (b.y - y1) * dy > 0;
        if (ahead && off < off_line) {
            o.points[n - 2] = static_cast<float>(b.x), o.points[n - 1] = static_cast<float>(b.y);
            double seg = std::hypot(b.x - x0, b.y - y0);
            if (!o.has_dir && seg >= direction_after)
                o.dir_x = (b.x - x0) / seg, o.dir_y = (b.y - y0) / seg, o.has_dir = true;
            return;
        }
    }
    o.points.push_back(static_cast<float>(b.x));
    o.points.push_back(static_cast<float>(b.y));
    o.has_dir = false;
}

void Strokes::line(std::uint16_t style, std::uint32_t move, Xy a, Xy b) {
    Open& o = open_[style];
    Built& into = built_[static_cast<int>(layer_of_[style])];
    bool other_block = split_ && o.open && moves_[move].block != moves_[o.stroke.move].block;
    if (!o.open || other_block || std::abs(o.end.x - a.x) > 1e-6 || std::abs(o.end.y - a.y) > 1e-6) {
        close(o, into);
        start(o, style, move, a);
    }
    o.end = b;
    std::size_t n = o.points.size();
    Xy last{o.points[n - 2], o.points[n - 1]};
    if (std::hypot(b.x - last.x, b.y - last.y) < drop_under) {
        o.pending = true;
        return;
    }
    o.pending = false;
    if (seen(style, last, b)) {  // drawn already: the polyline goes on from b
        close(o, into);
        start(o, style, move, b);
        return;
    }
    o.stroke.last_move = move;
    count(move);
    add_point(o, b);
}

void Strokes::arc(std::uint16_t style, std::uint32_t move, Xy c, double r, double a0, double a1) {
    constexpr double two_pi = 2 * 3.14159265358979323846;
    if (std::abs(a1 - a0) > two_pi) a1 = a0 + (a1 > a0 ? two_pi : -two_pi);  // whole turns over each other
    std::array<std::int32_t, 6> k{style | 0x10000,
                                  quarter(c.x),
                                  quarter(c.y),
                                  quarter(r),
                                  static_cast<std::int32_t>(std::lround(std::min(a0, a1) * 1000)),
                                  static_cast<std::int32_t>(std::lround(std::max(a0, a1) * 1000))};
    if (!drawn_.insert(k).second) return;
    count(move);
    built_[static_cast<int>(layer_of_[style])].strokes.push_back(PlotStroke{.style = style,
                                                                            .arc = true,
                                                                            .cx = c.x,
                                                                            .cy = c.y,
                                                                            .r = r,
                                                                            .a0 = a0,
                                                                            .a1 = a1,
                                                                            .move = move,
                                                                            .last_move = move});
}

void Strokes::finish() {
    for (std::size_t s = 0; s < open_.size(); ++s) {
        Open& o = open_[s];
        Built& into = built_[static_cast<int>(layer_of_[s])];
        if (o.open && o.pending) {
            std::size_t n = o.points.size();
            if (std::hypot(o.end.x - o.points[n - 2], o.end.y - o.points[n - 1]) > 0.01) add_point(o, o.end);
        }
        close(o, into);
    }
    for (auto& layer : built_) {
        auto offset = static_cast<std::uint32_t>(plan_.points.size() / 2);
        for (auto& s : layer.strokes) {
            if (!s.arc) s.first += offset;
            plan_.strokes.push_back(s);
        }
        plan_.points.insert(plan_.points.end(), layer.points.begin(), layer.points.end());
    }
}

}  // namespace tape::plot
