// What the benchmarks against tape-adapter-sim share (adapter_bench, adapter_emulate_bench): the
// simulator and the tape CLI as processes, their outputs, and distributions as counters.
#pragma once

#include <benchmark/benchmark.h>
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "spawn_util.hpp"

namespace sim_process {

using namespace std::chrono_literals;

struct Sim {
    pid_t pid = -1;
    std::string device;
    Sim(const std::vector<std::string>& args, const std::string& out, const std::string& err = "") {
        pid = spawn_to_files(TAPE_ADAPTER_SIM, args, out, err);
        for (auto end = std::chrono::steady_clock::now() + 10s; pid > 0 && std::chrono::steady_clock::now() < end;) {
            std::ifstream in(out);
            std::getline(in, device);
            if (!device.empty()) break;
            std::this_thread::sleep_for(5ms);
        }
    }
    ~Sim() { stop(); }
    void stop() {
        if (pid > 0) {
            ::kill(pid, SIGTERM);
            ::waitpid(pid, nullptr, 0);
            pid = -1;
        }
    }
};

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A value from the simulator's --stats line ("name=value"), -1 when it is not there.
inline double sim_stat(const std::string& err, const std::string& name) {
    auto at = err.find(" " + name + "=");
    return at == std::string::npos ? -1 : std::stod(err.substr(at + name.size() + 2));
}

// Runs tape with args to its end (deadline: the status is -1 after it, and it is killed).
inline int run_tape(const std::vector<std::string>& args, const std::string& out, const std::string& err,
                    std::chrono::milliseconds deadline, pid_t* pid_out = nullptr) {
    pid_t pid = spawn_to_files(TAPE_BINARY, args, out, err);
    if (pid < 0) return -1;
    if (pid_out) *pid_out = pid;
    auto status = wait_for_exit(pid, deadline);
    if (!status) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
        return -1;
    }
    return WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
}

// min, median, p99 and max of values as counters named prefix_min and so on.
inline void distribution(benchmark::State& state, const std::string& prefix, std::vector<double> v) {
    if (v.empty()) return;
    std::sort(v.begin(), v.end());
    state.counters[prefix + "_min"] = v.front();
    state.counters[prefix + "_median"] = v[v.size() / 2];
    state.counters[prefix + "_p99"] = v[std::min(v.size() - 1, v.size() * 99 / 100)];
    state.counters[prefix + "_max"] = v.back();
}

}  // namespace sim_process
