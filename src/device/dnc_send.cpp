// Sending frames over a line: pacing, XON/XOFF or RTS/CTS, exactly once each, in order.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tape/dnc.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

using namespace std::chrono_literals;

class Sender {
public:
    Sender(Transport& line, const SendOptions& o, Clock& clock)
        : line_(line), o_(o), clock_(clock), flow_(o.flow.value_or(line.flow())), xonxoff_(o.xon, o.xoff) {}

    SendResult run(std::span<const Frame> frames) {
        SendResult r;
        double rate = o_.rate > 0 ? o_.rate : line_.line_rate();
        auto period = rate > 0 ? frame_period(rate) : Clock::time_point::duration::zero();
        bool paced = period.count() > 0 || o_.block_delay.count() > 0;
        if (o_.wait_xon) wait_for_xon();
        auto start = clock_.now(), next = start, last_report = start;
        for (std::size_t i = 0; i < frames.size();) {
            if (stopped()) {
                r.stopped = true;
                break;
            }
            if (paced) {
                // After a pause: no burst to catch up.
                if (clock_.now() > next + 100 * period + o_.block_delay) next = clock_.now();
                clock_.sleep_until(next);
            }
            // Looked at right before each write: after DC3 (or CTS dropped) not one more frame goes out.
            if (flow_ == Flow::xonxoff) take_input(0ms, i);
            bool waited = false;
            while (blocked() && !stopped()) {
                waited = true;
                report(i, frames.size(), start, true);
                if (flow_ == Flow::xonxoff)
                    take_input(50ms, i);
                else
                    clock_.sleep_until(clock_.now() + 5ms);
            }
            if (stopped()) {
                r.stopped = true;
                break;
            }
            if (waited) next = clock_.now();  // resumed: paced from now, no burst to catch up the pause
            std::size_t n = write_burst(frames, i);
            i += n;
            r.sent = i;
            next += static_cast<long>(n) * period;
            if (o_.block_delay.count() > 0 && frames[i - 1] == o_.block_end) next += o_.block_delay;
            if (o_.progress && clock_.now() - last_report > 250ms) {
                last_report = clock_.now();
                report(i, frames.size(), start, false);
            }
        }
        line_.drain();
        r.pauses = xonxoff_.pauses();
        report(r.sent, frames.size(), start, false);
        return r;
    }

private:
    Transport& line_;
    const SendOptions& o_;
    Clock& clock_;
    Flow flow_;
    XonXoff xonxoff_;

    bool stopped() const { return o_.stop && o_.stop->load(); }

    // Writes up to a burst of frames from `from`, ending early after an end of block that has a delay
    // after it. How many went.
    std::size_t write_burst(std::span<const Frame> frames, std::size_t from) {
        std::uint8_t bytes[256];
        std::size_t n = 0, most = std::min({std::max<std::size_t>(o_.burst, 1), sizeof bytes, frames.size() - from});
        while (n < most) {
            Frame f = frames[from + n++];
            bytes[n - 1] = line_.seven_bit() ? f & 0x7F : f;
            if (o_.block_delay.count() > 0 && f == o_.block_end) break;
        }
        try {
            line_.write({bytes, n});
        } catch (const Error& e) {
            throw Error(e.code(), std::string(e.what()) + " (at frame " + std::to_string(from + 1) + " of " +
                                      std::to_string(frames.size()) + ")");
        }
        return n;
    }
    bool blocked() {
        if (flow_ == Flow::xonxoff) return xonxoff_.paused();
        if (flow_ == Flow::rtscts && line_.modem()) return !line_.modem()->cts();
        return false;
    }

    void take_input(std::chrono::milliseconds wait, std::size_t frame) {
        std::uint8_t buf[64];
        ReadResult got = line_.read(buf, wait);
        for (std::size_t k = 0; k < got.count; ++k) xonxoff_.receive(buf[k]);
        if (got.end)
            throw Error(Errc::io,
                        line_.name() + ": the other side hung up after " + std::to_string(frame) + " frame(s)");
    }

    void wait_for_xon() {
        auto start = clock_.now();
        while (!xonxoff_.seen_xon() && !stopped()) {
            take_input(100ms, 0);
            // Compared in milliseconds: any xon_timeout fits, where a deadline in nanoseconds could overflow.
            auto waited = std::chrono::duration_cast<std::chrono::milliseconds>(clock_.now() - start);
            if (o_.xon_timeout.count() > 0 && waited >= o_.xon_timeout && !xonxoff_.seen_xon())
                throw Error(Errc::io, line_.name() + ": no DC1 (XON) from the other side within " +
                                          std::to_string(o_.xon_timeout.count() / 1000.0).substr(0, 4) + " s");
        }
        if (xonxoff_.paused()) xonxoff_ = XonXoff(o_.xon, o_.xoff);
    }

    void report(std::uint64_t done, std::uint64_t total, Clock::time_point start, bool paused) {
        if (!o_.progress) return;
        double seconds = std::chrono::duration<double>(clock_.now() - start).count();
        o_.progress(LineProgress{done, total, xonxoff_.pauses(), paused,
                                 seconds > 0 ? static_cast<double>(done) / seconds : 0});
    }
};

}  // namespace

std::chrono::steady_clock::duration frame_period(double rate) {
    if (!std::isfinite(rate) || !(rate >= min_frame_rate)) {
        char text[64];
        std::snprintf(text, sizeof text, "%g", rate);
        throw Error(Errc::usage,
                    "the rate must be a number of frames per second from one a day up, not " + std::string(text));
    }
    return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(1.0 / rate));
}

SendResult send_frames(Transport& line, std::span<const Frame> frames, const SendOptions& options, Clock& clock) {
    if (options.rate != 0) frame_period(options.rate);  // refused here, before anything is sent
    Flow flow = options.flow.value_or(line.flow());
    if (flow == Flow::rtscts && !line.modem())
        throw Error(Errc::usage, line.name() + ": flow=rtscts, but this device has no modem lines");
    if ((flow == Flow::xonxoff || options.wait_xon) && (options.xon & 0x7F) == (options.xoff & 0x7F))
        throw Error(Errc::usage, "XON and XOFF are the same character");
    // A 7-bit line's UART makes even parity itself: it can carry only ISO frames whose track 8 is just that.
    if (line.seven_bit())
        for (std::size_t i = 0; i < frames.size(); ++i)
            if (hole_count(frames[i]) % 2 != 0)
                throw Error(Errc::usage, Position{.frame = i + 1},
                            line.name() + ": a 7-bit line carries ISO frames with even parity only, and frame " +
                                std::to_string(i + 1) + " is not one (an EIA or damaged tape): use bits=8");
    return Sender(line, options, clock).run(frames);
}

}  // namespace tape
