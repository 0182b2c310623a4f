// A tape reader a controller pulls from: start/stop on DC1/DC3 (or CTS), paced at the reader's speed,
// rewinding to '%' at the end of a program, searching ':' main blocks on request.

#include <algorithm>

#include "tape/dnc.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

using namespace std::chrono_literals;

bool is_char(const FrameCode& code, Frame f, char c) {
    return code.kind(f) == FrameKind::character && code.character(f) == c;
}

class Emulator {
public:
    Emulator(Transport& line, std::span<const Frame> tape, const EmulatorOptions& o, Clock& clock)
        : line_(line),
          tape_(tape),
          o_(o),
          clock_(clock),
          code_(FrameCode::make(o.code, o.parity, o.eia_table)),
          flow_(o.flow.value_or(line.flow())) {}

    EmulatorResult run() {
        auto period = frame_period(o_.rate);
        if (flow_ == Flow::rtscts && !line_.modem())
            throw Error(Errc::usage, line_.name() + ": flow=rtscts, but this device has no modem lines");
        if (o_.skip_leader)
            while (pos_ < tape_.size() && tape_[pos_] == blank_frame) ++pos_;
        log("loaded, waiting for " + std::string(flow_ == Flow::rtscts ? "CTS" : "DC1"));
        while (!(o_.stop && o_.stop->load())) {
            // Listen while the next frame's time comes (up to 20 ms at a time, so that a stop is seen);
            // its last fraction of a millisecond is slept, then the line looked at once more.
            std::chrono::milliseconds wait = 20ms;
            if (running_ && pos_ < tape_.size()) {
                auto left = next_ - clock_.now();
                if (left < 1ms) {
                    clock_.sleep_until(next_);
                    wait = 0ms;
                } else {
                    wait =
                        std::min<std::chrono::milliseconds>(std::chrono::floor<std::chrono::milliseconds>(left), 20ms);
                }
            }
            take_input(wait);
            if (flow_ == Flow::rtscts) set_running(line_.modem()->cts());
            if (!running_) continue;
            if (pos_ >= tape_.size()) {
                set_running(false);
                log("end of tape");
                continue;
            }
            if (clock_.now() < next_) continue;
            // The line was looked at just now, after the wait: once DC3 (or CTS dropped) has come, no
            // frame starts.
            std::uint8_t byte = line_.seven_bit() ? tape_[pos_] & 0x7F : tape_[pos_];
            try {
                line_.write({&byte, 1});
            } catch (const Error& e) {
                throw Error(e.code(), std::string(e.what()) + "; " + std::to_string(r_.frames_sent) + " frame(s) sent");
            }
            ++r_.frames_sent;
            // Late (this process was not scheduled), the reader catches up, but never faster than twice its
            // speed: frames sent back to back would be on the line before a DC3 already on its way is seen.
            due_ += period;
            if (clock_.now() > due_ + 10 * period) due_ = clock_.now();  // very late: give up catching up
            next_ = std::max(due_, clock_.now() + period / 2);
            Frame sent = tape_[pos_++];
            if (code_.kind(sent) == FrameKind::character &&
                watch_.feed(code_.character(sent)) == ProgramEndWatch::Event::program_end) {
                std::size_t stop = seek_rewind_stop(tape_, pos_, code_);
                log("end of program");
                set_running(false);
                rewind_to(stop);
            }
        }
        return r_;
    }

private:
    Transport& line_;
    std::span<const Frame> tape_;
    const EmulatorOptions& o_;
    Clock& clock_;
    FrameCode code_;
    Flow flow_;
    std::size_t pos_ = 0;
    bool running_ = false;
    Clock::time_point due_{};   // when the next frame is due while running, at the reader's speed
    Clock::time_point next_{};  // when it may go: due, or half a frame time after the last one
    ProgramEndWatch watch_;
    EmulatorResult r_;
    std::optional<std::string> search_digits_;  // after the search character, until a non-digit

    void log(const std::string& what) {
        if (o_.log) o_.log(pos_ + 1, what);
    }

    void set_running(bool on) {
        if (on == running_) return;
        running_ = on;
        if (on) due_ = next_ = clock_.now();  // a started reader sends its first frame at once
        ++(on ? r_.starts : r_.stops);
        log(on ? "start" : "stop");
    }

    void rewind_to(std::size_t stop) {
        pos_ = stop;
        watch_ = ProgramEndWatch{};
        ++r_.rewinds;
        log("rewound to the '%' stop");
    }

    void finish_search() {
        std::optional<long long> number;
        if (search_digits_ && !search_digits_->empty() && search_digits_->size() < 18)
            number = std::stoll(*search_digits_);
        search_digits_.reset();
        ++r_.searches;
        auto hit = seek_main_block(tape_, pos_, code_, number);
        if (!hit) {
            log("search: no main block" + (number ? " :" + std::to_string(*number) : std::string()) + " ahead");
            return;
        }
        pos_ = *hit;
        watch_ = ProgramEndWatch{};
        log("search: at main block" + (number ? " :" + std::to_string(*number) : std::string()));
    }

    // Commands from the controller. Throws Error(Errc::io) when the line hung up.
    void take_input(std::chrono::milliseconds wait) {
        std::uint8_t buf[64];
        ReadResult got = line_.read(buf, wait);
        for (std::size_t i = 0; i < got.count; ++i) {
            std::uint8_t b = buf[i] & 0x7F;  // commands come in either parity
            if (search_digits_) {
                if (b >= '0' && b <= '9') {
                    *search_digits_ += static_cast<char>(b);
                    continue;
                }
                finish_search();
            }
            if (flow_ != Flow::rtscts && b == (o_.start & 0x7F))
                set_running(true);
            else if (flow_ != Flow::rtscts && b == (o_.stop_code & 0x7F))
                set_running(false);
            else if (b == (o_.search & 0x7F))
                search_digits_ = std::string();
            else if (b == (o_.rewind & 0x7F)) {
                set_running(false);
                rewind_to(seek_rewind_stop(tape_, pos_, code_));
            }
        }
        if (search_digits_ && got.count == 0) finish_search();
        if (got.end) {
            log("the controller hung up");
            throw Error(Errc::io, line_.name() + ": the other side hung up; " + std::to_string(r_.frames_sent) +
                                      " frame(s) sent");
        }
    }
};

}  // namespace

EmulatorResult emulate_reader(Transport& line, std::span<const Frame> tape, const EmulatorOptions& options,
                              Clock& clock) {
    return Emulator(line, tape, options, clock).run();
}

std::optional<std::size_t> seek_main_block(std::span<const Frame> tape, std::size_t from, const FrameCode& code,
                                           std::optional<long long> number) {
    for (std::size_t i = from; i < tape.size(); ++i) {
        if (!is_char(code, tape[i], ':')) continue;
        if (!number) return i;
        long long n = 0;
        int digits = 0;
        for (std::size_t k = i + 1; k < tape.size() && digits < 18; ++k) {
            FrameKind kind = code.kind(tape[k]);
            if (kind == FrameKind::blank || kind == FrameKind::rubout) continue;
            if (kind != FrameKind::character || code.character(tape[k]) < '0' || code.character(tape[k]) > '9') break;
            n = n * 10 + (code.character(tape[k]) - '0');
            ++digits;
        }
        if (digits && n == *number) return i;
    }
    return std::nullopt;
}

std::size_t seek_rewind_stop(std::span<const Frame> tape, std::size_t from, const FrameCode& code) {
    for (std::size_t i = std::min(from, tape.size()); i-- > 0;)
        if (is_char(code, tape[i], '%')) return i;
    return 0;
}

}  // namespace tape
