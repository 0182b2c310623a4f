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
    a.emulate = i.capabilities & tapefw::caps::emulate;
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

namespace tape {
namespace {

tapefw::Wiring wiring_to_wire(const AdapterWiring& w) {
    namespace wb = tapefw::wiring_bit;
    tapefw::Wiring f;
    for (std::size_t i = 0; i < 8; ++i)
        f.data_pins[i] = static_cast<std::uint8_t>(i < w.data_pins.size() ? w.data_pins[i] : tapefw::Wiring::no_pin);
    f.strobe_pin = static_cast<std::uint8_t>(w.strobe_pin);
    f.run_pin = static_cast<std::uint8_t>(w.run_pin);
    f.reverse_pin = static_cast<std::uint8_t>(w.reverse_pin.value_or(tapefw::Wiring::no_pin));
    f.rewind_pin = static_cast<std::uint8_t>(w.rewind_pin.value_or(tapefw::Wiring::no_pin));
    f.data_invert = static_cast<std::uint8_t>(w.data_invert);
    f.tracks = static_cast<std::uint8_t>(w.tracks);
    f.lines = static_cast<std::uint8_t>((w.strobe_low ? wb::strobe_low : 0) | (w.run_low ? wb::run_low : 0) |
                                        (w.reverse_low ? wb::reverse_low : 0) | (w.rewind_low ? wb::rewind_low : 0));
    f.braking = static_cast<std::uint8_t>(w.braking);
    f.rate = static_cast<std::uint16_t>(w.rate);
    f.strobe_us = static_cast<std::uint16_t>(w.strobe_us);
    f.setup_us = static_cast<std::uint16_t>(w.setup_us);
    f.hold_us = static_cast<std::uint16_t>(w.hold_us);
    f.start_delay_us = static_cast<std::uint16_t>(w.start_delay_us);
    return f;
}

}  // namespace

std::string adapter_wiring_problem(const AdapterWiring& w) {
    // Ranges first, so that a value too large for its field is named rather than cut.
    if (w.data_pins.size() != w.tracks)
        return "data-pins: " + std::to_string(w.data_pins.size()) + " pins for " + std::to_string(w.tracks) + " tracks";
    for (unsigned pin : w.data_pins)
        if (pin > tapefw::Wiring::max_pin) return "data-pins: " + std::to_string(pin) + " is not 0 to 63";
    for (auto pin :
         {std::optional<unsigned>(w.strobe_pin), std::optional<unsigned>(w.run_pin), w.reverse_pin, w.rewind_pin})
        if (pin && *pin > tapefw::Wiring::max_pin) return "pin " + std::to_string(*pin) + " is not 0 to 63";
    if (w.data_invert > 255) return "invert: not a mask of 8 lines";
    for (unsigned us : {w.strobe_us, w.setup_us, w.hold_us, w.start_delay_us})
        if (us > 65535) return std::to_string(us) + " us is more than 65535 us";
    if (w.rate > 4000) return "frame-rate: " + std::to_string(w.rate) + " is not 1 to 4000";
    const char* problem = wiring_to_wire(w).problem();
    return problem ? problem : "";
}

void adapter_configure_emulation(std::string_view device, const AdapterWiring& w) {
    if (auto problem = adapter_wiring_problem(w); !problem.empty()) throw Error(Errc::usage, problem);
    adapter::Session s(adapter::open_pipe(device));
    if (!(s.info().capabilities & tapefw::caps::emulate))
        throw Error(Errc::io, s.name() + ": this adapter cannot stand in for a tape reader (no emulate role)");
    s.set_wiring(wiring_to_wire(w));
}

}  // namespace tape
