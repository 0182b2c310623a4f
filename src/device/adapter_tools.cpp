// adapter_info and adapter_selftest: the adapter's own questions, on the shared session.
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
