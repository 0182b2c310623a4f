// What the adapter benchmarks share (adapter_bench against tape-adapter-sim, adapter_backends_bench
// against the fake adapter of the tests): the tape read, reading a run whole and scoring it by the frame
// counter, and timing the report of a packet lost for good.
#pragma once

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "tape/device.hpp"
#include "tape/error.hpp"

/// n frames of every value, in an order that repeats only after a long stretch.
inline std::vector<std::uint8_t> adapter_test_tape(std::size_t n) {
    std::vector<std::uint8_t> frames(n);
    for (std::size_t i = 0; i < n; ++i) frames[i] = static_cast<std::uint8_t>((i * 131 + i / 977) & 0xFF);
    return frames;
}

/// Reads device until the tape's end and sets the counters frames, sim_fps (simulated frames a simulated
/// second, the clock running speed times real time), lost and doubled (against tape, by position: both
/// must be 0) and real_s. A failure skips the benchmark with its message.
inline void read_and_score(benchmark::State& state, const std::string& device, const std::vector<std::uint8_t>& tape,
                           double speed) {
    std::vector<std::uint8_t> got;
    got.reserve(tape.size());
    auto start = std::chrono::steady_clock::now();
    try {
        auto t = tape::open_device(device, tape::DeviceUse::read);
        std::uint8_t buf[4096];
        for (;;) {
            auto r = t->read(buf, std::chrono::milliseconds(100));
            got.insert(got.end(), buf, buf + r.count);
            if (r.end) break;
        }
    } catch (const tape::Error& e) {
        state.SkipWithError(e.what());
        return;
    }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t n = tape.size();
    std::size_t same = 0;
    while (same < std::min(n, got.size()) && got[same] == tape[same]) ++same;
    state.counters["frames"] = static_cast<double>(got.size());
    state.counters["sim_fps"] = static_cast<double>(got.size()) / (s * speed);
    state.counters["lost"] = static_cast<double>(n - same);
    state.counters["doubled"] = static_cast<double>(got.size() > n ? got.size() - n : 0);
    state.counters["real_s"] = s;
}

/// Reads device, whose adapter drops a packet for good, until the host reports the loss; sets report_s
/// (from the last row the host took, the loss being right after it, to the report) and kept_frames.
/// Skips the benchmark when the loss is not reported.
inline void time_loss_report(benchmark::State& state, const std::string& device) {
    std::size_t got = 0;
    std::chrono::steady_clock::time_point stalled{};
    std::string error;
    try {
        auto t = tape::open_device(device, tape::DeviceUse::read);
        std::uint8_t buf[4096];
        for (;;) {
            auto r = t->read(buf, std::chrono::milliseconds(20));
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
        state.SkipWithError(("the loss was not reported: " + error).c_str());
        return;
    }
    state.counters["report_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - stalled).count();
    state.counters["kept_frames"] = static_cast<double>(got);
}
