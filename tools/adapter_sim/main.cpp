// tape-adapter-sim: the USB tape adapter's firmware core on the host, with a simulated ФС-1501-class
// reader and ПЛ-150-class punch backed by tape images, on a pseudo-terminal standing for its CDC
// port: the whole toolkit can be tried, and tested, without hardware. Faults can be injected.
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <thread>

#include "adapter_sim/fault_filter.hpp"
#include "adapter_sim/sim_hardware.hpp"
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/numbers.hpp"
#include "cli/run.hpp"
#include "cli/signals.hpp"
#include "core/engine.hpp"

namespace {

struct SimArgs {
    std::string reader, punch, serial = "SIM0001", link;
    double speed = 1, read_rate = 1500, punch_rate = 150;
    std::uint32_t stop_frames = 1;
    std::uint64_t unplug_after = 0, torn_at = 0, chad_full_after = 0;
    std::vector<std::uint64_t> miss_hole_at, no_sprocket_at, mistimed_at, marginal_at;
    unsigned active_low = 0;
    bool torn = false, no_reader = false, no_punch = false, no_reverse = false, at_end = false, loop = false,
         stats = false;
    tapesim::Faults faults;
};

[[noreturn]] void die(const std::string& what) {
    std::cerr << "tape-adapter-sim: " << what << "\n";
    throw cli::Exit{cli::io_failure};
}

int run(const SimArgs& a) {
    std::vector<std::uint8_t> tape;
    if (!a.reader.empty()) {
        auto in = cli::read_tape(a.reader, "");
        tape.assign(in.frames.begin(), in.frames.end());
    }
    std::FILE* punched_out = nullptr;
    if (!a.punch.empty()) {
        punched_out = std::fopen(a.punch.c_str(), "wb");
        if (!punched_out) die(a.punch + ": cannot create: " + std::strerror(errno));
    }

    int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0)
        die(std::string("no pseudo-terminal: ") + std::strerror(errno));
    std::string slave_path = ::ptsname(master);
    // Held open, so that a host closing the port (between runs) does not hang the line up.
    int slave = ::open(slave_path.c_str(), O_RDWR | O_NOCTTY);
    if (slave < 0) die(slave_path + ": " + std::strerror(errno));
    termios t{};
    ::tcgetattr(slave, &t);
    ::cfmakeraw(&t);
    ::tcsetattr(slave, TCSANOW, &t);
    ::fcntl(master, F_SETFL, O_NONBLOCK);
    if (!a.link.empty()) {
        ::unlink(a.link.c_str());
        if (::symlink(slave_path.c_str(), a.link.c_str()) != 0) die(a.link + ": " + std::strerror(errno));
    }

    tapesim::SimOptions so;
    so.read_rate = a.read_rate;
    so.punch_rate = a.punch_rate;
    so.stop_frames = a.stop_frames;
    if (a.torn) so.torn_at = a.torn_at;
    so.loop = a.loop;
    so.miss_hole_at = a.miss_hole_at;
    so.active_low = static_cast<std::uint8_t>(a.active_low);
    so.head_at_end = a.at_end;
    for (auto [frames, flag] :
         {std::pair{&a.no_sprocket_at, tapefw::row_flag::no_sprocket},
          std::pair{&a.mistimed_at, tapefw::row_flag::timing}, std::pair{&a.marginal_at, tapefw::row_flag::marginal}})
        for (auto n : *frames) so.row_flags.emplace_back(n - 1, flag);
    tapesim::SimHardware hw(tape, so);
    tapefw::Identity id;
    id.serial = a.serial.c_str();
    // The simulated board tells a row without a sprocket, a mistimed one and a marginal level apart.
    id.capabilities = static_cast<std::uint8_t>(
        (a.no_reader ? 0
                     : tapefw::caps::reader | tapefw::caps::row_flags | (a.no_reverse ? 0 : tapefw::caps::reverse)) |
        (a.no_punch ? 0 : tapefw::caps::punch));
    id.max_read_rate = static_cast<std::uint16_t>(std::lround(a.read_rate));
    id.max_punch_rate = static_cast<std::uint16_t>(std::lround(a.punch_rate));
    tapesim::FaultFilter filter(a.faults);
    std::string out;
    hw.on_send = [&](const std::uint8_t* b, std::size_t n) {
        if (out.size() > 65536) return false;  // the host is not reading: the endpoint is full
        filter.pass(b, n, out);
        return true;
    };
    // The watchdog counts simulated time: a faster clock would take the host's keep-alives for silence.
    tapefw::Config defaults;
    defaults.watchdog_ms = static_cast<std::uint16_t>(std::min(65535.0, defaults.watchdog_ms * std::max(1.0, a.speed)));
    tapefw::Engine engine(hw, id, tapefw::Framing::stream, defaults);

