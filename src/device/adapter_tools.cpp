// adapter_info, adapter_configure and adapter_selftest: the adapter's own questions, on the shared session.
#include <random>

#include "adapter_session.hpp"
#include "tape/adapter.hpp"

namespace tape {

namespace {

AdapterInfo to_info(const tapefw::Info& i) {
    AdapterInfo a;
    a.protocol = i.protocol;
    a.firmware =
        std::to_string(i.firmware[0]) + "." + std::to_string(i.firmware[1]) + "." + std::to_string(i.firmware[2]);
    a.serial = i.serial;
    a.reader = i.capabilities & tapefw::caps::reader;
    a.punch = i.capabilities & tapefw::caps::punch;
    a.reverse = i.capabilities & tapefw::caps::reverse;
    a.row_flags = i.capabilities & tapefw::caps::row_flags;
    for (int n = 5; n <= 8; ++n)
        if (i.tracks & (1 << (n - 5))) a.tracks.push_back(n);
    a.max_read_rate = i.max_read_rate;
    a.max_punch_rate = i.max_punch_rate;
    a.read_buffer = i.read_buffer;
    a.punch_buffer = i.punch_buffer;
    return a;
}

}  // namespace

AdapterInfo adapter_info(std::string_view device) {
    adapter::Session s(adapter::open_pipe(device));
    return to_info(s.info());
}

std::string adapter_config_problem(const AdapterConfig& c) {
    // The ranges the engine and a board can honour: 16-bit fields, a sample taken within a frame of
    // the slowest reader, pulses a magnet or clutch can be driven with.
    struct Range {
        const char* name;
        unsigned value, min, max;
        const char* unit;
    };
    const Range ranges[] = {
        {"invert", c.data_invert, 0, 255, ""},
        {"tracks", c.tracks, 5, 8, ""},
        {"sample-delay", c.sample_delay_us, 0, 5000, " us"},
        {"punch-pulse", c.punch_pulse_us, 100, 50000, " us"},
        {"drive-pulse", c.drive_pulse_us, 10, 50000, " us"},
        {"sprocket-timeout", c.sprocket_timeout_ms, 1, 65535, " ms"},
        {"watchdog", c.watchdog_ms, 0, 65535, " ms"},
    };
    for (const auto& r : ranges)
        if (r.value < r.min || r.value > r.max)
            return std::string(r.name) + ": " + std::to_string(r.value) + " is not " + std::to_string(r.min) + " to " +
                   std::to_string(r.max) + r.unit;
    return "";
}

tapefw::Config adapter::to_wire(const AdapterConfig& c) {
    namespace lb = tapefw::line_bit;
    tapefw::Config f;
    f.data_invert = static_cast<std::uint8_t>(c.data_invert);
    f.tracks = static_cast<std::uint8_t>(c.tracks);
    f.lines = static_cast<std::uint8_t>(
        (c.sprocket_low ? lb::sprocket_low : 0) | (c.strobe_falling ? lb::strobe_falling : 0) |
        (c.drive_pulse ? lb::drive_pulse : 0) | (c.drive_low ? lb::drive_low : 0) |
        (c.status_low ? lb::status_low : 0) | (c.punch_ready_low ? lb::punch_ready_low : 0) |
        (c.punch_magnet_low ? lb::punch_magnet_low : 0));
    f.sample_delay_us = static_cast<std::uint16_t>(c.sample_delay_us);
    f.punch_pulse_us = static_cast<std::uint16_t>(c.punch_pulse_us);
    f.drive_pulse_us = static_cast<std::uint16_t>(c.drive_pulse_us);
    f.sprocket_timeout_ms = static_cast<std::uint16_t>(c.sprocket_timeout_ms);
    f.watchdog_ms = static_cast<std::uint16_t>(c.watchdog_ms);
    return f;
}

void adapter_configure(std::string_view device, const AdapterConfig& c) {
    if (auto problem = adapter_config_problem(c); !problem.empty()) throw Error(Errc::usage, problem);
    adapter::Session s(adapter::open_pipe(device));
    s.configure(adapter::to_wire(c));
}

AdapterSelftest adapter_selftest(std::string_view device, std::chrono::milliseconds duration, std::uint32_t seed) {
    adapter::Session s(adapter::open_pipe(device));
    std::mt19937 rng(seed);
    AdapterSelftest r;
    auto start = std::chrono::steady_clock::now();
    auto end = start + duration;
    std::vector<std::uint8_t> payload(tapefw::max_payload);
    while (std::chrono::steady_clock::now() < end) {
        // Every byte value, zeros and runs included, over the test: COBS and the CRC both exercised.
        for (auto& b : payload) b = static_cast<std::uint8_t>(rng());
        if (r.packets % 7 == 0) std::fill(payload.begin(), payload.begin() + 20, 0);
        auto back = s.echo(payload);
        ++r.packets;
        r.bytes += payload.size();
        if (back != payload) ++r.mismatches;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.round_trip_ms = r.packets ? r.seconds * 1000 / static_cast<double>(r.packets) : 0;
    r.bad_in = s.bad_packets_in();
    r.bad_out = s.bad_packets_out();
    return r;
}

}  // namespace tape
