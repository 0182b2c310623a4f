// tape adapter info|config|selftest DEVICE: what a USB tape adapter says about itself, its line settings,
// and its link measured.
#include <cstdio>

#include "adapter_wiring.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "device_options.hpp"
#include "tape/adapter.hpp"
#include "tape/utf8_text.hpp"

namespace cli {
namespace {

std::string info_text(const tape::AdapterInfo& i) {
    std::string tracks;
    for (int n : i.tracks) tracks += (tracks.empty() ? "" : ", ") + std::to_string(n);
    std::string out;
    out += "serial\t" + tape::visible(i.serial) + "\n";  // the adapter's own string: no terminal escapes
    out += "protocol\t" + std::to_string(i.protocol) + "\n";
    out += "firmware\t" + tape::visible(i.firmware) + "\n";
    out += "reader\t" + std::string(i.reader ? "yes" : "no") +
           (i.reader ? ", " + std::to_string(i.max_read_rate) + " frames/s" + (i.reverse ? ", reverse" : "") +
                           (i.row_flags ? ", flags doubtful rows" : "")
                     : "") +
           "\n";
    out += "punch\t" + std::string(i.punch ? "yes" : "no") +
           (i.punch ? ", " + std::to_string(i.max_punch_rate) + " rows/s" : "") + "\n";
    out += "emulate\t" + std::string(i.emulate ? "yes, stands in for a reader toward a control" : "no") + "\n";
    out += "tracks\t" + tracks + "\n";
    out += "buffers\t" + std::to_string(i.read_buffer) + " rows read, " + std::to_string(i.punch_buffer) +
           " rows to punch\n";
    return out;
}

std::string config_text(const tape::AdapterConfig& c) {
    char invert[8];
    std::snprintf(invert, sizeof invert, "0x%02X", c.data_invert);
    auto level = [](bool low) { return std::string(low ? "active low" : "active high"); };
    std::string out;
    out += "invert\t" + std::string(invert) + "\n";
    out += "tracks\t" + std::to_string(c.tracks) + "\n";
    out += "sprocket\t" + level(c.sprocket_low) + ", sampled " + std::to_string(c.sample_delay_us) + " us after its " +
           (c.strobe_falling ? "falling" : "rising") + " edge\n";
    out += "drive\t" + std::string(c.drive_pulse ? "pulses of " + std::to_string(c.drive_pulse_us) + " us" : "level") +
           ", " + level(c.drive_low) + "\n";
    out += "status inputs\t" + level(c.status_low) + "\n";
    out += "punch\tready " + level(c.punch_ready_low) + ", magnets " + level(c.punch_magnet_low) + ", held " +
           std::to_string(c.punch_pulse_us) + " us\n";
    out += "sprocket timeout\t" + std::to_string(c.sprocket_timeout_ms) + " ms\n";
    out += "watchdog\t" + (c.watchdog_ms ? std::to_string(c.watchdog_ms) + " ms" : std::string("off")) + "\n";
    return out;
}

// The unit's line settings (a CONFIG): polarities, timing, tape width, the watchdog.
void add_line_options(CLI::App& cfg, tape::AdapterConfig& c, std::string& strobe, std::string& drive) {
    cfg.add_option("--invert", c.data_invert, "Data lines that read a hole as a low level: a mask, bit n for track n+1")
        ->check(line_mask())
        ->capture_default_str();
    cfg.add_option("--tracks", c.tracks, "Tape width: rows are masked to this many tracks")
        ->check(whole_number(5, 8))
        ->capture_default_str();
    cfg.add_flag("--sprocket-low", c.sprocket_low, "The sprocket signal is active low");
    cfg.add_option("--strobe", strobe, "The sprocket edge that marks a stable row")
        ->check(CLI::IsMember({"rising", "falling"}))
        ->capture_default_str();
    cfg.add_option("--sample-delay", c.sample_delay_us, "Microseconds from the sprocket edge to sampling the data")
        ->check(whole_number(0, 5000))
        ->capture_default_str();
    cfg.add_option("--drive", drive, "Start and stop as a level, or as pulses of --drive-pulse")
        ->check(CLI::IsMember({"level", "pulse"}))
        ->capture_default_str();
    cfg.add_option("--drive-pulse", c.drive_pulse_us, "Start and stop pulse length in microseconds")
        ->check(whole_number(10, 50000))
        ->capture_default_str();
    cfg.add_flag("--drive-low", c.drive_low, "Start/stop and direction lines are active low");
    cfg.add_flag("--status-low", c.status_low, "Tape-out and fault inputs are active low");
    cfg.add_flag("--punch-ready-low", c.punch_ready_low, "The punch's ready (sync) input is active low");
    cfg.add_flag("--punch-magnet-low", c.punch_magnet_low, "The punch magnets are driven by a low level");
    cfg.add_option("--punch-pulse", c.punch_pulse_us, "Microseconds the punch magnets are held")
        ->check(whole_number(100, 50000))
        ->capture_default_str();
    cfg.add_option("--sprocket-timeout", c.sprocket_timeout_ms,
                   "Milliseconds without a sprocket while driving before the tape counts as torn")
        ->check(whole_number(1, 65535))
        ->capture_default_str();
    cfg.add_option("--watchdog", c.watchdog_ms,
                   "Milliseconds the host may be silent before the adapter stops reader and punch (0: never)")
        ->check(whole_number(0, 65535))
        ->capture_default_str();
}

void add_config(CLI::App& sub, std::shared_ptr<std::string> device) {
    auto c = std::make_shared<tape::AdapterConfig>();
    auto strobe = std::make_shared<std::string>("rising");
    auto drive = std::make_shared<std::string>("level");
    auto* cfg = sub.add_subcommand(
        "config",
        "Send the adapter its unit's line settings (a CONFIG: every setting at once, defaults for those "
        "not given) and, when any emulate option is given, how it is wired to a control's reader input (a WIRING), "
        "and print them");
    cfg->add_option("device", *device, "Device string: adapter:/dev/ttyACM0")->required();
    add_line_options(*cfg, *c, *strobe, *drive);
    auto wiring = std::make_shared<WiringArgs>();
    add_wiring_options(*cfg, wiring);
    cfg->callback([device, c, strobe, drive, wiring, cfg] {
        c->strobe_falling = *strobe == "falling";
        c->drive_pulse = *drive == "pulse";
        finish_wiring(*cfg, *wiring, c->tracks);
        // Checked before anything is sent: a refused wiring leaves the line settings as they were.
        if (auto problem = tape::adapter_wiring_problem(wiring->wiring); wiring->given && !problem.empty())
            fail("", tape::Errc::usage, "the emulate wiring: " + problem);
        try {
            tape::adapter_configure(*device, *c);
            if (wiring->given) tape::adapter_configure_emulation(*device, wiring->wiring);
        } catch (const tape::Error& e) {
            fail("", e);
        }
        write_output("-", config_text(*c) + (wiring->given ? wiring_text(wiring->wiring) : ""), false, false);
    });
}

}  // namespace

void add_adapter(CLI::App& app) {
    auto* sub =
        app.add_subcommand("adapter", "Ask a USB tape adapter about itself, set its line settings, or test its link");
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
    add_config(*sub, device);
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
