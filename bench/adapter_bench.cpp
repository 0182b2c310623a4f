// Through the USB tape adapter: the adapter: backend and the tape CLI against tape-adapter-sim (the
// firmware core with a simulated ФС-1501 at 1500 frames/s and a ПЛ-150 at 150 rows/s) on
// pseudo-terminals. Run: build/bin/adapter_bench   (every benchmark one iteration; counters below)
//  - BM_AdapterCdcRead: 900k frames at 30x: sim_fps (1500 when nothing waited), lost and doubled (0).
//  - BM_AdapterCdcLostPacketReported: one ROWS packet dropped for good: report_s, the time to the report.
//  - BM_EmulateStopOnDc3: the reader emulator (tape emulate's loop) into a pseudo-terminal at 1500
//    frames/s; the controller's side sends DC1, then DC3 at a random moment, 300 times: frames that
//    arrive after DC3 was written (frames_arrived_after_dc3), the same less those already waiting in
//    the pseudo-terminal when it was written (frames_after_dc3: sent after the stop), and the time
//    from DC3 to the last frame (last_frame_us); min/median/p99/max of each.
//  - BM_AdapterPunchHostStall: tape punch of 10000 rows at 150 rows/s (real time), the tape process
//    stopped (SIGSTOP) for 1 s at 20 s, then --verify through --loop with 8 rows punched wrong
//    (--miss-hole-at): underruns (rows punched after the punch stood ready with no row queued, from
//    the simulator's --stats), late_punches (rows more than 1.5 cycles after the one before, for any
//    reason, the simulator's own catching up included), and the differences named of those planted.
//  - BM_AdapterDesyncs: 40000 frames with a desync (noise or half a packet) before every 20th ROWS
//    packet: desyncs, and the longest wait between two deliveries of rows with them and without.
//  - BM_AdapterUnplugs: 100 runs of tape read with --unplug-after N (N from 100 to 2773): runs that
//    ended with exit 3 and the file a prefix of the tape, frames kept, frames the adapter had read
//    but the file lacks.
#include <benchmark/benchmark.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "adapter_reading.hpp"
#include "adapter_sim_process.hpp"
#include "emulator_on_pty.hpp"
#include "spawn_util.hpp"
#include "tape/device.hpp"
#include "tape/dnc.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"

namespace {

using namespace std::chrono_literals;
using namespace sim_process;

std::string make_tape(std::size_t n, std::vector<std::uint8_t>& frames) {
    frames = adapter_test_tape(n);
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
        read_and_score(state, sim.device, frames, speed);
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
        time_loss_report(state, sim.device);
    }
}
BENCHMARK(BM_AdapterCdcLostPacketReported)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

namespace emulate_stop {

using clock = std::chrono::steady_clock;

// Reads what the emulator sends until quiet for quiet_ms: the number of bytes and when the last came.
std::size_t drain(int master, int quiet_ms, clock::time_point& last) {
    std::uint8_t buf[4096];
    std::size_t n = 0;
    for (;;) {
        pollfd p{master, POLLIN, 0};
        if (::poll(&p, 1, quiet_ms) <= 0) return n;
        ssize_t got = ::read(master, buf, sizeof buf);
        if (got <= 0) return n;
        n += static_cast<std::size_t>(got);
        last = clock::now();
    }
}

// Reads what comes for the given time: the number of bytes.
std::size_t read_for(int master, std::chrono::microseconds span) {
    std::uint8_t buf[4096];
    std::size_t running = 0;
    auto until = clock::now() + span;
    while (clock::now() < until) {
        pollfd p{master, POLLIN, 0};
        if (::poll(&p, 1, 1) > 0) {
            ssize_t got = ::read(master, buf, sizeof buf);
            if (got > 0) running += static_cast<std::size_t>(got);
        }
    }
    return running;
}

struct Figures {
    std::vector<double> after, arrived, stop_us;
};

// One DC1 ... DC3: frames flow for a random 20 to 60 ms (the controller's buffer filling), then DC3 and
// what still comes. False when the pseudo-terminal fails.
bool one_stop(int master, std::mt19937& rng, Figures& f) {
    std::uint8_t dc1 = tape::dc1, dc3 = tape::dc3;
    bool ok = ::write(master, &dc1, 1) == 1;
    std::size_t running = read_for(master, std::chrono::microseconds(20000 + rng() % 40000));
    // Frames the emulator wrote before DC3 may still wait in the pseudo-terminal (the controller's
    // side was not scheduled): those waiting just before DC3 is written are not charged to the stop.
    int waiting = 0;
    ::ioctl(master, FIONREAD, &waiting);
    auto sent_dc3 = clock::now();
    ok = ok && ::write(master, &dc3, 1) == 1 && running > 0;
    clock::time_point last = sent_dc3;
    std::size_t n = drain(master, 50, last);
    f.arrived.push_back(static_cast<double>(n));
    f.after.push_back(static_cast<double>(n) - std::min<double>(waiting, static_cast<double>(n)));
    f.stop_us.push_back(n ? std::chrono::duration<double, std::micro>(last - sent_dc3).count() : 0.0);
    return ok;
}

}  // namespace emulate_stop

