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
    std::string reader, punch, serial = "SIM0001", link, control;
    double speed = 1, read_rate = 1500, punch_rate = 150;
    std::uint32_t stop_frames = 1;
    double control_rate = 1500;
    std::uint64_t control_stops = 0, control_rewind_after = 0, control_reverse_after = 0, control_reverse_frames = 10;
    std::uint32_t control_seed = 1;
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

std::vector<std::uint8_t> reader_tape(const SimArgs& a) {
    if (a.reader.empty()) return {};
    auto in = cli::read_tape(a.reader, "");
    return {in.frames.begin(), in.frames.end()};
}

// The adapter's CDC port: a pseudo-terminal in raw mode, its far end held open so that a host closing
// the port (between runs) does not hang the line up, and optionally a symbolic link to it.
class Port {
public:
    explicit Port(const std::string& link) : link_(link) {
        master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0)
            die(std::string("no pseudo-terminal: ") + std::strerror(errno));
        path_ = ::ptsname(master_);
        slave_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY);
        if (slave_ < 0) die(path_ + ": " + std::strerror(errno));
        termios t{};
        ::tcgetattr(slave_, &t);
        ::cfmakeraw(&t);
        ::tcsetattr(slave_, TCSANOW, &t);
        ::fcntl(master_, F_SETFL, O_NONBLOCK);
        if (!link_.empty()) {
            ::unlink(link_.c_str());
            if (::symlink(path_.c_str(), link_.c_str()) != 0) die(link_ + ": " + std::strerror(errno));
        }
    }
    ~Port() {
        ::close(master_);
        ::close(slave_);
        if (!link_.empty()) ::unlink(link_.c_str());
    }
    Port(const Port&) = delete;
    Port& operator=(const Port&) = delete;

    const std::string& path() const { return path_; }
    int fd() const { return master_; }

private:
    std::string link_, path_;
    int master_ = -1, slave_ = -1;
};

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
    if (!a.control.empty())
        so.control = tapesim::ControlOptions{.rate = a.control_rate,
                                             .stops = a.control_stops,
                                             .seed = a.control_seed,
                                             .rewind_after = a.control_rewind_after,
                                             .reverse_after = a.control_reverse_after,
                                             .reverse_frames = a.control_reverse_frames};
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
        (a.no_punch ? 0 : tapefw::caps::punch) | (a.control.empty() ? 0 : tapefw::caps::emulate));
    id.max_read_rate = static_cast<std::uint16_t>(std::lround(a.read_rate));
    id.max_punch_rate = static_cast<std::uint16_t>(std::lround(a.punch_rate));
    return id;
}

// The watchdog counts simulated time: a faster clock would take the host's keep-alives for silence.
tapefw::Config line_defaults(const SimArgs& a) {
    tapefw::Config defaults;
    defaults.watchdog_ms = static_cast<std::uint16_t>(std::min(65535.0, defaults.watchdog_ms * std::max(1.0, a.speed)));
    return defaults;
}

// The board: the firmware core driving the simulated reader and punch, its packets to the host passing
// the fault filter, on a clock `speed` times real time.
class Board {
public:
    Board(const SimArgs& a, const std::vector<std::uint8_t>& tape)
        : a_(a),
          hw_(tape, sim_options(a)),
          id_(identity(a)),
          filter_(a.faults),
          engine_(hw_, id_, tapefw::Framing::stream, line_defaults(a)) {
        hw_.on_send = [this](const std::uint8_t* b, std::size_t n) {
            if (out_.size() > 65536) return false;  // the host is not reading: the endpoint is full
            filter_.pass(b, n, out_);
            return true;
        };
    }

    /// Runs the board on the port until Ctrl-C or the unplug asked for.
    void run(const Port& port, std::FILE* punched_out, std::FILE* control_out) {
        fd_ = port.fd();
        t0_ = std::chrono::steady_clock::now();
        while (!cli::interrupted()) {
            catch_up();
            if (punched_out) write_punched(punched_out);
            if (control_out) write_taken(control_out);
            std::uint64_t frames = std::max<std::uint64_t>(engine_.rows_read(), engine_.frames_taken());
            if (a_.unplug_after && frames >= a_.unplug_after) {
                std::cerr << "tape-adapter-sim: unplugged after " << frames << " frames\n";
                return;
            }
            send_to_host();
            wait_for_host();
        }
    }

