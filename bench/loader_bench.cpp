// Loader throughput: characters -> programs, blocks and words, on a 100 MB generated program.
// Run: build/bin/loader_bench (--benchmark_filter=LongNonAscii for the long-line figures alone)
#include <benchmark/benchmark.h>

#include <string>

#include "tape/program.hpp"

namespace {

// Blocks as real programs have them: numbers, G codes, signed dimensions with points, feeds, M codes,
// now and then a comment, a skipped block and a main block.
const std::string& generated_program() {
    static const std::string text = [] {
        constexpr std::size_t size = 100'000'000;
        std::string t = "%1\n";
        t.reserve(size + 200);
        char buf[160];
        for (long n = 1; t.size() < size; ++n) {
            int len;
            if (n % 50 == 0)
                len = std::snprintf(buf, sizeof buf, ":%ld G90 G17 X+%ld.25 Y-%ld.5 Z+2. S1250 T0101 M03\n", n, n % 900,
                                    n % 700);
            else if (n % 17 == 0)
                len = std::snprintf(buf, sizeof buf, "/N%ld G00 Z+50. (CHECK THE CLAMP)\n", n);
            else
                len = std::snprintf(buf, sizeof buf, "N%ld G01 X+%ld.125 Y-%ld.5 Z-5.0 F120.5 M08\n", n, n % 1000,
                                    n % 800);
            t.append(buf, static_cast<std::size_t>(len));
        }
        t += "N999999 M02\n";
        return t;
    }();
    return text;
}

// Characters -> blocks with words, streamed: what a reader or a long tape gets.
void BM_LoadEach(benchmark::State& state) {
    struct Count : tape::ProgramVisitor {
        std::size_t blocks = 0, words = 0;
        void block(const tape::Block& b) override {
            ++blocks;
            words += b.words.size();
        }
    };
    const std::string& text = generated_program();
    Count count;
    for (auto _ : state) {
        count = Count{};
        tape::load_each(text, {}, count);
        benchmark::DoNotOptimize(count.words);
    }
    state.counters["blocks"] = static_cast<double>(count.blocks);
    state.counters["words"] = static_cast<double>(count.words);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

// The same kept whole in memory (tape blocks, lint): allocation of every block and word included.
void BM_LoadWholeTape(benchmark::State& state) {
    const std::string& text = generated_program();
    std::size_t blocks = 0;
    for (auto _ : state) {
        auto loaded = tape::load(text);
        blocks = loaded.programs.at(0).blocks.size();
        benchmark::DoNotOptimize(loaded.programs.data());
    }
    state.counters["blocks"] = static_cast<double>(blocks);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

// One long line that is not ASCII (a Cyrillic comment, then words): each word's column is counted in
// characters. The loader must stay linear in the line's length (issue 24: a 160 KB line took 2.1 s when
// every word counted its column from the line's start); the complexity fit says oN.
void BM_LongNonAsciiLine(benchmark::State& state) {
    std::string text = "%\nN1 (ДЕТАЛЬ \xD0\x96)";
    while (text.size() < static_cast<std::size_t>(state.range(0))) text += " X1.5 Y-2";
    text += "\nN2 M02\n";
    struct Words : tape::ProgramVisitor {
        std::uint64_t last_column = 0;
        void block(const tape::Block& b) override {
            if (!b.words.empty()) last_column = b.words.back().where.column;
        }
    };
    Words words;
    for (auto _ : state) {
        tape::load_each(text, {}, words);
        benchmark::DoNotOptimize(words.last_column);
    }
    state.SetComplexityN(state.range(0));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

}  // namespace

BENCHMARK(BM_LongNonAsciiLine)
    ->Arg(20 << 10)
    ->Arg(40 << 10)
    ->Arg(80 << 10)
    ->Arg(160 << 10)
    ->Arg(320 << 10)
    ->Arg(640 << 10)
    ->Complexity(benchmark::oN);
BENCHMARK(BM_LoadEach)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(BM_LoadWholeTape)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_MAIN();
