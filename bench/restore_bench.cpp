// Restoration: recovery on damaged reads of generated programs and of the sample tapes, and speed.
// Run: build/bin/restore_bench (Release: bench/run.sh builds it; BUILD_DIR=... to choose the build).
//   BM_ThreeReads:   3 reads, each with 1% damaged frames (flips, drops, doubles, bursts mixed), of
//                    10 generated programs of 10^6 frames
//   BM_ThreeReadsSampleTapes: the same, 1000 times on each ISO sample tape in tapes/
//   BM_OneReadFlips: 1 read with single-hole flips in 0.5% of frames: repaired right / wrong / left flagged
//   BM_FiveReadsSpeed: 5 reads of 10^6 frames aligned and voted
// Counters: programs byte-exact (the punched part: leader and trailer length are voted like any run of
// equal frames), frames wrong in the output where the report has no doubt (tape::check_restore), frames
// wrong where it says it is in doubt, and the frames it puts in doubt.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "tape/damage.hpp"
#include "tape/encode.hpp"
#include "tape/restore.hpp"

namespace {

// Blocks as real programs have them, numbers varying with a seed.
std::vector<tape::Frame> generated_tape(std::size_t chars, std::uint64_t seed) {
    std::string t = "%\n";
    std::uint64_t x = seed * 0x9E3779B97F4A7C15ULL + 1;
    auto next = [&x](int m) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        return static_cast<int>(x % static_cast<std::uint64_t>(m));
    };
    char buf[128];
    for (long n = 1; t.size() < chars; ++n) {
        int len = std::snprintf(buf, sizeof buf, "N%ld G01 X%d.%03d Y%d.%02d F%d\n", n, next(1999) - 999, next(1000),
                                next(1999) - 999, next(100), 50 + next(900));
        t.append(buf, static_cast<std::size_t>(len));
    }
    t += "M02\n";
    return tape::encode(t, tape::EncodeOptions{});
}

// The bundled sample tapes in the ISO code (raw images: a frame a byte).
std::vector<std::vector<tape::Frame>> sample_tapes() {
    std::vector<std::vector<tape::Frame>> out;
    for (const char* name : {"16k20f3s5-turning.iso.ptp", "circle-examples.iso.ptp",
                             "gost-20999-format-example.iso.ptp", "koi7-comment.iso.ptp"}) {
        std::ifstream in(std::string(TAPE_SAMPLE_TAPES) + "/" + name, std::ios::binary);
        out.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (out.back().empty()) std::fprintf(stderr, "restore_bench: cannot read %s\n", name);
    }
    return out;
}

// A count over all iterations, shown per iteration.
benchmark::Counter per_run(std::uint64_t n) {
    return benchmark::Counter(static_cast<double>(n), benchmark::Counter::kAvgIterations);
}

struct Tally {
    std::uint64_t programs = 0, exact = 0, frames = 0, wrong = 0, flagged_wrong = 0, in_doubt = 0, blank_ends = 0;

    void add(std::span<const tape::Frame> tape, const tape::RestoreResult& r) {
        auto check = tape::check_restore(tape, r);
        ++programs;
        exact += check.exact;
        frames += tape.size();
        wrong += check.silently_wrong;
        flagged_wrong += check.flagged_wrong;
        blank_ends += check.blank_ends;
        for (const auto& q : r.problems) in_doubt += tape::in_doubt(q.status);
    }
    void report(benchmark::State& state) const {
        state.counters["programs"] = per_run(programs);
        state.counters["byte_exact"] = per_run(exact);
        state.counters["frames"] = per_run(frames);
        state.counters["silently_wrong"] = per_run(wrong);
        state.counters["wrong_flagged"] = per_run(flagged_wrong);
        state.counters["in_doubt"] = per_run(in_doubt);
        state.counters["leader_trailer_length_off"] = per_run(blank_ends);
    }
};

std::vector<std::vector<tape::Frame>> three_reads(std::span<const tape::Frame> tape, std::uint64_t seed) {
    std::vector<std::vector<tape::Frame>> reads;
    for (std::uint64_t k = 0; k < 3; ++k)
        reads.push_back(tape::damage(tape, tape::mixed_damage(0.01, seed * 3 + k + 1)));
    return reads;
}

