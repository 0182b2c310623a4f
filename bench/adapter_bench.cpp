// Reading through the adapter: backend against tape-adapter-sim (the firmware core with a simulated
// ФС-1501 at 1500 frames/s) on a pseudo-terminal, faster than real time by the second argument.
// Counters: sim_fps (simulated frames a simulated second, 1500 when nothing was lost to waiting),
// lost and doubled (proven by the frame counter: both must be 0), speedup_used. A second benchmark
// drops one ROWS packet for good and times how long the host takes to report its frame range.
// Run: build/bin/adapter_bench
#include <benchmark/benchmark.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "spawn_util.hpp"
#include "tape/device.hpp"
#include "tape/error.hpp"

namespace {

using namespace std::chrono_literals;

struct Sim {
    pid_t pid = -1;
    std::string device;
    Sim(const std::vector<std::string>& args, const std::string& out) {
        pid = spawn_to_files(TAPE_ADAPTER_SIM, args, out, "");
        for (auto end = std::chrono::steady_clock::now() + 10s; pid > 0 && std::chrono::steady_clock::now() < end;) {
            std::ifstream in(out);
            std::getline(in, device);
            if (!device.empty()) break;
            std::this_thread::sleep_for(5ms);
        }
    }
    ~Sim() {
        if (pid > 0) {
            ::kill(pid, SIGTERM);
            ::waitpid(pid, nullptr, 0);
        }
    }
};

std::string make_tape(std::size_t n, std::vector<std::uint8_t>& frames) {
    frames.resize(n);
    for (std::size_t i = 0; i < n; ++i) frames[i] = static_cast<std::uint8_t>((i * 131 + i / 977) & 0xFF);
    std::string path = "/tmp/adapter_bench_tape.ptp";
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(frames.data()), static_cast<std::streamsize>(n));
    return path;
}

void BM_AdapterCdcRead(benchmark::State& state) {
    const std::size_t n = static_cast<std::size_t>(state.range(0));
    const double speed = static_cast<double>(state.range(1));
    std::vector<std::uint8_t> frames;
    std::string tape = make_tape(n, frames);
    for (auto _ : state) {
        Sim sim({"--reader", tape, "--speed", std::to_string(speed)}, "/tmp/adapter_bench_sim.out");
        if (sim.device.empty()) {
            state.SkipWithError("tape-adapter-sim did not start");
            return;
        }
        std::vector<std::uint8_t> got;
        got.reserve(n);
        auto start = std::chrono::steady_clock::now();
        try {
            auto t = tape::open_device(sim.device, tape::DeviceUse::read);
            std::uint8_t buf[4096];
            for (;;) {
                auto r = t->read(buf, 100ms);
                got.insert(got.end(), buf, buf + r.count);
                if (r.end) break;
            }
        } catch (const tape::Error& e) {
            state.SkipWithError(e.what());
            return;
        }
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::size_t same = 0;
        while (same < got.size() && same < n && got[same] == frames[same]) ++same;
        state.counters["sim_fps"] = static_cast<double>(got.size()) / (s * speed);
        state.counters["lost"] = static_cast<double>(n - std::min(n, same));
        state.counters["doubled"] = static_cast<double>(got.size() > n ? got.size() - n : 0);
        state.counters["real_s"] = s;
    }
}
// 10 minutes of tape at 1500 frames/s, 30 times faster than real time.
BENCHMARK(BM_AdapterCdcRead)->Args({900000, 30})->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_AdapterCdcLostPacketReported(benchmark::State& state) {
    std::vector<std::uint8_t> frames;
    std::string tape = make_tape(30000, frames);
    for (auto _ : state) {
        Sim sim({"--reader", tape, "--drop-packet", "20", "--drop-times", "1000000"}, "/tmp/adapter_bench_sim.out");
        if (sim.device.empty()) {
            state.SkipWithError("tape-adapter-sim did not start");
            return;
        }
        std::size_t got = 0;
        std::chrono::steady_clock::time_point stalled{};
        std::string error;
        try {
            auto t = tape::open_device(sim.device, tape::DeviceUse::read);
            std::uint8_t buf[4096];
            for (;;) {
                auto r = t->read(buf, 20ms);
                if (r.count) stalled = {};
                if (!r.count && stalled == std::chrono::steady_clock::time_point{})
                    stalled = std::chrono::steady_clock::now();
                got += r.count;
                if (r.end) break;
            }
        } catch (const tape::Error& e) {
            error = e.what();
        }
        if (error.find(" lost") == std::string::npos) {
            state.SkipWithError("the loss was not reported");
            return;
        }
        // From the last row the host took (the loss is right after it) to the report.
        state.counters["report_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - stalled).count();
        state.counters["kept_frames"] = static_cast<double>(got);
    }
}
BENCHMARK(BM_AdapterCdcLostPacketReported)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
