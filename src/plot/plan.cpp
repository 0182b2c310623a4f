// The toolpath laid out on the page (tape/toolpath.hpp): seen from one side, fitted, and cut down to
// what shows at the page's resolution, so that a picture of a million moves stays small.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "plot/page.hpp"
#include "plot/strokes.hpp"
#include "tape/error.hpp"
#include "tape/toolpath.hpp"
#include "toolpath/arc.hpp"

namespace tape {
namespace {

constexpr std::uint32_t doubt_rgb = 0xe69a1c;          // tape render's "doubtful"
constexpr std::uint32_t not_simulated_rgb = 0xe0302a;  // and its "parity error"
constexpr std::uint32_t palette[] = {0x1f5fbf, 0x2a9d4a, 0x8e3fbf, 0x00a0a8, 0xb8327a,
                                     0x6b6b00, 0x4a4a4a, 0x0070ff, 0x7a4a1c, 0xd0308a};

// The part's bounds on the page's axes, every point of every move (an arc by its ends and the
// quarter points it passes).
struct Bounds {
    double u0 = std::numeric_limits<double>::max(), u1 = -u0, v0 = u0, v1 = -u0;
    void add(plot::Uv p) {
        u0 = std::min(u0, p.u), u1 = std::max(u1, p.u), v0 = std::min(v0, p.v), v1 = std::max(v1, p.v);
    }
};

void add_arc_bounds(Bounds& b, const plot::Page& page, const PathMove& m) {
    arcs::Sweep w = arcs::sweep_of(m.start, m.end, m.centre, m.plane, m.clockwise, m.turns);
    double quarter = std::numbers::pi / 2, lo = std::min(w.start, w.start + w.sweep),
           hi = std::max(w.start, w.start + w.sweep);
    for (double k = std::ceil(lo / quarter); k * quarter <= hi && k - std::ceil(lo / quarter) < 4; ++k) {
        double t = w.sweep == 0 ? 0 : (k * quarter - w.start) / w.sweep;
        b.add(page.view(arcs::point_at(w, m.start, m.end, m.centre, m.plane, t)));
    }
}

Bounds bounds_of(const Toolpath& path, const plot::Page& page) {
    Bounds b;
    for (const auto& m : path.moves()) {
        if (!page.shows(m)) continue;
        b.add(page.view(m.start));
        b.add(page.view(m.end));
        if (m.kind == MoveKind::arc) add_arc_bounds(b, page, m);
    }
    return b;
}

// Colours a tool by the order tools come in, so that the first tools of any program differ.
class ToolColours {
public:
    std::uint32_t of(int tool) {
        auto [it, added] = order_.emplace(tool, order_.size());
        return palette[it->second % std::size(palette)];
    }
    const std::map<int, std::size_t>& tools() const { return order_; }

private:
    std::map<int, std::size_t> order_;
};

plot::Layer layer_of(const PathMove& m) {
    if (m.doubt || m.kind == MoveKind::not_simulated) return plot::Layer::doubt;
    return m.kind == MoveKind::rapid ? plot::Layer::rapid : plot::Layer::feed;
}

PlotStyle style_of(const PathMove& m, std::uint32_t colour, double unit) {
    if (m.doubt) return {doubt_rgb, static_cast<float>(2.5 * unit), m.kind == MoveKind::rapid};
    if (m.kind == MoveKind::not_simulated) return {not_simulated_rgb, static_cast<float>(2 * unit), false};
    if (m.kind == MoveKind::rapid) return {colour, static_cast<float>(1.25 * unit), true};
    return {colour, static_cast<float>(2 * unit), false};
}

// A move seen on the page: an arc face on as an arc, any other arc as a polyline fine enough that it
// strays less than a quarter unit, a line as a line.
void lay_move(plot::Strokes& out, const plot::Page& page, const PathMove& m, std::uint16_t style, std::uint32_t i,
              double unit) {
    plot::Xy a = page.at(m.start), b = page.at(m.end);
    // A block not simulated: a ring where the tool stood.
    if (m.kind == MoveKind::not_simulated) return out.arc(style, i, a, 6 * unit, 0, 2 * std::numbers::pi);
    if (m.kind != MoveKind::arc) return out.line(style, i, a, b);
    arcs::Sweep w = arcs::sweep_of(m.start, m.end, m.centre, m.plane, m.clockwise, m.turns);
    double r = std::max(w.r0, w.r1) * page.scale();
    if (r * std::abs(w.sweep) < 1 || r < 0.5) return out.line(style, i, a, b);
    if (page.face_on(m.plane)) {
        plot::Xy c = page.at(m.centre);
        double a0 = std::atan2(a.y - c.y, a.x - c.x), sweep = page.page_sweep(w.sweep);
        if (std::abs(w.r0 - w.r1) * page.scale() < 0.25) return out.arc(style, i, c, r, a0, a0 + sweep);
    }
    double step = 2 * std::acos(std::max(0.0, 1 - 0.25 / r));
    auto n = static_cast<std::size_t>(std::clamp(std::ceil(std::abs(w.sweep) / std::max(step, 1e-3)), 2.0, 1e5));
    plot::Xy prev = a;
    for (std::size_t k = 1; k <= n; ++k) {
        plot::Xy p = k == n ? b : page.at(arcs::point_at(w, m.start, m.end, m.centre, m.plane, double(k) / n));
        out.line(style, i, prev, p);
        prev = p;
    }
}

// The scale bar: 1, 2 or 5 times a power of ten millimetres, about a fifth of the page across.
void lay_scale_bar(PlotPlan& plan, double scale, int height) {
    double want = plan.width / 5.0 / scale, unit = std::pow(10, std::floor(std::log10(want))), mm = unit;
    for (double f : {2.0, 5.0, 10.0})
        if (f * unit <= want) mm = f * unit;
    float x0 = 20, y = static_cast<float>(height - 20), x1 = x0 + static_cast<float>(mm * scale);
    plan.scale_bar = {{x0, y}, {x1, y}};
    char text[32];
    std::snprintf(text, sizeof text, mm >= 1 ? "%g mm" : "%.3g mm", mm);
    plan.texts.push_back({x1 + 6, y + 4, 12, 0x333333, text});
}

void lay_legend(PlotPlan& plan, const ToolColours& tools, bool any_doubt, bool any_not_simulated) {
    double x = plan.width - 20.0, y = plan.height - 16.0;
    auto put = [&](std::uint32_t rgb, std::string text) {
        x -= 8.0 * static_cast<double>(text.size()) + 14;
        plan.texts.push_back({x, y, 12, rgb, std::move(text)});
    };
    if (any_doubt) put(doubt_rgb, "in doubt");
    if (any_not_simulated) put(not_simulated_rgb, "o not simulated");
    put(0x666666, "rapids dashed");
    std::vector<std::pair<std::size_t, int>> order;
    for (auto [tool, k] : tools.tools()) order.emplace_back(k, tool);
    std::sort(order.rbegin(), order.rend());
    for (std::size_t n = 0; n < order.size() && n < 12; ++n)
        put(palette[order[n].first % std::size(palette)], "T" + std::to_string(order[n].second));
}

}  // namespace

PlotPlan plan_plot(const Toolpath& path, const PlotOptions& options) {
    if (options.width < 100 || options.height < 100 || options.width > 20000 || options.height > 20000)
        throw Error(Errc::usage, "the picture is 100 to 20000 units across and high");
    plot::Page page(options);
    Bounds b = bounds_of(path, page);
    if (b.u0 > b.u1)
        throw Error(Errc::bad_program, std::string("no move to draw (no rapid, feed or arc with ") +
                                           (page.axes() == (axis_x | axis_y)   ? "X and Y"
                                            : page.axes() == (axis_y | axis_z) ? "Y and Z"
                                                                               : "X and Z") +
                                           " known)");
    page.fit(b.u0, b.u1, b.v0, b.v1);
    PlotPlan plan;
    plan.width = options.width;
    plan.height = options.height;
    plan.x0 = page.origin_x();
    plan.y0 = page.origin_y();
    plan.scale = page.scale();
    double unit = std::clamp(std::min(options.width, options.height) / 900.0, 1.0, 4.0);
    ToolColours tools;
    plot::Strokes strokes(plan, path.moves(), options.per_block);
    bool any_doubt = false, any_not_simulated = false;
    for (std::uint32_t i = 0; i < path.moves().size(); ++i) {
        const PathMove& m = path.moves()[i];
        if (!page.shows(m)) {
            ++plan.unplaced;
            continue;
        }
        any_doubt |= m.doubt;
        any_not_simulated |= !m.doubt && m.kind == MoveKind::not_simulated;
        std::uint16_t style = strokes.style(layer_of(m), style_of(m, tools.of(m.tool), unit));
        lay_move(strokes, page, m, style, i, unit);
    }
    strokes.finish();
    if (!options.title.empty()) plan.texts.push_back({20, 24, 14, 0x1b1b1b, options.title});
    plan.texts.push_back({20, 42, 11, 0x555555, std::string(page.axes_text())});
    lay_scale_bar(plan, page.scale(), options.height);
    lay_legend(plan, tools, any_doubt, any_not_simulated);
    return plan;
}

std::string_view plot_format_for_path(std::string_view path) {
    auto dot = path.rfind('.');
    if (dot == std::string_view::npos) return {};
    std::string ext(path.substr(dot + 1));
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (std::string_view f : {"svg", "png", "pdf", "html"})
        if (ext == f || (f == "html" && ext == "htm")) return f;
    return {};
}

}  // namespace tape
