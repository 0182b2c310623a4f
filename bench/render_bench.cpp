// The SVG drawing of a long tape: 10^5 frames of a real program (with a few parity errors to shade) must
// take at most 1 s. Run: build/bin/render_bench
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "tape/encode.hpp"
#include "tape/render.hpp"

namespace {

constexpr std::size_t frames_drawn = 100000;

const std::vector<tape::Frame>& long_tape() {
    static const std::vector<tape::Frame> frames = [] {
        std::string block = "N0001 G01 X+00012500 Y-00003000 Z+00000250 F1200 S1250 T0101 M03\n", text;
        while (text.size() < frames_drawn) text += block;
        auto f = tape::encode(text, tape::EncodeOptions{.leader = 0, .trailer = 0});
        f.resize(frames_drawn);
        for (std::size_t i = 500; i < f.size(); i += 1000) f[i] ^= 0x04;  // parity errors, shaded
        return f;
    }();
    return frames;
}

void BM_RenderSvg(benchmark::State& state) {
    const auto& frames = long_tape();
    auto code = tape::FrameCode::iso();
    tape::RenderOptions o{.code = &code, .strip_mm = 500, .marks = {}};
    std::size_t bytes = 0;
    for (auto _ : state) {
        std::string svg = tape::render_svg(frames, o);
        bytes = svg.size();
        benchmark::DoNotOptimize(svg.data());
    }
    state.counters["frames"] = static_cast<double>(frames.size());
    state.counters["svg_MB"] = static_cast<double>(bytes) / 1e6;
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * frames.size()));
}
BENCHMARK(BM_RenderSvg)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
