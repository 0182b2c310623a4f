#include "adapter_sim/board.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "cli/signals.hpp"

namespace tapesim {
namespace {

SimOptions sim_options(const SimArgs& a) {
    SimOptions so;
    so.read_rate = a.read_rate;
    so.punch_rate = a.punch_rate;
    so.stop_frames = a.stop_frames;
    if (a.torn) so.torn_at = a.torn_at;
    so.loop = a.loop;
    so.miss_hole_at = a.miss_hole_at;
    so.active_low = static_cast<std::uint8_t>(a.active_low);
    so.head_at_end = a.at_end;
    if (!a.control.empty())
        so.control = ControlOptions{.rate = a.control_rate,
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

}  // namespace

Board::Board(const SimArgs& a, const std::vector<std::uint8_t>& tape)
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

void Board::run(const Port& port, std::FILE* punched_out, std::FILE* control_out) {
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

void Board::print_faults() const {
    if (filter_.dropped() || filter_.corrupted())
        std::cerr << "tape-adapter-sim: " << filter_.dropped() << " packet(s) dropped, " << filter_.corrupted()
                  << " damaged, of " << filter_.rows_packets() << " ROWS packets\n";
}

void Board::print_stats() const {
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
        static_cast<unsigned long long>(hw_.longest_punch_gap_us()), static_cast<unsigned long long>(filter_.desyncs()),
        static_cast<unsigned long long>(engine_.bad_packets()), c.data_invert, c.lines, c.tracks, c.sample_delay_us,
        c.punch_pulse_us, c.drive_pulse_us, c.sprocket_timeout_ms, c.watchdog_ms);
    std::cerr << line;
    // The control's findings, one JSON line of their own.
    if (hw_.control()) std::cerr << hw_.control()->stats_json() << "\n";
}

std::uint64_t Board::virtual_now() const {
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count() * a_.speed;
    return static_cast<std::uint64_t>(s * 1e6);
}

void Board::take_input() {
    std::uint8_t buf[4096];
    ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n > 0) engine_.receive(buf, static_cast<std::size_t>(n));
}

// The chad box fills at an exact row: looked at after each turn, which punches one row at most.
void Board::turn() {
    engine_.poll();
    hw_.after_poll();
    if (a_.chad_full_after && hw_.punched().size() >= a_.chad_full_after)
        hw_.forced_status |= tapefw::status::chad_full;
}

// The simulated clock brought up to real time. The engine polls between rows, as the firmware's main
// loop does: rows are given in small steps. After the process was not scheduled, the host's packets
// that came meanwhile are taken step by step, as the board's USB interrupt would take them, so that
// the watchdog does not count the simulator's own pause as the host's silence.
void Board::catch_up() {
    const std::uint64_t step = static_cast<std::uint64_t>(16e6 / a_.read_rate);
    std::uint64_t target = virtual_now();
    while (hw_.now() < target) {
        take_input();
        hw_.advance_to(std::min(target, hw_.now() + step), engine_);
        turn();
    }
    turn();
}

void Board::write_punched(std::FILE* to) {
    if (hw_.punched().size() <= punched_written_) return;
    std::fwrite(hw_.punched().data() + punched_written_, 1, hw_.punched().size() - punched_written_, to);
    std::fflush(to);
    punched_written_ = hw_.punched().size();
}

void Board::write_taken(std::FILE* to) {
    const auto& taken = hw_.control()->taken();
    if (taken.size() <= taken_written_) return;
    std::fwrite(taken.data() + taken_written_, 1, taken.size() - taken_written_, to);
    std::fflush(to);
    taken_written_ = taken.size();
}

void Board::send_to_host() {
    while (!out_.empty()) {
        ssize_t n = ::write(fd_, out_.data(), out_.size());
        if (n <= 0) break;
        out_.erase(0, static_cast<std::size_t>(n));
    }
}

// Until the next simulated event, 5 ms at most, or the host's next packet.
void Board::wait_for_host() {
    std::uint64_t next = hw_.next_event();
    std::uint64_t now = virtual_now();
    int wait_ms = next > now ? static_cast<int>(std::min<double>(5, (next - now) / 1000.0 / a_.speed)) : 0;
    pollfd p{fd_, static_cast<short>(POLLIN | (out_.empty() ? 0 : POLLOUT)), 0};
    if (::poll(&p, 1, wait_ms) > 0 && (p.revents & POLLIN)) take_input();
}

}  // namespace tapesim