    std::cout << "adapter:" << slave_path << std::endl;
    auto t0 = std::chrono::steady_clock::now();
    auto virtual_now = [&] {
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() * a.speed;
        return static_cast<std::uint64_t>(s * 1e6);
    };
    // The engine polls between rows, as the firmware's main loop does: rows are given in small steps.
    const std::uint64_t step = static_cast<std::uint64_t>(16e6 / a.read_rate);
    std::size_t punched_written = 0;
    while (!cli::interrupted()) {
        std::uint64_t target = virtual_now();
        // The chad box fills at an exact row: looked at after each turn, which punches one row at most.
        auto chad = [&] {
            if (a.chad_full_after && hw.punched().size() >= a.chad_full_after)
                hw.forced_status |= tapefw::status::chad_full;
        };
        // Catching up after the process was not scheduled: the host's packets that came meanwhile are
        // taken step by step, as the board's USB interrupt would take them, so that the watchdog does
        // not count the simulator's own pause as the host's silence.
        auto take_input = [&] {
            std::uint8_t buf[4096];
            ssize_t n = ::read(master, buf, sizeof buf);
            if (n > 0) engine.receive(buf, static_cast<std::size_t>(n));
        };
        while (hw.now() < target) {
            take_input();
            hw.advance_to(std::min(target, hw.now() + step), engine);
            engine.poll();
            hw.after_poll();
            chad();
        }
        engine.poll();
        hw.after_poll();
        chad();
        if (punched_out && hw.punched().size() > punched_written) {
            std::fwrite(hw.punched().data() + punched_written, 1, hw.punched().size() - punched_written, punched_out);
            std::fflush(punched_out);
            punched_written = hw.punched().size();
        }
        if (a.unplug_after && engine.rows_read() >= a.unplug_after) {
            std::cerr << "tape-adapter-sim: unplugged after " << engine.rows_read() << " frames\n";
            break;
        }
        while (!out.empty()) {
            ssize_t n = ::write(master, out.data(), out.size());
            if (n <= 0) break;
            out.erase(0, static_cast<std::size_t>(n));
        }
        std::uint64_t next = hw.next_event();
        std::uint64_t now = virtual_now();
        int wait_ms = next > now ? static_cast<int>(std::min<double>(5, (next - now) / 1000.0 / a.speed)) : 0;
        pollfd p{master, static_cast<short>(POLLIN | (out.empty() ? 0 : POLLOUT)), 0};
        if (::poll(&p, 1, wait_ms) > 0 && (p.revents & POLLIN)) {
            std::uint8_t buf[4096];
            ssize_t n = ::read(master, buf, sizeof buf);
            if (n > 0) engine.receive(buf, static_cast<std::size_t>(n));
        }
    }
    if (punched_out) std::fclose(punched_out);
    ::close(master);
    ::close(slave);
    if (!a.link.empty()) ::unlink(a.link.c_str());
    if (filter.dropped() || filter.corrupted())
        std::cerr << "tape-adapter-sim: " << filter.dropped() << " packet(s) dropped, " << filter.corrupted()
                  << " damaged, of " << filter.rows_packets() << " ROWS packets\n";
    if (a.stats) {
        // One line of name=value pairs, for the tests and benchmarks to read what the adapter saw.
        const tapefw::Config& c = hw.config();
        char line[512];
        std::snprintf(
            line, sizeof line,
            "tape-adapter-sim: stats: tape_position=%llu rows_punched=%llu underruns=%llu late_punches=%llu "
            "longest_punch_gap_us=%llu desyncs=%llu bad_packets_in=%llu config: invert=0x%02X lines=0x%02X "
            "tracks=%u sample_delay_us=%u punch_pulse_us=%u drive_pulse_us=%u sprocket_timeout_ms=%u "
            "watchdog_ms=%u\n",
            static_cast<unsigned long long>(hw.position()), static_cast<unsigned long long>(hw.punched().size()),
            static_cast<unsigned long long>(hw.underruns()), static_cast<unsigned long long>(hw.late_punches()),
            static_cast<unsigned long long>(hw.longest_punch_gap_us()),
            static_cast<unsigned long long>(filter.desyncs()), static_cast<unsigned long long>(engine.bad_packets()),
            c.data_invert, c.lines, c.tracks, c.sample_delay_us, c.punch_pulse_us, c.drive_pulse_us,
            c.sprocket_timeout_ms, c.watchdog_ms);
        std::cerr << line;
    }
    return cli::ok;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "tape-adapter-sim: a USB tape adapter with a ФС-1501-class reader and a ПЛ-150-class punch, simulated on a "
        "pseudo-terminal.\nPrints the device string (adapter:/dev/pts/N) on stdout, then runs until Ctrl-C.",
        "tape-adapter-sim"};
    app.set_version_flag("--version", std::string("tape-adapter-sim ") + TAPE_VERSION);
    app.footer("See tape-usb(7) and docs/adapter-protocol.md.");
    cli::globals().program = "tape-adapter-sim";
    SimArgs a;
    using cli::real_number;
    using cli::whole_number;
    constexpr std::uint64_t most = 1'000'000'000;
    app.add_option("--reader", a.reader, "Tape image in the reader (any format); without it the reader has no tape");
    app.add_option("--punch", a.punch, "Raw image file the punch punches into (rows appended as punched)");
    app.add_option("--serial", a.serial, "The adapter's serial string")->capture_default_str();
    app.add_option("--link", a.link, "Also make a symbolic link PATH to the pseudo-terminal");
    app.add_option("--speed", a.speed, "Run the simulated clock this many times faster than real time")
        ->check(real_number(0.01, 1000))
        ->capture_default_str();
    app.add_option("--read-rate", a.read_rate, "Frames per second the reader reads")
        ->check(real_number(1, 60000))
        ->capture_default_str();
    app.add_option("--punch-rate", a.punch_rate, "Rows per second the punch punches")
        ->check(real_number(1, 60000))
        ->capture_default_str();
    app.add_option("--stop-frames", a.stop_frames, "Frames that pass the head while the reader brakes")
        ->check(whole_number(0, 100))
        ->capture_default_str();
    app.add_flag(
           "--loop", a.loop,
           "The punched tape goes on into the reader, which reads it back (tape punch --verify); not with --reader")
        ->excludes("--reader");
    app.add_flag("--no-reader", a.no_reader, "An adapter with a punch only");
    app.add_flag("--no-punch", a.no_punch, "An adapter with a reader only");
    app.add_flag("--no-reverse", a.no_reverse, "A reader that cannot read backwards");
    app.add_flag("--at-end", a.at_end,
                 "The tape is loaded with its end at the head, as after reading it through: read it back with "
                 "direction=reverse");
    app.add_option("--no-sprocket-at", a.no_sprocket_at,
                   "Frame N (from 1) is read without its sprocket hole, sampled by time, and flagged so "
                   "(repeatable)")
        ->check(whole_number(1, most));
    app.add_option("--mistimed-at", a.mistimed_at,
                   "Frame N's sprocket hole comes early or late, and the row is flagged so (repeatable)")
        ->check(whole_number(1, most));
    app.add_option("--marginal-at", a.marginal_at,
                   "A track of frame N reads near its threshold, and the row is flagged so (repeatable)")
        ->check(whole_number(1, most));
    app.add_option("--unplug-after", a.unplug_after, "Unplug (hang the line up and end) after N frames read")
        ->check(whole_number(1, most));
    app.add_option("--torn-at", a.torn_at, "The tape is torn after N frames: no sprocket hole from there")
        ->check(whole_number(0, most))
        ->each([&a](const std::string&) { a.torn = true; });
    app.add_option("--chad-full-after", a.chad_full_after, "The chad box is full after N rows punched")
        ->check(whole_number(1, most));
    app.add_option("--miss-hole-at", a.miss_hole_at,
                   "Row N (from 1) is punched with its lowest hole missing (repeatable: several rows)")
        ->check(whole_number(1, most));
    app.add_option("--active-low", a.active_low,
                   "The unit's data lines that are low for a hole (a mask, bit n for track n+1): tape adapter "
                   "config --invert must say the same for true rows")
        ->check(whole_number(0, 255));
    app.add_option("--garbage-every", a.faults.garbage_every,
                   "Before every K-th ROWS packet, a desync on the line: noise, or half a packet, in turn")
        ->check(whole_number(1, most));
    app.add_flag(
        "--stats", a.stats,
        "At the end, print on stderr the tape's position, rows punched, punch underruns and late cycles, desyncs "
        "injected, bad packets from the host and the line settings in force");
    app.add_option("--drop-packet", a.faults.drop_rows_packet, "Do not send the K-th ROWS packet (from 1)")
        ->check(whole_number(1, most));
    app.add_option("--drop-times", a.faults.drop_times,
                   "...nor its resends: N sendings dropped in all (a large N: frames lost for good)")
        ->check(whole_number(1, most))
        ->capture_default_str();
    app.add_option("--duplicate-packet", a.faults.duplicate_rows_packet, "Send the K-th ROWS packet twice")
        ->check(whole_number(1, most));
    app.add_option("--corrupt-packet", a.faults.corrupt_rows_packet,
                   "Damage a byte of the K-th ROWS packet (the host sees a CRC failure)")
        ->check(whole_number(1, most));
    app.add_option("--corrupt-times", a.faults.corrupt_times, "...and of its resends: N sendings damaged in all")
        ->check(whole_number(1, most))
        ->capture_default_str();
    app.add_option("--protocol", a.faults.protocol, "Claim this protocol version in INFO (to try a mismatch)")
        ->check(whole_number(0, 255));
    app.callback([&a] { throw cli::Exit{run(a)}; });
    cli::install_interrupt_handler();
    return cli::parse_and_run(app, argc, argv);
}