void BM_EmulateStopOnDc3(benchmark::State& state) {
    const double rate = 1500;
    const int stops = static_cast<int>(state.range(0));
    auto tape = long_program_tape(400000);
    for (auto _ : state) {
        EmulatorOnPty emulator(tape, rate);
        if (emulator.master < 0) {
            state.SkipWithError("openpty failed");
            return;
        }
        std::mt19937 rng(7);
        emulate_stop::Figures f;
        bool ok = true;
        for (int i = 0; i < stops && ok; ++i) ok = emulate_stop::one_stop(emulator.master, rng, f);
        if (!ok) {
            state.SkipWithError("the pseudo-terminal failed");
            return;
        }
        state.counters["stops"] = static_cast<double>(f.after.size());
        state.counters["stops_over_1_frame"] =
            static_cast<double>(std::count_if(f.after.begin(), f.after.end(), [](double n) { return n > 1; }));
        distribution(state, "frames_after_dc3", f.after);
        distribution(state, "frames_arrived_after_dc3", f.arrived);
        distribution(state, "last_frame_us", f.stop_us);
    }
}
BENCHMARK(BM_EmulateStopOnDc3)->Arg(300)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void BM_AdapterPunchHostStall(benchmark::State& state) {
    const std::size_t n = static_cast<std::size_t>(state.range(0));
    std::vector<std::uint8_t> frames;
    std::string tape = make_tape(n, frames);
    // Rows punched wrong, each with a lowest hole to lose (so that the read-back differs).
    std::vector<std::string> sim_args = {"--loop", "--stats"};
    std::vector<std::size_t> planted;
    for (std::size_t at = 700; planted.size() < 8 && at < n; at += n / 9) {
        while (frames[at - 1] == 0) ++at;
        planted.push_back(at);
        sim_args.insert(sim_args.end(), {"--miss-hole-at", std::to_string(at)});
    }
    const std::string dir = "/tmp/adapter_bench_";
    for (auto _ : state) {
        Sim sim(sim_args, dir + "sim.out", dir + "sim.err");
        if (sim.device.empty()) {
            state.SkipWithError("tape-adapter-sim did not start");
            return;
        }
        // The adapter's watchdog (500 ms) would stop the punch in a 1 s stall, as it should: it is set to 3 s.
        if (run_tape({"adapter", "config", sim.device, "--watchdog", "3000"}, dir + "cfg.out", dir + "cfg.err", 10s) !=
            0) {
            state.SkipWithError("tape adapter config failed");
            return;
        }
        pid_t pid = -1;
        int status = -1;
        std::thread punch([&] {
            status = run_tape({"punch", tape, sim.device, "--verify", sim.device, "--verify-timeout", "1"},
                              dir + "punch.out", dir + "punch.err", 200s, &pid);
        });
        // The host stalls for 1 s, 20 s into the run (about 3000 rows punched, the adapter's queue full).
        std::this_thread::sleep_for(20s);
        bool stalled = pid > 0 && ::kill(pid, SIGSTOP) == 0;
        std::this_thread::sleep_for(1s);
        if (pid > 0) ::kill(pid, SIGCONT);
        punch.join();
        sim.stop();
        std::string err = slurp(dir + "punch.err"), stats = slurp(dir + "sim.err");
        std::size_t named = 0;
        for (auto at : planted)
            if (err.find("frame " + std::to_string(at) + ": punched ") != std::string::npos) ++named;
        state.counters["exit_status"] = status;
        state.counters["stalled"] = stalled;
        state.counters["rows_punched"] = sim_stat(stats, "rows_punched");
        state.counters["underruns"] = sim_stat(stats, "underruns");
        state.counters["late_punches"] = sim_stat(stats, "late_punches");
        state.counters["longest_punch_gap_ms"] = sim_stat(stats, "longest_punch_gap_us") / 1000;
        state.counters["planted"] = static_cast<double>(planted.size());
        state.counters["planted_named"] = static_cast<double>(named);
        state.counters["other_differences_named"] =
            static_cast<double>(std::count(err.begin(), err.end(), '\n')) - static_cast<double>(named);
    }
}
BENCHMARK(BM_AdapterPunchHostStall)->Arg(10000)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

