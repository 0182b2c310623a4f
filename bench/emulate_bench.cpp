// The reader emulator at 1500 frames/s into a pseudo-terminal for 10 s: achieved rate against the set
// rate, and the 99th-percentile gap between frames as the controller side sees them.
// Run: build/bin/emulate_bench   (counters: rate_fps, rate_error_pct, gap_p50_ms, gap_p99_ms, gap_max_ms)
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <optional>
#include <thread>
#include <vector>

#include "emulator_on_pty.hpp"
#include "tape/dnc.hpp"

namespace {

void BM_EmulateIntoPty(benchmark::State& state) {
    const double rate = static_cast<double>(state.range(0));
    const auto seconds = std::chrono::seconds(state.range(1));
    auto tape = long_program_tape(40000);
    for (auto _ : state) {
        std::optional<EmulatorOnPty> emulator(std::in_place, tape, rate);
        if (emulator->master < 0) {
            state.SkipWithError("openpty failed");
            return;
        }
        const int master = emulator->master;
        std::uint8_t dc1 = tape::dc1;
        if (::write(master, &dc1, 1) != 1) state.SkipWithError("write failed");
        std::vector<std::chrono::steady_clock::time_point> arrivals;
        arrivals.reserve(static_cast<std::size_t>(rate * static_cast<double>(seconds.count()) * 1.2));
        auto end = std::chrono::steady_clock::now() + seconds;
        std::uint8_t buf[256];
        while (std::chrono::steady_clock::now() < end) {
            pollfd p{master, POLLIN, 0};
            if (::poll(&p, 1, 100) <= 0) continue;
            ssize_t n = ::read(master, buf, sizeof buf);
            auto now = std::chrono::steady_clock::now();
            for (ssize_t i = 0; i < n; ++i) arrivals.push_back(now);
        }
        emulator.reset();
        if (arrivals.size() < 2) {
            state.SkipWithError("no frames");
            return;
        }
        double span = std::chrono::duration<double>(arrivals.back() - arrivals.front()).count();
        double achieved = static_cast<double>(arrivals.size() - 1) / span;
        std::vector<double> gaps;
        for (std::size_t i = 1; i < arrivals.size(); ++i)
            gaps.push_back(std::chrono::duration<double, std::milli>(arrivals[i] - arrivals[i - 1]).count());
        std::sort(gaps.begin(), gaps.end());
        state.SetIterationTime(span);
        state.counters["frames"] = static_cast<double>(arrivals.size());
        state.counters["rate_fps"] = achieved;
        state.counters["rate_error_pct"] = 100.0 * (achieved - rate) / rate;
        state.counters["gap_p50_ms"] = gaps[gaps.size() / 2];
        state.counters["gap_p99_ms"] = gaps[gaps.size() * 99 / 100];
        state.counters["gap_max_ms"] = gaps.back();
    }
}

}  // namespace

BENCHMARK(BM_EmulateIntoPty)->Args({1500, 10})->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
