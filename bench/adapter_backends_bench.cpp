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

#include "adapter_reading.hpp"
#include "fake_adapter/fake_adapter.hpp"

namespace {

using namespace std::chrono_literals;

void BM_AdapterRead(benchmark::State& state) {
    const auto link = static_cast<fake::Link>(state.range(0));
    const std::size_t n = static_cast<std::size_t>(state.range(1));
    const double speed = static_cast<double>(state.range(2));
    if (link != fake::Link::cdc && !fake::umockdev_unavailable().empty()) {
        state.SkipWithError(fake::umockdev_unavailable().c_str());
        return;
    }
    state.SetLabel(fake::link_name(link));
    auto tape = adapter_test_tape(n);
    for (auto _ : state) {
        fake::Options o;
        o.link = link;
        o.serial = std::string("BENCH-") + fake::link_name(link);
        o.speed = speed;
        o.tape = tape;
        fake::Adapter a(o);
        read_and_score(state, a.device(), tape, speed);
    }
}

void BM_AdapterLostPacketReported(benchmark::State& state) {
    const auto link = static_cast<fake::Link>(state.range(0));
    if (link != fake::Link::cdc && !fake::umockdev_unavailable().empty()) {
        state.SkipWithError(fake::umockdev_unavailable().c_str());
        return;
    }
    state.SetLabel(fake::link_name(link));
    auto tape = adapter_test_tape(30000);
    for (auto _ : state) {
        fake::Options o;
        o.link = link;
        o.serial = std::string("LOST-") + fake::link_name(link);
        o.speed = 1;  // real time: the report's delay is the host's own
        o.tape = tape;
        o.faults.drop_rows_packet = 20;
        o.faults.drop_times = 1000000;
        fake::Adapter a(o);
        time_loss_report(state, a.device());
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