    void print_faults() const {
        if (filter_.dropped() || filter_.corrupted())
            std::cerr << "tape-adapter-sim: " << filter_.dropped() << " packet(s) dropped, " << filter_.corrupted()
                      << " damaged, of " << filter_.rows_packets() << " ROWS packets\n";
    }

    // One line of name=value pairs, for the tests and benchmarks to read what the adapter saw.
    void print_stats() const {
        const tapefw::Config& c = hw_.config();
        char line[512];
        std::snprintf(
            line, sizeof line,
            "tape-adapter-sim: stats: tape_position=%llu rows_punched=%llu underruns=%llu late_punches=%llu "
            "longest_punch_gap_us=%llu desyncs=%llu bad_packets_in=%llu config: invert=0x%02X lines=0x%02X "
            "tracks=%u sample_delay_us=%u punch_pulse_us=%u drive_pulse_us=%u sprocket_timeout_ms=%u "
            "watchdog_ms=%u\n",
            static_cast<unsigned long long>(hw_.position()), static_cast<unsigned long long>(hw_.punched().size()),
            static_cast<unsigned long long>(hw_.underruns()), static_cast<unsigned long long>(hw_.late_punches()),
            static_cast<unsigned long long>(hw_.longest_punch_gap_us()),
            static_cast<unsigned long long>(filter_.desyncs()), static_cast<unsigned long long>(engine_.bad_packets()),
            c.data_invert, c.lines, c.tracks, c.sample_delay_us, c.punch_pulse_us, c.drive_pulse_us,
            c.sprocket_timeout_ms, c.watchdog_ms);
        std::cerr << line;
        // The control's findings, one JSON line of their own.
        if (hw_.control()) std::cerr << hw_.control()->stats_json() << "\n";
    }

private:
    const SimArgs& a_;
    int fd_ = -1;  ///< the port's
    tapesim::SimHardware hw_;
    tapefw::Identity id_;
    tapesim::FaultFilter filter_;
    tapefw::Engine engine_;
    std::string out_;  ///< bytes for the host the port has not taken yet
    std::size_t punched_written_ = 0, taken_written_ = 0;
    std::chrono::steady_clock::time_point t0_{};  ///< when the simulated clock started

    std::uint64_t virtual_now() const {
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count() * a_.speed;
        return static_cast<std::uint64_t>(s * 1e6);
    }

    void take_input() {
        std::uint8_t buf[4096];
        ssize_t n = ::read(fd_, buf, sizeof buf);
        if (n > 0) engine_.receive(buf, static_cast<std::size_t>(n));
    }

    // The chad box fills at an exact row: looked at after each turn, which punches one row at most.
    void turn() {
        engine_.poll();
        hw_.after_poll();
        if (a_.chad_full_after && hw_.punched().size() >= a_.chad_full_after)
            hw_.forced_status |= tapefw::status::chad_full;
    }

    // The simulated clock brought up to real time. The engine polls between rows, as the firmware's main
    // loop does: rows are given in small steps. After the process was not scheduled, the host's packets
    // that came meanwhile are taken step by step, as the board's USB interrupt would take them, so that
    // the watchdog does not count the simulator's own pause as the host's silence.
    void catch_up() {
        const std::uint64_t step = static_cast<std::uint64_t>(16e6 / a_.read_rate);
        std::uint64_t target = virtual_now();
        while (hw_.now() < target) {
            take_input();
            hw_.advance_to(std::min(target, hw_.now() + step), engine_);
            turn();
        }
        turn();
    }

    void write_punched(std::FILE* to) {
        if (hw_.punched().size() <= punched_written_) return;
        std::fwrite(hw_.punched().data() + punched_written_, 1, hw_.punched().size() - punched_written_, to);
        std::fflush(to);
        punched_written_ = hw_.punched().size();
    }

    void write_taken(std::FILE* to) {
        const auto& taken = hw_.control()->taken();
        if (taken.size() <= taken_written_) return;
        std::fwrite(taken.data() + taken_written_, 1, taken.size() - taken_written_, to);
        std::fflush(to);
        taken_written_ = taken.size();
    }

    void send_to_host() {
        while (!out_.empty()) {
            ssize_t n = ::write(fd_, out_.data(), out_.size());
            if (n <= 0) break;
            out_.erase(0, static_cast<std::size_t>(n));
        }
    }

