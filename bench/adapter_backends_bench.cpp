// Reading through each adapter backend — adapter: (CDC), usb: (libusb bulk), hid: (hidapi) — from the
// firmware core with a simulated ФС-1501 at 1500 frames/s (tests/fake_adapter), its clock faster than
// real time by the second argument; for usb: and hid: umockdev plays the kernel's usbfs and hidraw.
// Counters: sim_fps (simulated frames a simulated second: 1500 when the host kept up), lost and doubled
// (proven by the frame counter: both must be 0). A second benchmark drops one ROWS packet for good and
// times how long the host takes to report its frame range (report_s).
// Run: build/bin/adapter_backends_bench
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <vector>

#include "fake_adapter/fake_adapter.hpp"
#include "tape/device.hpp"
#include "tape/error.hpp"

namespace {

using namespace std::chrono_literals;

std::vector<std::uint8_t> make_tape(std::size_t n) {
    std::vector<std::uint8_t> frames(n);
    for (std::size_t i = 0; i < n; ++i) frames[i] = static_cast<std::uint8_t>((i * 131 + i / 977) & 0xFF);
    return frames;
}

void BM_AdapterRead(benchmark::State& state) {
    const auto link = static_cast<fake::Link>(state.range(0));
    const std::size_t n = static_cast<std::size_t>(state.range(1));
    const double speed = static_cast<double>(state.range(2));
    if (link != fake::Link::cdc && !fake::umockdev_unavailable().empty()) {
        state.SkipWithError(fake::umockdev_unavailable().c_str());
        return;
    }
    state.SetLabel(fake::link_name(link));
    auto tape = make_tape(n);
    for (auto _ : state) {
        fake::Options o;
        o.link = link;
        o.serial = std::string("BENCH-") + fake::link_name(link);
        o.speed = speed;
        o.tape = tape;
        fake::Adapter a(o);
        std::vector<std::uint8_t> got;
        got.reserve(n);
        auto start = std::chrono::steady_clock::now();
        try {
            auto t = tape::open_device(a.device(), tape::DeviceUse::read);
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
        while (same < std::min(n, got.size()) && got[same] == tape[same]) ++same;
        state.counters["frames"] = static_cast<double>(got.size());
        state.counters["sim_fps"] = static_cast<double>(got.size()) / (s * speed);
        state.counters["lost"] = static_cast<double>(n - std::min(n, same));
        state.counters["doubled"] = static_cast<double>(got.size() > n ? got.size() - n : 0);
        state.counters["real_s"] = s;
    }
}

void BM_AdapterLostPacketReported(benchmark::State& state) {
    const auto link = static_cast<fake::Link>(state.range(0));
    if (link != fake::Link::cdc && !fake::umockdev_unavailable().empty()) {
        state.SkipWithError(fake::umockdev_unavailable().c_str());
        return;
    }
    state.SetLabel(fake::link_name(link));
    auto tape = make_tape(30000);
    for (auto _ : state) {
        fake::Options o;
        o.link = link;
        o.serial = std::string("LOST-") + fake::link_name(link);
        o.speed = 1;  // real time: the report's delay is the host's own
        o.tape = tape;
        o.faults.drop_rows_packet = 20;
        o.faults.drop_times = 1000000;
        fake::Adapter a(o);
        std::size_t got = 0;
        std::chrono::steady_clock::time_point stalled{};
        std::string error;
        try {
            auto t = tape::open_device(a.device(), tape::DeviceUse::read);
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
            state.SkipWithError(("the loss was not reported: " + error).c_str());
            return;
        }
        // From the last row the host took (the loss is right after it) to the report.
        state.counters["report_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - stalled).count();
        state.counters["kept_frames"] = static_cast<double>(got);
    }
}

// Ten minutes of tape at 1500 frames/s (900 000 frames) through each backend, at 30 times real time.
BENCHMARK(BM_AdapterRead)
    ->Args({static_cast<int>(fake::Link::cdc), 900000, 30})
    ->Args({static_cast<int>(fake::Link::usb), 900000, 30})
    ->Args({static_cast<int>(fake::Link::hid), 900000, 30})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_AdapterLostPacketReported)
    ->Arg(static_cast<int>(fake::Link::cdc))
    ->Arg(static_cast<int>(fake::Link::usb))
    ->Arg(static_cast<int>(fake::Link::hid))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
