// Restoration: recovery on damaged reads of generated programs and of the sample tapes, and speed.
// Run: build/bin/restore_bench (Release: bench/run.sh builds it; BUILD_DIR=... to choose the build).
//   BM_ThreeReads:   3 reads, each with 1% damaged frames (flips, drops, doubles, bursts mixed)
//   BM_OneReadFlips: 1 read with single-hole flips in 0.5% of frames: repaired right / wrong / left flagged
//   BM_FiveReadsSpeed: 5 reads of 10^6 frames aligned and voted
// Counters: programs byte-exact (the punched part: leader and trailer length are voted like any run of
// equal frames), frames wrong in the output without a flag (clean or voted there), and the statuses.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "tape/align.hpp"
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

std::span<const tape::Frame> punched(std::span<const tape::Frame> f) {
    std::size_t a = 0, b = f.size();
    while (a < b && f[a] == tape::blank_frame) ++a;
    while (b > a && f[b - 1] == tape::blank_frame) --b;
    return f.subspan(a, b - a);
}

bool flagged(tape::FrameStatus s) {
    using S = tape::FrameStatus;
    return s == S::inferred || s == S::contested || s == S::unstable || s == S::unresolved || s == S::missing;
}

// Output frames that differ from the tape where the report says clean or voted (or nothing), and frames
// of the tape dropped as extra: wrong without a flag. Found by aligning the output with the tape.
std::uint64_t silently_wrong(std::span<const tape::Frame> truth, const tape::RestoreResult& r) {
    std::vector<std::span<const tape::Frame>> pair{truth, r.frames};
    tape::ReadAlignment a = tape::align_reads(pair);
    std::vector<tape::FrameStatus> status(r.frames.size(), tape::FrameStatus::clean);
    for (const auto& p : r.problems)
        if (p.frame && *p.frame <= status.size()) status[*p.frame - 1] = p.status;
    // Frames not written but said to be in doubt: contested ones, by the restored frame they follow.
    std::vector<std::uint64_t> doubted;
    for (const auto& p : r.problems)
        if (!p.frame && p.status == tape::FrameStatus::contested) doubted.push_back(p.after);
    std::uint64_t wrong = 0, written_before = 0;
    for (std::size_t c = 0; c < a.columns(); ++c) {
        std::int32_t t = a.frame(c, 0), o = a.frame(c, 1);
        if (o != tape::ReadAlignment::none) ++written_before;
        if (t != tape::ReadAlignment::none && o != tape::ReadAlignment::none &&
            truth[static_cast<std::size_t>(t)] == r.frames[static_cast<std::size_t>(o)])
            continue;
        if (o != tape::ReadAlignment::none && flagged(status[static_cast<std::size_t>(o)])) continue;
        if (o == tape::ReadAlignment::none && !a.covers(1, c)) continue;  // the ends: counted as missing
        if (o == tape::ReadAlignment::none &&
            std::find(doubted.begin(), doubted.end(), written_before) != doubted.end())
            continue;
        ++wrong;
    }
    return wrong;
}

void BM_ThreeReads(benchmark::State& state) {
    const auto programs = static_cast<std::uint64_t>(state.range(0));
    std::uint64_t exact = 0, frames = 0, wrong = 0, flagged_frames = 0;
    for (auto _ : state) {
        for (std::uint64_t p = 0; p < programs; ++p) {
            auto tape = generated_tape(1'000'000, p + 1);
            std::vector<std::vector<tape::Frame>> reads;
            for (std::uint64_t k = 0; k < 3; ++k)
                reads.push_back(tape::damage(tape, tape::mixed_damage(0.01, p * 3 + k + 1)));
            std::vector<std::span<const tape::Frame>> spans(reads.begin(), reads.end());
            auto r = tape::restore(
                spans, tape::RestoreOptions{.code = tape::FrameCode::iso(), .dialect = tape::Dialect::gost});
            auto a = punched(tape), b = punched(r.frames);
            exact += a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
            frames += tape.size();
            wrong += silently_wrong(tape, r);
            for (const auto& q : r.problems) flagged_frames += flagged(q.status);
        }
    }
    state.counters["programs"] = static_cast<double>(programs);
    state.counters["byte_exact"] = static_cast<double>(exact) / static_cast<double>(state.iterations());
    state.counters["frames"] = static_cast<double>(frames) / static_cast<double>(state.iterations());
    state.counters["silently_wrong"] = static_cast<double>(wrong) / static_cast<double>(state.iterations());
    state.counters["flagged"] = static_cast<double>(flagged_frames) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ThreeReads)->Arg(10)->Iterations(1)->Unit(benchmark::kSecond);

void BM_OneReadFlips(benchmark::State& state) {
    std::uint64_t bad = 0, right = 0, wrong_flagged = 0, left = 0, wrong_silent = 0;
    const auto code = tape::FrameCode::iso();
    for (auto _ : state) {
        for (std::uint64_t p = 0; p < 4; ++p) {
            auto tape = generated_tape(250'000, p + 100);
            tape::DamageOptions o;
            o.seed = p + 7;
            o.flips = 0.005;
            auto read = tape::damage(tape, o);
            std::vector<std::span<const tape::Frame>> spans{read};
            auto r = tape::restore(spans, tape::RestoreOptions{.code = code, .dialect = tape::Dialect::gost});
            for (std::size_t i = 0; i < tape.size(); ++i) {
                if (read[i] == tape[i]) continue;
                if (code.kind(read[i]) != tape::FrameKind::parity_error) {  // a flip can give good parity only in
                    wrong_silent += r.frames[i] != tape[i];                 // codes without it; not in ISO
                    continue;
                }
                ++bad;
                if (r.frames[i] == tape[i])
                    ++right;
                else if (r.frames[i] != read[i])
                    ++wrong_flagged;  // inferred, listed in the report
                else
                    ++left;
            }
        }
    }
    auto per = [&](std::uint64_t n) { return static_cast<double>(n) / static_cast<double>(state.iterations()); };
    state.counters["bad_frames"] = per(bad);
    state.counters["repaired_right"] = per(right);
    state.counters["repaired_wrong_flagged"] = per(wrong_flagged);
    state.counters["left_flagged"] = per(left);
    state.counters["wrong_unflagged"] = per(wrong_silent);
}
BENCHMARK(BM_OneReadFlips)->Iterations(1)->Unit(benchmark::kSecond);

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
