// Codec throughput on a 64 MiB tape, beside memcpy of the same buffer in the same run.
// Run: build/bin/codec_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <chrono>
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
    static const auto eia =
        tape::encode(program_text(), tape::EncodeOptions{.code = tape::Code::eia, .leader = 0, .trailer = 0});
    std::vector<char> out(eia.size());
    tape::FrameCode code = tape::FrameCode::eia();
    for (auto _ : state) {
        std::size_t written = 0;
        tape::decode_run(code, eia, out.data(), &written);
        benchmark::DoNotOptimize(written);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * eia.size()));
}

// The codec core as the CLI drives it, tape::Decoder and tape::Encoder on memory, beside memcpy of the
// same bytes in the same loop: the 64 MiB fed in pieces of range(0) bytes (128 KiB: the CLI's chunk,
// in the cache; 64 MiB: one piece, from and to memory), the output emptied after each piece as the
// CLI does. Counters: GB/s of each and vs_memcpy, the core's throughput over memcpy's (issue: >= 0.5).
void core_versus_memcpy(benchmark::State& state, bool decoding) {
    auto piece = static_cast<std::size_t>(state.range(0));
    const char* in = decoding ? reinterpret_cast<const char*>(program_tape().data()) : program_text().data();
    std::vector<char> copy(piece);
    tape::DecodeResult text;
    std::vector<tape::Frame> frames;
    double copy_s = 0, core_s = 0;
    for (auto _ : state) {
        auto start = std::chrono::steady_clock::now();
        for (std::size_t at = 0; at < size; at += piece) {
            std::memcpy(copy.data(), in + at, piece);
            benchmark::ClobberMemory();
        }
        auto middle = std::chrono::steady_clock::now();
        if (decoding) {
            tape::Decoder decoder(tape::DecodeOptions{});
            for (std::size_t at = 0; at < size; at += piece) {
                if (!decoder.feed(std::span(reinterpret_cast<const tape::Frame*>(in + at), piece), text))
                    state.SkipWithError("the benchmark tape does not decode");
                benchmark::ClobberMemory();
                text.text.clear();
            }
        } else {
            tape::Encoder encoder(tape::EncodeOptions{.leader = 0, .trailer = 0});
            for (std::size_t at = 0; at < size; at += piece) {
                encoder.feed(std::string_view(in + at, piece), frames);
                benchmark::ClobberMemory();
                frames.clear();
            }
        }
        auto end = std::chrono::steady_clock::now();
        copy_s += std::chrono::duration<double>(middle - start).count();
        core_s += std::chrono::duration<double>(end - middle).count();
    }
    double total = static_cast<double>(state.iterations() * size);
    state.counters["GBps"] = total / core_s / 1e9;
    state.counters["memcpy_GBps"] = total / copy_s / 1e9;
    state.counters["vs_memcpy"] = copy_s / core_s;
}

void BM_DecodeVsMemcpy(benchmark::State& state) { core_versus_memcpy(state, true); }
void BM_EncodeVsMemcpy(benchmark::State& state) { core_versus_memcpy(state, false); }

}  // namespace

BENCHMARK(BM_DecodeVsMemcpy)->Arg(128 << 10)->Arg(size)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodeVsMemcpy)->Arg(128 << 10)->Arg(size)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Memcpy)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeIsoWithParityCheck)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodeIso)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeWholeTape)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeEiaTable)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
