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
#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
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

// The pseudo-terminal standing for the adapter's CDC port: its master is the adapter's side.
struct Port {
    int master = -1, slave = -1;
    std::string path;
};

Port open_port(const std::string& link) {
    Port port;
    port.master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (port.master < 0 || ::grantpt(port.master) != 0 || ::unlockpt(port.master) != 0)
        die(std::string("no pseudo-terminal: ") + std::strerror(errno));
    port.path = ::ptsname(port.master);
    // Held open, so that a host closing the port (between runs) does not hang the line up.
    port.slave = ::open(port.path.c_str(), O_RDWR | O_NOCTTY);
    if (port.slave < 0) die(port.path + ": " + std::strerror(errno));
    termios t{};
    ::tcgetattr(port.slave, &t);
    ::cfmakeraw(&t);
    ::tcsetattr(port.slave, TCSANOW, &t);
    ::fcntl(port.master, F_SETFL, O_NONBLOCK);
    if (!link.empty()) {
        ::unlink(link.c_str());
        if (::symlink(port.path.c_str(), link.c_str()) != 0) die(link + ": " + std::strerror(errno));
    }
    return port;
}

tapesim::SimOptions sim_options(const SimArgs& a) {
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
    return so;
}

tapefw::Identity identity(const SimArgs& a) {
    tapefw::Identity id;
    id.serial = a.serial.c_str();
    // The simulated board tells a row without a sprocket, a mistimed one and a marginal level apart.
    id.capabilities = static_cast<std::uint8_t>(
        (a.no_reader ? 0
                     : tapefw::caps::reader | tapefw::caps::row_flags | (a.no_reverse ? 0 : tapefw::caps::reverse)) |
        (a.no_punch ? 0 : tapefw::caps::punch));
    id.max_read_rate = static_cast<std::uint16_t>(std::lround(a.read_rate));
    id.max_punch_rate = static_cast<std::uint16_t>(std::lround(a.punch_rate));
    return id;
}

// One line of name=value pairs, for the tests and benchmarks to read what the adapter saw.
void print_stats(const tapesim::SimHardware& hw, const tapesim::FaultFilter& filter, const tapefw::Engine& engine) {
    const tapefw::Config& c = hw.config();
    char line[512];
    std::snprintf(line, sizeof line,
                  "tape-adapter-sim: stats: tape_position=%llu rows_punched=%llu underruns=%llu late_punches=%llu "
                  "longest_punch_gap_us=%llu desyncs=%llu bad_packets_in=%llu config: invert=0x%02X lines=0x%02X "
                  "tracks=%u sample_delay_us=%u punch_pulse_us=%u drive_pulse_us=%u sprocket_timeout_ms=%u "
                  "watchdog_ms=%u\n",
                  static_cast<unsigned long long>(hw.position()), static_cast<unsigned long long>(hw.punched().size()),
                  static_cast<unsigned long long>(hw.underruns()), static_cast<unsigned long long>(hw.late_punches()),
                  static_cast<unsigned long long>(hw.longest_punch_gap_us()),
                  static_cast<unsigned long long>(filter.desyncs()),
                  static_cast<unsigned long long>(engine.bad_packets()), c.data_invert, c.lines, c.tracks,
                  c.sample_delay_us, c.punch_pulse_us, c.drive_pulse_us, c.sprocket_timeout_ms, c.watchdog_ms);
    std::cerr << line;
}

// The adapter running: its engine and simulated hardware on the port, in simulated time.
class Simulation {
public:
    Simulation(const SimArgs& a, std::vector<std::uint8_t> tape, Port port, std::FILE* punched_out)
        : a_(a),
          port_(std::move(port)),
          punched_out_(punched_out),
          hw_(tape, sim_options(a)),
          id_(identity(a)),
          filter_(a.faults),
          engine_(hw_, id_, tapefw::Framing::stream, scaled_defaults(a)),
          step_(static_cast<std::uint64_t>(16e6 / a.read_rate)) {
        hw_.on_send = [this](const std::uint8_t* b, std::size_t n) {
            if (out_.size() > 65536) return false;  // the host is not reading: the endpoint is full
            filter_.pass(b, n, out_);
            return true;
        };
    }

    void run() {
        std::cout << "adapter:" << port_.path << std::endl;
        t0_ = std::chrono::steady_clock::now();
        while (!cli::interrupted()) {
            catch_up();
            save_punched();
            if (a_.unplug_after && engine_.rows_read() >= a_.unplug_after) {
                std::cerr << "tape-adapter-sim: unplugged after " << engine_.rows_read() << " frames\n";
                break;
            }
            send_out();
            wait_for_host();
        }
    }

