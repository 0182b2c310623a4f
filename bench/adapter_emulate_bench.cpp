// The adapter standing in for a control's tape reader: tape emulate (a process) through the adapter:
// backend to tape-adapter-sim playing the control (--control), on pseudo-terminals.
// Run: build/bin/adapter_emulate_bench   (every benchmark one iteration; counters below)
//  - BM_AdapterEmulateMillion: a program of 10^6 frames at 30 times real time (1500 frames/s simulated),
//    the control stopping the reader 1000 times at random frames: frames taken (1e6), wrong (frames that
//    differ from the tape by position, 0), stops, frames_after_stop (max 1, the braking distance) and
//    stops_over_1_frame, longest_restart_us (from a start to its first strobe, simulated, <= 2000),
//    longest_gap_us (simulated, between strobes while the control runs), sim_fps.
//  - BM_AdapterEmulateHostStall: 15000 frames at real time, the tape process stopped (SIGSTOP) for 1 s
//    after 4 s (the adapter's watchdog set to 3 s): taken, wrong and doubled (both 0), and the gap the
//    control saw (a slow reader, not a wrong frame).
#include <benchmark/benchmark.h>
#include <signal.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "adapter_sim_process.hpp"
#include "emulator_on_pty.hpp"

namespace {

using namespace sim_process;

const std::string dir = "/tmp/adapter_emulate_bench_";

std::string write_tape(const std::vector<tape::Frame>& frames) {
    std::string path = dir + "tape.ptp";
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(frames.data()), static_cast<std::streamsize>(frames.size()));
    return path;
}

// The control's JSON line among the simulator's stderr lines, or null.
nlohmann::json control_stats(const std::string& err) {
    auto at = err.rfind("\n{");
    if (at == std::string::npos) return nullptr;
    return nlohmann::json::parse(err.substr(at + 1, err.find('\n', at + 1) - at - 1), nullptr, false);
}

// Waits (up to limit) until the control has taken n frames into out; then ends tape emulate with Ctrl-C.
bool wait_taken(const std::string& out, std::size_t n, pid_t tape_pid, std::chrono::seconds limit) {
    auto end = std::chrono::steady_clock::now() + limit;
    std::ifstream probe;
    while (std::chrono::steady_clock::now() < end) {
        std::ifstream in(out, std::ios::binary | std::ios::ate);
        if (in && static_cast<std::size_t>(in.tellg()) >= n) break;
        std::this_thread::sleep_for(50ms);
    }
    ::kill(tape_pid, SIGINT);
    return slurp(out).size() >= n;
}

// Frames the control took that are not the tape's at their place, and frames past its end.
void score(benchmark::State& state, const std::string& taken, const std::vector<tape::Frame>& tape) {
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < std::min(taken.size(), tape.size()); ++i)
        wrong += static_cast<std::uint8_t>(taken[i]) != tape[i];
    state.counters["taken"] = static_cast<double>(taken.size());
    state.counters["wrong"] = static_cast<double>(wrong);
    state.counters["doubled"] = static_cast<double>(taken.size() > tape.size() ? taken.size() - tape.size() : 0);
}

void stop_counters(benchmark::State& state, const nlohmann::json& stats) {
    if (stats.is_null()) return state.SkipWithError("no JSON line from the simulator's --stats");
    std::vector<double> after;
    for (unsigned n : stats["frames_after_stop"]) after.push_back(n);
    state.counters["stops"] = static_cast<double>(after.size());
    state.counters["stops_over_1_frame"] =
        static_cast<double>(std::count_if(after.begin(), after.end(), [](double n) { return n > 1; }));
    distribution(state, "frames_after_stop", after);
    state.counters["longest_restart_us"] = stats["longest_restart_us"].get<double>();
    state.counters["longest_gap_us"] = stats["longest_gap_us"].get<double>();
}

void BM_AdapterEmulateMillion(benchmark::State& state) {
    const auto frames = long_program_tape(static_cast<std::size_t>(state.range(0)));
    const std::string speed = std::to_string(state.range(1));
    const std::string path = write_tape(frames);
    for (auto _ : state) {
        std::remove((dir + "control.out").c_str());
        Sim sim({"--control", dir + "control.out", "--control-stops", std::to_string(state.range(2)), "--speed", speed,
                 "--stats"},
                dir + "sim.out", dir + "sim.err");
        if (sim.device.empty()) return state.SkipWithError("tape-adapter-sim did not start");
        auto began = std::chrono::steady_clock::now();
        pid_t pid = spawn_to_files(TAPE_BINARY, {"emulate", path, sim.device}, dir + "tape.out", dir + "tape.err");
        bool all = wait_taken(dir + "control.out", frames.size(), pid, 600s);
        double real_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
        auto status = wait_for_exit(pid, 20s);
        sim.stop();
        if (!all)
            return state.SkipWithError(("the control did not take every frame: " + slurp(dir + "tape.err")).c_str());
        score(state, slurp(dir + "control.out"), frames);
        stop_counters(state, control_stats(slurp(dir + "sim.err")));
        state.counters["tape_exit"] = status && WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
        state.counters["sim_fps"] = static_cast<double>(frames.size()) / (real_s * static_cast<double>(state.range(1)));
    }
}
BENCHMARK(BM_AdapterEmulateMillion)->Args({1000000, 30, 1000})->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void BM_AdapterEmulateHostStall(benchmark::State& state) {
    const auto frames = long_program_tape(static_cast<std::size_t>(state.range(0)));
    const std::string path = write_tape(frames);
    for (auto _ : state) {
        std::remove((dir + "control.out").c_str());
        Sim sim({"--control", dir + "control.out", "--stats"}, dir + "sim.out", dir + "sim.err");
        if (sim.device.empty()) return state.SkipWithError("tape-adapter-sim did not start");
        // The watchdog (500 ms) would end the run in a 1 s stall, as it should: it is set to 3 s.
        pid_t pid = spawn_to_files(TAPE_BINARY, {"emulate", path, sim.device + "?watchdog=3000"}, dir + "tape.out",
                                   dir + "tape.err");
        std::this_thread::sleep_for(4s);
        bool stalled = ::kill(pid, SIGSTOP) == 0;
        std::this_thread::sleep_for(1s);
        ::kill(pid, SIGCONT);
        bool all = wait_taken(dir + "control.out", frames.size(), pid, 60s);
        wait_for_exit(pid, 20s);
        sim.stop();
        if (!all)
            return state.SkipWithError(("the control did not take every frame: " + slurp(dir + "tape.err")).c_str());
        score(state, slurp(dir + "control.out"), frames);
        stop_counters(state, control_stats(slurp(dir + "sim.err")));
        state.counters["stalled"] = stalled;
    }
}
BENCHMARK(BM_AdapterEmulateHostStall)->Arg(15000)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
