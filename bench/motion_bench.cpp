// The motion interpreter's speed (tape/motion.hpp), on a generated mill program of lines, arcs and a
// drilling cycle now and then:
//   Interpret1MBlocks     blocks interpreted a second, loader included (target >= 10^6 /s)
//   Stream10MBlocks       10^7 blocks streamed in 1 MiB pieces through ProgramLoader into an Interpreter:
//                         CPU seconds (target <= 10 s) and the process's peak resident set (target <= 64 MB)
// Run: build/bin/motion_bench (--benchmark_filter=Stream10M for the long one).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <string>

#include "tape/motion.hpp"

namespace {

// n blocks of a ГОСТ-style mill program with explicit points: G01 lines, G02/G03 arcs on their circles
// (no finding), rapids with coolant.
std::string make_program(std::size_t n, std::size_t first = 1) {
    std::string text;
    text.reserve(n * 32);
    char b[96];
    for (std::size_t i = first; i < first + n; ++i) {
        int len;
        switch (i % 4) {
            case 0:
                len = std::snprintf(b, sizeof b, "N%zu G01 X0 Y10. F%zu.\n", i, 100 + i % 100);
                break;
            case 1:
                len = std::snprintf(b, sizeof b, "N%zu G02 X10. Y0 I0 J-10.\n", i);
                break;
            case 2:
                len = std::snprintf(b, sizeof b, "N%zu G03 X0 Y10. I-10. J0\n", i);
                break;
            default:
                len = std::snprintf(b, sizeof b, "N%zu G00 Z5. M08\n", i);
                break;
        }
        text.append(b, static_cast<std::size_t>(len));
    }
    return text;
}

struct Count : tape::MotionVisitor {
    std::size_t moves = 0, findings = 0;
    void move(const tape::Move&) override { ++moves; }
    void finding(const tape::Finding&) override { ++findings; }
};

void BM_Interpret1MBlocks(benchmark::State& state) {
    std::string text = "%\nN0 G90 G17 G00 X0 Y10. Z5.\n" + make_program(1000000) + "M02\n";
    Count c;
    for (auto _ : state) {
        c = Count{};
        tape::interpret_each(text, {}, c, tape::motion_options(tape::Dialect::gost));
        benchmark::DoNotOptimize(c.moves);
    }
    state.counters["blocks_per_s"] = benchmark::Counter(1e6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["moves"] = static_cast<double>(c.moves);
    if (c.findings) state.SkipWithError("findings in a clean program");
}
BENCHMARK(BM_Interpret1MBlocks)->Unit(benchmark::kMillisecond)->Iterations(3);

double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

void BM_Stream10MBlocks(benchmark::State& state) {
    for (auto _ : state) {
        double cpu0 = cpu_seconds();
        Count c;
        tape::Interpreter in(c, tape::motion_options(tape::Dialect::gost));
        tape::ProgramLoader loader(in, tape::LoadOptions{tape::Dialect::gost});
        loader.feed("%\nN0 G90 G17 G00 X0 Y10. Z5.\n");
        constexpr std::size_t piece = 40000;  // about 1 MiB of text a piece
        for (std::size_t first = 1; first <= 10000000; first += piece) loader.feed(make_program(piece, first));
        loader.feed("M02\n");
        loader.finish();
        state.counters["cpu_s"] = cpu_seconds() - cpu0;
        state.counters["moves"] = static_cast<double>(c.moves);
    }
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    state.counters["peak_rss_mb"] = static_cast<double>(u.ru_maxrss) / 1024;
}
BENCHMARK(BM_Stream10MBlocks)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