tape::RestoreResult restore_reads(const std::vector<std::vector<tape::Frame>>& reads) {
    std::vector<std::span<const tape::Frame>> spans(reads.begin(), reads.end());
    return tape::restore(spans, tape::RestoreOptions{.code = tape::FrameCode::iso(), .dialect = tape::Dialect::gost});
}

void BM_ThreeReads(benchmark::State& state) {
    const auto programs = static_cast<std::uint64_t>(state.range(0));
    Tally t;
    for (auto _ : state) {
        for (std::uint64_t p = 0; p < programs; ++p) {
            auto tape = generated_tape(1'000'000, p + 1);
            t.add(tape, restore_reads(three_reads(tape, p)));
        }
    }
    t.report(state);
}
BENCHMARK(BM_ThreeReads)->Arg(10)->Iterations(1)->Unit(benchmark::kSecond);

// The same on the bundled sample tapes, a thousand sets of three reads of each.
void BM_ThreeReadsSampleTapes(benchmark::State& state) {
    const auto tapes = sample_tapes();
    Tally t;
    for (auto _ : state)
        for (const auto& tape : tapes)
            for (std::uint64_t seed = 0; seed < 1000; ++seed) t.add(tape, restore_reads(three_reads(tape, seed)));
    t.report(state);
}
BENCHMARK(BM_ThreeReadsSampleTapes)->Iterations(1)->Unit(benchmark::kSecond);

// One read with single-hole flips: each bad frame repaired right, repaired wrong (inferred, so listed
// in the report), or left as read (unresolved, listed).
struct Repairs {
    std::uint64_t bad = 0, right = 0, wrong_flagged = 0, left = 0, wrong_silent = 0;

    void add(std::span<const tape::Frame> tape, std::uint64_t seed) {
        const auto code = tape::FrameCode::iso();
        tape::DamageOptions o;
        o.seed = seed;
        o.flips = 0.005;
        auto read = tape::damage(tape, o);
        std::vector<std::span<const tape::Frame>> spans{read};
        auto r = tape::restore(spans, tape::RestoreOptions{.code = code, .dialect = tape::Dialect::gost});
        wrong_silent += tape::check_restore(tape, r).silently_wrong;
        for (std::size_t i = 0; i < tape.size(); ++i) {
            if (read[i] == tape[i]) continue;
            ++bad;
            if (r.frames[i] == tape[i])
                ++right;
            else if (r.frames[i] != read[i])
                ++wrong_flagged;
            else
                ++left;
        }
    }
    void report(benchmark::State& state) const {
        state.counters["bad_frames"] = per_run(bad);
        state.counters["repaired_right"] = per_run(right);
        state.counters["repaired_wrong_flagged"] = per_run(wrong_flagged);
        state.counters["left_flagged"] = per_run(left);
        state.counters["wrong_unflagged"] = per_run(wrong_silent);
    }
};

void BM_OneReadFlips(benchmark::State& state) {
    Repairs t;
    for (auto _ : state)
        for (std::uint64_t p = 0; p < 4; ++p) t.add(generated_tape(250'000, p + 100), p + 7);
    t.report(state);
}
BENCHMARK(BM_OneReadFlips)->Iterations(1)->Unit(benchmark::kSecond);

void BM_OneReadFlipsSampleTapes(benchmark::State& state) {
    const auto tapes = sample_tapes();
    Repairs t;
    for (auto _ : state)
        for (const auto& tape : tapes)
            for (std::uint64_t seed = 1; seed <= 200; ++seed) t.add(tape, seed);
    t.report(state);
}
BENCHMARK(BM_OneReadFlipsSampleTapes)->Iterations(1)->Unit(benchmark::kSecond);

void BM_FiveReadsSpeed(benchmark::State& state) {
    auto tape = generated_tape(1'000'000, 42);
    std::vector<std::vector<tape::Frame>> reads;
    for (std::uint64_t k = 0; k < 5; ++k) reads.push_back(tape::damage(tape, tape::mixed_damage(0.01, k + 50)));
    std::vector<std::span<const tape::Frame>> spans(reads.begin(), reads.end());
    for (auto _ : state) {
        auto r =
            tape::restore(spans, tape::RestoreOptions{.code = tape::FrameCode::iso(), .dialect = tape::Dialect::gost});
        benchmark::DoNotOptimize(r.frames.data());
    }
    state.counters["frames_per_read"] = static_cast<double>(tape.size());
}
BENCHMARK(BM_FiveReadsSpeed)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
