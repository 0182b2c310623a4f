// tape adapter info|selftest DEVICE: what a USB tape adapter says about itself, and its link measured.
#include <cstdio>

#include "cli_device.hpp"
#include "cli_numbers.hpp"
#include "commands.hpp"
#include "tape/adapter.hpp"

namespace cli {
namespace {

std::string info_text(const tape::AdapterInfo& i) {
    std::string tracks;
    for (int n : i.tracks) tracks += (tracks.empty() ? "" : ", ") + std::to_string(n);
    std::string out;
    out += "serial\t" + i.serial + "\n";
    out += "protocol\t" + std::to_string(i.protocol) + "\n";
    out += "firmware\t" + i.firmware + "\n";
    out += "reader\t" + std::string(i.reader ? "yes" : "no") +
           (i.reader ? ", " + std::to_string(i.max_read_rate) + " frames/s" + (i.reverse ? ", reverse" : "") : "") +
           "\n";
    out += "punch\t" + std::string(i.punch ? "yes" : "no") +
           (i.punch ? ", " + std::to_string(i.max_punch_rate) + " rows/s" : "") + "\n";
    out += "tracks\t" + tracks + "\n";
    out += "buffers\t" + std::to_string(i.read_buffer) + " rows read, " + std::to_string(i.punch_buffer) +
           " rows to punch\n";
    return out;
}

}  // namespace

void add_adapter(CLI::App& app) {
    auto* sub = app.add_subcommand("adapter", "Ask a USB tape adapter about itself, or test its link");
    sub->require_subcommand(1);
    auto device = std::make_shared<std::string>();
    auto* info = sub->add_subcommand("info", "Print the adapter's serial, versions, capabilities and buffers");
    info->add_option("device", *device, "Device string: adapter:/dev/ttyACM0")->required();
    info->callback([device] {
        try {
            write_output("-", info_text(tape::adapter_info(*device)), false, false);
        } catch (const tape::Error& e) {
            fail("", e);
        }
    });
    auto seconds = std::make_shared<double>(2);
    auto* test = sub->add_subcommand(
        "selftest", "Send pseudo-random packets to the adapter's echo and check every answer; exit 3 on any fault");
    test->add_option("device", *device, "Device string: adapter:/dev/ttyACM0")->required();
    test->add_option("--seconds", *seconds, "How long to test")
        ->check(real_number(0.1, max_timeout_s))
        ->capture_default_str();
    test->callback([device, seconds] {
        tape::AdapterSelftest r;
        try {
            r = tape::adapter_selftest(*device, std::chrono::milliseconds(static_cast<long long>(*seconds * 1000)));
        } catch (const tape::Error& e) {
            fail("", e);
        }
        char line[256];
        std::snprintf(line, sizeof line,
                      "%llu echoes, %llu bytes each way in %.2f s: %.0f bytes/s each way, %.2f ms a round trip; "
                      "%llu wrong, %llu bad packets in, %llu out\n",
                      static_cast<unsigned long long>(r.packets), static_cast<unsigned long long>(r.bytes), r.seconds,
                      r.seconds > 0 ? static_cast<double>(r.bytes) / r.seconds : 0.0, r.round_trip_ms,
                      static_cast<unsigned long long>(r.mismatches), static_cast<unsigned long long>(r.bad_in),
                      static_cast<unsigned long long>(r.bad_out));
        write_output("-", line, false, false);
        if (r.mismatches || r.bad_in || r.bad_out || r.packets == 0)
            fail(*device, tape::Errc::io, "the link is faulty: see the counts above");
    });
}

}  // namespace cli
