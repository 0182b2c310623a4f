// A toolpath of 10^6 moves drawn: to PNG in at most 5 s, and to SVG of a bounded size (moves under a
// pixel dropped, collinear segments merged, passes over the same place drawn once). The moves are a
// pocket's: a spiral of arcs and short feeds at 20 depths, with rapids between, as CAM posts them.
// Run: build/bin/plot_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "tape/toolpath.hpp"

namespace {

constexpr std::size_t moves_made = 1'000'000;

const tape::Toolpath& pocket() {
    static const tape::Toolpath path = [] {
        tape::Toolpath p;
        tape::Move m;
        std::size_t per_level = moves_made / 20;
        for (int level = 0; level < 20 && m.block < moves_made; ++level) {
            double z = -0.5 * (level + 1);
            m.state.tool = level < 10 ? 1 : 2;
            tape::Point at{0, 0, z};
            for (std::size_t i = 0; i < per_level; ++i, ++m.block) {
                // A spiral out of short feeds (0.02 mm to 0.3 mm), every 50th move an arc about the middle.
                double a = static_cast<double>(i) * 0.013, r = 1 + 80.0 * static_cast<double>(i) / per_level;
                tape::Point next{r * std::cos(a), r * std::sin(a), z};
                m.start = at;
                m.end = next;
                m.kind = i % 50 == 0 ? tape::MoveKind::arc : tape::MoveKind::linear;
                m.centre = {0, 0, z};
                m.radius = std::hypot(at.x, at.y);
                m.clockwise = false;
                if (i % 1000 == 999) m.kind = tape::MoveKind::rapid;
                p.move(m);
                at = next;
            }
        }
        return p;
    }();
    return path;
}

void BM_PlotPng(benchmark::State& state) {
    if (!tape::plot_available()) return state.SkipWithError(std::string(tape::plot_unavailable_message()).c_str());
    const auto& path = pocket();
    tape::PlotOptions o{.width = 2000, .height = 1500};
    std::size_t bytes = 0;
    for (auto _ : state) {
        tape::PlotPlan plan = tape::plan_plot(path, o);
        auto png = tape::draw_plot(plan, "png");
        bytes = png.size();
        benchmark::DoNotOptimize(png.data());
    }
    state.counters["moves"] = static_cast<double>(path.moves().size());
    state.counters["png_MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_PlotPng)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_PlotSvg(benchmark::State& state) {
    if (!tape::plot_available()) return state.SkipWithError(std::string(tape::plot_unavailable_message()).c_str());
    const auto& path = pocket();
    tape::PlotOptions o{.width = 1200, .height = 900};
    std::size_t bytes = 0, points = 0;
    for (auto _ : state) {
        tape::PlotPlan plan = tape::plan_plot(path, o);
        points = plan.points.size() / 2;
        auto svg = tape::draw_plot(plan, "svg");
        bytes = svg.size();
        benchmark::DoNotOptimize(svg.data());
    }
    state.counters["moves"] = static_cast<double>(path.moves().size());
    state.counters["points"] = static_cast<double>(points);
    state.counters["svg_MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_PlotSvg)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