    void finish() {
        if (punched_out_) std::fclose(punched_out_);
        ::close(port_.master);
        ::close(port_.slave);
        if (!a_.link.empty()) ::unlink(a_.link.c_str());
        if (filter_.dropped() || filter_.corrupted())
            std::cerr << "tape-adapter-sim: " << filter_.dropped() << " packet(s) dropped, " << filter_.corrupted()
                      << " damaged, of " << filter_.rows_packets() << " ROWS packets\n";
        if (a_.stats) print_stats(hw_, filter_, engine_);
    }

private:
    // The watchdog counts simulated time: a faster clock would take the host's keep-alives for silence.
    static tapefw::Config scaled_defaults(const SimArgs& a) {
        tapefw::Config defaults;
        defaults.watchdog_ms =
            static_cast<std::uint16_t>(std::min(65535.0, defaults.watchdog_ms * std::max(1.0, a.speed)));
        return defaults;
    }
    std::uint64_t virtual_now() const {
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count() * a_.speed;
        return static_cast<std::uint64_t>(s * 1e6);
    }
    void take_input() {
        std::uint8_t buf[4096];
        ssize_t n = ::read(port_.master, buf, sizeof buf);
        if (n > 0) engine_.receive(buf, static_cast<std::size_t>(n));
    }
    // The engine's turn, then the chad box, which fills at an exact row: looked at after each turn, which
    // punches one row at most.
    void turn() {
        engine_.poll();
        hw_.after_poll();
        if (a_.chad_full_after && hw_.punched().size() >= a_.chad_full_after)
            hw_.forced_status |= tapefw::status::chad_full;
    }
    // The engine polls between rows, as the firmware's main loop does: rows are given in small steps.
    // Catching up after the process was not scheduled, the host's packets that came meanwhile are taken
    // step by step, as the board's USB interrupt would take them, so that the watchdog does not count the
    // simulator's own pause as the host's silence.
    void catch_up() {
        std::uint64_t target = virtual_now();
        while (hw_.now() < target) {
            take_input();
            hw_.advance_to(std::min(target, hw_.now() + step_), engine_);
            turn();
        }
        turn();
    }
    void save_punched() {
        if (!punched_out_ || hw_.punched().size() <= punched_written_) return;
        std::fwrite(hw_.punched().data() + punched_written_, 1, hw_.punched().size() - punched_written_, punched_out_);
        std::fflush(punched_out_);
        punched_written_ = hw_.punched().size();
    }
    void send_out() {
        while (!out_.empty()) {
            ssize_t n = ::write(port_.master, out_.data(), out_.size());
            if (n <= 0) break;
            out_.erase(0, static_cast<std::size_t>(n));
        }
    }
    void wait_for_host() {
        std::uint64_t next = hw_.next_event(), now = virtual_now();
        int wait_ms = next > now ? static_cast<int>(std::min<double>(5, (next - now) / 1000.0 / a_.speed)) : 0;
        pollfd p{port_.master, static_cast<short>(POLLIN | (out_.empty() ? 0 : POLLOUT)), 0};
        if (::poll(&p, 1, wait_ms) > 0 && (p.revents & POLLIN)) take_input();
    }

    const SimArgs& a_;
    Port port_;
    std::FILE* punched_out_;
    tapesim::SimHardware hw_;
    tapefw::Identity id_;
    tapesim::FaultFilter filter_;
    tapefw::Engine engine_;
    std::string out_;
    std::uint64_t step_;
    std::size_t punched_written_ = 0;
    std::chrono::steady_clock::time_point t0_;
};

int run(const SimArgs& a) {
    std::vector<std::uint8_t> tape;
    if (!a.reader.empty()) {
        auto in = cli::read_tape(a.reader, "");
        tape.assign(in.frames.begin(), in.frames.end());
    }
    std::FILE* punched_out = nullptr;
    if (!a.punch.empty()) {
        if (a.punch == "-")
            cli::fail("--punch -", tape::Errc::usage, "standard output carries the device string: give a file");
        cli::claim_output(a.punch);
        punched_out = std::fopen(a.punch.c_str(), "wb");
        if (!punched_out) die(a.punch + ": cannot create: " + std::strerror(errno));
    }
    Simulation sim(a, std::move(tape), open_port(a.link), punched_out);
    sim.run();
    sim.finish();
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
