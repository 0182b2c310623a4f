// A machine's thread: the line opened (again after a hang-up or an unplug), punch-outs received as
// they arrive and filed, requests answered (machine_send.cpp).
#include "machine.hpp"

#include <cstdio>

#include "punch_out.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"

namespace tape::dnc {
namespace {

using namespace std::chrono_literals;

// Between reads while a punch-out comes: one read then takes what 40 ms brought (38 characters at
// 9600 baud), instead of waking for every character.
constexpr auto gather = 40ms;
constexpr auto reopen_after = 2s;
// How long the LF after a closing '%' may take: a character at 300 baud, and a read's gathering.
constexpr auto line_end_wait = 60ms;

std::string seconds_text(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", s);
    return text;
}

const char* cut_reason(ReceiveResult::End end, bool flood) {
    if (flood) return "longer than max_punch_out: a flood";
    switch (end) {
        case ReceiveResult::End::idle:
            return "no frame for receive_timeout before the program's end";
        case ReceiveResult::End::hangup:
            return "the other side hung up";
        case ReceiveResult::End::stopped:
            return "the service stopped";
        default:
            return "cut";
    }
}

}  // namespace

Machine::Machine(MachineSettings settings, std::shared_ptr<Shared> shared)
    : s_(std::move(settings)), shared_(std::move(shared)) {
    status_.name = s_.name;
    status_.device = s_.device;
}

Machine::~Machine() {
    if (thread_.joinable()) thread_.join();
}

void Machine::start() {
    thread_ = std::thread([this] { run(); });
}

void Machine::abandon() {
    if (thread_.joinable()) thread_.detach();
}

MachineStatus Machine::status() const {
    std::lock_guard lock(status_mutex_);
    return status_;
}

void Machine::set_state(LineState state, const std::string& program, std::uint64_t total) {
    std::lock_guard lock(status_mutex_);
    status_.state = state;
    status_.program = program;
    status_.frames = 0;
    status_.total = total;
}

void Machine::set_frames(std::uint64_t frames) {
    std::lock_guard lock(status_mutex_);
    status_.frames = frames;
}

void Machine::count(std::uint64_t MachineStatus::*counter, const std::string& line) {
    std::lock_guard lock(status_mutex_);
    ++(status_.*counter);
    status_.last = line;
}

double Machine::since(Clock::time_point start) const {
    return std::chrono::duration<double>(shared_->clock->now() - start).count();
}

void Machine::pause(std::chrono::milliseconds how_long) {
    auto end = shared_->clock->now() + how_long;
    while (!stop_ && shared_->clock->now() < end) shared_->clock->sleep_until(shared_->clock->now() + 50ms);
}

void Machine::run() {
    bool said_gone = false;
    while (!stop_) {
        set_state(LineState::opening);
        std::unique_ptr<Transport> line;
        try {
            line = open_device(s_.device, DeviceUse::both);
        } catch (const Error& e) {
            if (!said_gone) log(Priority::err, std::string(e.what()) + " (trying again every 2 s)");
            said_gone = true;
            set_state(LineState::waiting);
            pause(reopen_after);
            continue;
        }
        if (said_gone) log(Priority::notice, "the line is open again");
        said_gone = false;
        try {
            serve(*line);
        } catch (const Error& e) {
            log(Priority::warning, e.what());
        }
        line.reset();
        if (!stop_) {
            set_state(LineState::waiting);
            pause(reopen_after);
        }
    }
    set_state(LineState::stopped);
    finished_ = true;
}

void Machine::serve(Transport& line) {
    while (!stop_)
        if (!listen(line)) return;
}

// Receives one punch-out (beginning with what is pending from the last), or waits receive_timeout for
// one. False when the line hung up.
bool Machine::listen(Transport& line) {
    set_state(LineState::listening);
    FrameCode code = FrameCode::make(s_.code, s_.parity);
    std::vector<std::uint8_t> first = std::exchange(pending_, {});
    pending_overflow_ = false;
    Reception rx(code, shared_->library()->received, s_.name,
                 DecodeOptions{.code = s_.code, .parity = s_.parity, .keep_going = true, .max_diagnostics = 1},
                 s_.max_punch_out, pending_);
    ReceiveOptions o{.idle_timeout = s_.receive_timeout, .code = s_.code, .parity = s_.parity, .drop_flow_codes = true};
    o.stop = &stop_;
    o.gather = gather;
    o.first = first;
    Clock::time_point start{};
    o.sink = [&](std::span<const Frame> f) {
        bool began = rx.file.started();
        rx.sink(f);
        if (!rx.file.started()) return;  // blank leader so far
        if (!began) {
            start = shared_->clock->now();
            set_state(LineState::receiving, "punch-out");
        }
        set_frames(rx.frames);
    };
    o.ends_after = [&rx](Frame f) { return rx.ends_after(f); };
    ReceiveResult r = receive_frames(line, o, *shared_->clock);
    if (r.end == ReceiveResult::End::program_end && rx.watch.closing() && rx.write_error.empty()) {
        // The closing '%' came without its line's end: it follows at once when it comes at all.
        o.idle_timeout = line_end_wait;
        o.first = {};
        ReceiveResult more = receive_frames(line, o, *shared_->clock);
        if (more.end == ReceiveResult::End::hangup || more.end == ReceiveResult::End::stopped) r.end = more.end;
    }
    if (!rx.write_error.empty())
        after_write_failure(line, rx, r.end);
    else if (rx.file.started())
        finish_punch_out(line, rx, r.end, since(start));
    return r.end != ReceiveResult::End::hangup;
}

void Machine::finish_punch_out(Transport& line, Reception& rx, ReceiveResult::End end, double seconds) {
    const PunchOutWatch& watch = rx.watch;
    if (watch.noise()) {
        keep_failed(line, rx,
                    std::to_string(watch.bad_frames()) + " of its " + std::to_string(watch.punched_frames()) +
                        " frames bad: noise on the line, no program",
                    seconds);
        return;
    }
    if (!watch.content()) {  // a line end or a '%' after the last punch-out: nothing to file
        rx.file.discard();
        log(Priority::debug, std::to_string(rx.frames) + " frames of '%', blanks and line ends only: not filed");
        return;
    }
    if (rx.flood || (end != ReceiveResult::End::program_end && !watch.complete())) {
        keep_failed(line, rx, cut_reason(end, rx.flood), seconds);
        return;
    }
    auto request = rx.file.bytes() <= rx.file.head().size() ? parse_request(rx.file.head()) : std::nullopt;
    if (request) {
        rx.file.discard();
        answer(line, *request);
        return;
    }
    file_program(rx.file, rx.frames, seconds);
}

void Machine::keep_failed(Transport& line, Reception& rx, const std::string& reason, double seconds) {
    std::string kept = rx.file.keep_failed();
    std::string message = "received: " + std::to_string(rx.frames) + " frames, " + seconds_text(seconds) + ": cut (" +
                          reason + "): kept as " + kept;
    log(Priority::warning, message);
    count(&MachineStatus::failed, message);
    if (!rx.flood) return;
    pending_.clear();  // the flood's own
    std::uint64_t dropped = discard_until_quiet(line);
    log(Priority::warning, std::to_string(dropped) + " more frames of the flood dropped until the line was quiet");
}

// A write to received/ failed (a full disk): the rest of that punch-out is dropped until the line is
// quiet, so that none of it is taken for a punch-out of its own or filed under a program's name.
void Machine::after_write_failure(Transport& line, Reception& rx, ReceiveResult::End end) {
    std::string kept = rx.file.keep_written();
    pending_.clear();
    std::uint64_t dropped = rx.dropped;
    if (end == ReceiveResult::End::program_end) dropped += discard_until_quiet(line);
    const char* until = end == ReceiveResult::End::hangup    ? "until the other side hung up"
                        : end == ReceiveResult::End::stopped ? "until the service stopped"
                                                             : "until the line was quiet";
    std::string message = "received: " + rx.write_error + ": " +
                          (kept.empty() ? "nothing of the punch-out kept" : "what was written kept as " + kept) +
                          "; the rest, " + std::to_string(dropped) + " frames, dropped " + until;
    log(Priority::err, message);
    count(&MachineStatus::failed, message);
}

void Machine::keep_pending(std::span<const std::uint8_t> bytes) {
    std::size_t room = s_.max_punch_out > pending_.size() ? s_.max_punch_out - pending_.size() : 0;
    pending_.insert(pending_.end(), bytes.begin(),
                    bytes.begin() + static_cast<std::ptrdiff_t>(std::min(room, bytes.size())));
    if (room < bytes.size() && !pending_overflow_) {
        pending_overflow_ = true;
        log(Priority::warning, "more came while answering than max_punch_out: the rest of it dropped");
    }
}

void Machine::file_program(PunchOutFile& file, std::uint64_t frames, double seconds) {
    auto library = shared_->library();
    auto stem = program_file_stem(file.head());
    std::string name = stem.value_or("UNNUMBERED-" + s_.name);
    std::string path = file.file_as(name);
    std::string message =
        "received " + name + ": " + std::to_string(frames) + " frames, " + seconds_text(seconds) + ": filed as " + path;
    if (stem) {
        Found copy = find_program(library->programs, *stem);
        if (!copy.path.empty()) {
            auto bytes = read_file(path);
            message += ", " + compare_with(std::string(bytes.begin(), bytes.end()), copy.path);
        } else {
            message += ", no copy in the library (" + copy.problem + ")";
        }
    } else {
        message += " (it has no program number)";
    }
    if (auto request = request_comment_in(file.head()))
        message += "; it holds " + request->comment + " among other text: a program, not a request";
    Priority p = Priority::info;
    if (file.bad_frames()) {
        message += "; " + std::to_string(file.bad_frames()) + " bad frame(s) marked U+FFFD in the text";
        p = Priority::warning;
    }
    log(p, message);
    count(&MachineStatus::filed, message);
}

std::uint64_t Machine::discard_until_quiet(Transport& line) {
    std::uint64_t dropped = 0;
    ReceiveOptions o{.idle_timeout = s_.receive_timeout};
    o.stop = &stop_;
    o.gather = gather;
    o.sink = [&dropped](std::span<const Frame> f) { dropped += f.size(); };
    receive_frames(line, o, *shared_->clock);
    return dropped;
}

}  // namespace tape::dnc
