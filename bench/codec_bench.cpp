// Codec throughput on a 64 MiB tape, beside memcpy of the same buffer in the same run.
// Run: build/bin/codec_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <cstring>
#include <string>
#include <vector>

#include "tape/decode.hpp"
#include "tape/encode.hpp"

namespace {

constexpr std::size_t size = 64u << 20;

// A realistic program text repeated to 64 MiB: blocks of words, LF, no leader inside.
const std::string& program_text() {
    static const std::string text = [] {
        std::string block = "N0001 G01 X+00012500 Y-00003000 Z+00000250 F1200 S1250 T0101 M03\n";
        std::string t;
        t.reserve(size);
        while (t.size() + block.size() <= size) t += block;
        t.append(size - t.size(), 'X');
        return t;
    }();
    return text;
}

const std::vector<tape::Frame>& program_tape() {
    static const std::vector<tape::Frame> frames =
        tape::encode(program_text(), tape::EncodeOptions{.leader = 0, .trailer = 0});
    return frames;
}

void BM_Memcpy(benchmark::State& state) {
    const auto& in = program_tape();
    std::vector<char> out(in.size());
    for (auto _ : state) {
        std::memcpy(out.data(), in.data(), in.size());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * in.size()));
}

void BM_DecodeIsoWithParityCheck(benchmark::State& state) {
    const auto& in = program_tape();
    std::vector<char> out(in.size());
    tape::FrameCode iso = tape::FrameCode::iso();
    for (auto _ : state) {
        std::size_t written = 0;
        std::size_t stop = tape::decode_run(iso, in, out.data(), &written);
        if (stop != in.size()) state.SkipWithError("parity error in the benchmark tape");
        benchmark::DoNotOptimize(written);
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * in.size()));
}

void BM_EncodeIso(benchmark::State& state) {
    const auto& text = program_text();
    std::vector<tape::Frame> out(text.size());
    tape::FrameCode iso = tape::FrameCode::iso();
    for (auto _ : state) {
        std::size_t stop = tape::encode_run(iso, text, out.data());
        if (stop != text.size()) state.SkipWithError("unencodable text in the benchmark");
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

// The whole library call, allocation of the result included (what `tape decode` does).
void BM_DecodeWholeTape(benchmark::State& state) {
    const auto& in = program_tape();
    for (auto _ : state) {
        auto r = tape::decode(in, {});
        benchmark::DoNotOptimize(r.text.data());
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * in.size()));
}

void BM_DecodeEiaTable(benchmark::State& state) {
    static const auto eia = tape::encode(program_text(), tape::EncodeOptions{.code = tape::Code::eia, .leader = 0, .trailer = 0});
    std::vector<char> out(eia.size());
    tape::FrameCode code = tape::FrameCode::eia();
    for (auto _ : state) {
        std::size_t written = 0;
        tape::decode_run(code, eia, out.data(), &written);
        benchmark::DoNotOptimize(written);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * eia.size()));
}

}  // namespace

BENCHMARK(BM_Memcpy)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeIsoWithParityCheck)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodeIso)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeWholeTape)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeEiaTable)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