// Reads a whole tape through the backend, noting the longest wait between two deliveries of rows.
struct TimedRead {
    std::vector<std::uint8_t> rows;
    double longest_wait_ms = 0;
    std::string error;
};
TimedRead timed_read(const std::string& device) {
    TimedRead r;
    try {
        auto t = tape::open_device(device, tape::DeviceUse::read);
        std::uint8_t buf[4096];
        std::chrono::steady_clock::time_point last{};
        for (;;) {
            auto got = t->read(buf, 5ms);
            if (got.count) {
                auto now = std::chrono::steady_clock::now();
                if (last != std::chrono::steady_clock::time_point{})
                    r.longest_wait_ms =
                        std::max(r.longest_wait_ms, std::chrono::duration<double, std::milli>(now - last).count());
                last = now;
            }
            r.rows.insert(r.rows.end(), buf, buf + got.count);
            if (got.end) break;
        }
    } catch (const tape::Error& e) {
        r.error = e.what();
    }
    return r;
}

void BM_AdapterDesyncs(benchmark::State& state) {
    std::vector<std::uint8_t> frames;
    std::string tape = make_tape(static_cast<std::size_t>(state.range(0)), frames);
    const std::string dir = "/tmp/adapter_bench_";
    for (auto _ : state) {
        TimedRead clean, faulty;
        {
            Sim sim({"--reader", tape}, dir + "sim.out");
            clean = timed_read(sim.device);
        }
        Sim sim({"--reader", tape, "--stats", "--garbage-every", std::to_string(state.range(1))}, dir + "sim.out",
                dir + "sim.err");
        if (sim.device.empty()) {
            state.SkipWithError("tape-adapter-sim did not start");
            return;
        }
        faulty = timed_read(sim.device);
        sim.stop();
        std::string stats = slurp(dir + "sim.err");
        for (const auto* r : {&clean, &faulty})
            if (!r->error.empty()) {
                state.SkipWithError(r->error.c_str());
                return;
            }
        state.counters["desyncs"] = sim_stat(stats, "desyncs");
        state.counters["complete_and_in_order"] = faulty.rows == frames && clean.rows == frames;
        // From the last rows before a desync to the first after it, at most: the recovery time's bound.
        state.counters["longest_wait_ms"] = faulty.longest_wait_ms;
        state.counters["longest_wait_clean_ms"] = clean.longest_wait_ms;
    }
}
BENCHMARK(BM_AdapterDesyncs)->Args({40000, 20})->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void BM_AdapterUnplugs(benchmark::State& state) {
    const int runs = static_cast<int>(state.range(0));
    std::vector<std::uint8_t> frames;
    std::string tape = make_tape(3000, frames);
    const std::string dir = "/tmp/adapter_bench_";
    for (auto _ : state) {
        int exit3 = 0, prefix = 0, gone = 0;
        std::vector<double> kept, short_of;
        for (int i = 0; i < runs; ++i) {
            std::size_t after = 100 + static_cast<std::size_t>(i) * 27;
            Sim sim({"--reader", tape, "--speed", "4", "--unplug-after", std::to_string(after)}, dir + "sim.out",
                    dir + "sim.err");
            if (sim.device.empty()) {
                state.SkipWithError("tape-adapter-sim did not start");
                return;
            }
            std::remove((dir + "unplug.ptp").c_str());
            int status =
                run_tape({"read", sim.device, "-o", dir + "unplug.ptp"}, dir + "read.out", dir + "read.err", 20s);
            std::string got = slurp(dir + "unplug.ptp");
            exit3 += status == 3;
            prefix += got.size() <= frames.size() &&
                      std::equal(got.begin(), got.end(), frames.begin(),
                                 [](char a, std::uint8_t b) { return static_cast<std::uint8_t>(a) == b; });
            gone += slurp(dir + "read.err").find("the adapter is gone") != std::string::npos;
            kept.push_back(static_cast<double>(got.size()));
            // The simulator unplugs once it has read at least N: rows still in it or on the line are lost.
            short_of.push_back(static_cast<double>(after) - static_cast<double>(got.size()));
        }
        state.counters["runs"] = runs;
        state.counters["exit_3"] = exit3;
        state.counters["file_is_prefix"] = prefix;
        state.counters["said_gone"] = gone;
        distribution(state, "frames_kept", kept);
        distribution(state, "frames_short_of_unplug", short_of);
    }
}
BENCHMARK(BM_AdapterUnplugs)->Arg(100)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