    // Until the next simulated event, 5 ms at most, or the host's next packet.
    void wait_for_host() {
        std::uint64_t next = hw_.next_event();
        std::uint64_t now = virtual_now();
        int wait_ms = next > now ? static_cast<int>(std::min<double>(5, (next - now) / 1000.0 / a_.speed)) : 0;
        pollfd p{fd_, static_cast<short>(POLLIN | (out_.empty() ? 0 : POLLOUT)), 0};
        if (::poll(&p, 1, wait_ms) > 0 && (p.revents & POLLIN)) take_input();
    }
};

// An output file of the run: standard output is taken by the device string, and no two outputs (or an
// output and the reader's tape) may be one file.
std::FILE* create(const std::string& path, const std::string& option) {
    if (path.empty()) return nullptr;
    if (path == "-")
        cli::fail(option + " -", tape::Errc::usage, "standard output carries the device string: give a file");
    cli::claim_output(path);
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) die(path + ": cannot create: " + std::strerror(errno));
    return f;
}

int run(const SimArgs& a) {
    const std::vector<std::uint8_t> tape = reader_tape(a);
    std::FILE* punched_out = create(a.punch, "--punch");
    std::FILE* control_out = create(a.control, "--control");
    Board board(a, tape);
    {
        Port port(a.link);
        std::cout << "adapter:" << port.path() << std::endl;
        board.run(port, punched_out, control_out);
    }
    for (auto* f : {punched_out, control_out})
        if (f) std::fclose(f);
    board.print_faults();
    if (a.stats) board.print_stats();
    return cli::ok;
}

// The adapter as built: what it holds, its line and its clock.
void add_unit_options(CLI::App& app, SimArgs& a) {
    using cli::real_number;
    using cli::whole_number;
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
    app.add_option("--control", a.control,
                   "A control reads through the adapter standing in for its tape reader (tape emulate); every "
                   "frame it takes is appended to this raw image file");
    app.add_option("--control-rate", a.control_rate,
                   "Frames per second the control can take; slower than the reader's rate, it stops the reader "
                   "after each frame")
        ->check(real_number(1, 60000))
        ->capture_default_str();
    app.add_option("--control-stops", a.control_stops,
                   "The control stops the reader N times at random frames (1 to 2000 frames apart) and starts it "
                   "again after a random 2 to 30 ms")
        ->check(whole_number(0, 1'000'000'000));
    app.add_option("--control-seed", a.control_seed, "Seed of the control's random stops")
        ->check(whole_number(0, 4'294'967'295))
        ->capture_default_str();
    app.add_option("--control-rewind-after", a.control_rewind_after,
                   "Once, after taking N frames, the control stops, rewinds (its rewind line on and off) and starts "
                   "again")
        ->check(whole_number(1, 1'000'000'000));
    app.add_option("--control-reverse-after", a.control_reverse_after,
                   "Once, after taking N frames, the control reads backwards for --control-reverse-frames frames, "
                   "then forwards again")
        ->check(whole_number(1, 1'000'000'000));
    app.add_option("--control-reverse-frames", a.control_reverse_frames, "Frames the control reads backwards")
        ->check(whole_number(1, 1'000'000'000))
        ->capture_default_str();
    app.add_flag("--no-reader", a.no_reader, "An adapter with a punch only");
    app.add_flag("--no-punch", a.no_punch, "An adapter with a reader only");
    app.add_flag("--no-reverse", a.no_reverse, "A reader that cannot read backwards");
    app.add_flag("--at-end", a.at_end,
                 "The tape is loaded with its end at the head, as after reading it through: read it back with "
                 "direction=reverse");
}

// Faults of the tape, the units and the line, each at a frame or packet named.
void add_fault_options(CLI::App& app, SimArgs& a) {
    using cli::whole_number;
    constexpr std::uint64_t most = 1'000'000'000;
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
    app.add_option("--unplug-after", a.unplug_after,
                   "Unplug (hang the line up and end) after N frames read, or taken by the control")
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
        "injected, bad packets from the host and the line settings in force; with --control, then a JSON line: "
        "frames taken, frames_after_stop (for each stop), longest_gap_us, longest_restart_us, restarts");
    app.add_option("--drop-taken-every", a.faults.drop_taken_every,
                   "Lose every K-th TAKEN packet on the way to the host (emulating)")
        ->check(whole_number(1, most));
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
    add_unit_options(app, a);
    add_fault_options(app, a);
    app.callback([&a] { throw cli::Exit{run(a)}; });
    cli::install_interrupt_handler();
    return cli::parse_and_run(app, argc, argv);
}
