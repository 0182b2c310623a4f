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

    SendResult run(FrameSource& frames) {
        double rate = o_.rate > 0 ? o_.rate : line_.line_rate();
        period_ = rate > 0 ? frame_period(rate) : Clock::time_point::duration::zero();
        total_ = frames.total();
        auto chunk = frames.next();
        check_seven_bit(chunk);  // the first chunk before anything is sent or waited for
        if (o_.wait_xon) wait_for_xon();
        start_ = next_ = last_report_ = clock_.now();
        while (!chunk.empty() && !stopped()) {
            for (std::size_t i = 0; i < chunk.size() && !stopped();) i += send_burst(chunk, i);
            if (r_.stopped) break;
            chunk = frames.next();
            check_seven_bit(chunk);
        }
        // Stopped: what the device still holds is not waited for, and what it says now is no failure
        // of the run (the stop may well have caused it).
        try {
            if (!r_.stopped) line_.drain();
        } catch (const Error&) {
            if (!stopped()) throw;
        }
        r_.pauses = xonxoff_.pauses();
        report(false);
        return r_;
    }

private:
    Transport& line_;
    const SendOptions& o_;
    Clock& clock_;
    Flow flow_;
    XonXoff xonxoff_;
    SendResult r_;
    Clock::time_point::duration period_{};
    Clock::time_point start_{}, next_{}, last_report_{};
    std::uint64_t total_ = 0;

    bool stopped() {
        if (o_.stop && o_.stop->load()) r_.stopped = true;
        return r_.stopped;
    }

    // A 7-bit line's UART makes even parity itself: it can carry only ISO frames whose track 8 is just that.
    void check_seven_bit(std::span<const Frame> chunk) const {
        if (!line_.seven_bit()) return;
        for (std::size_t i = 0; i < chunk.size(); ++i)
            if (hole_count(chunk[i]) % 2 != 0) {
                std::uint64_t frame = r_.sent + i + 1;
                throw Error(Errc::usage, Position{.frame = frame},
                            line_.name() + ": a 7-bit line carries ISO frames with even parity only, and frame " +
                                std::to_string(frame) + " is not one (an EIA or damaged tape): use bits=8" +
                                (r_.sent ? " (" + std::to_string(r_.sent) + " frames were sent)" : ""));
            }
    }

    // Paced, held while the other side says so, then a burst from chunk[from]. How many frames went
    // (none once stopped).
    std::size_t send_burst(std::span<const Frame> chunk, std::size_t from) {
        if (period_.count() > 0 || o_.block_delay.count() > 0) {
            // After a pause: no burst to catch up.
            if (clock_.now() > next_ + 100 * period_ + o_.block_delay) next_ = clock_.now();
            clock_.sleep_until(next_);
        }
        // Looked at right before each write: after DC3 (or CTS dropped) not one more frame goes out.
        if (flow_ == Flow::xonxoff) take_input(0ms);
        bool waited = false;
        while (blocked() && !stopped()) {
            waited = true;
            report(true);
            if (flow_ == Flow::xonxoff)
                take_input(50ms);
            else
                clock_.sleep_until(clock_.now() + 5ms);
        }
        if (stopped()) return 0;
        if (waited) next_ = clock_.now();  // resumed: paced from now, no burst to catch up the pause
        std::size_t n = write_burst(chunk, from);
        if (n == 0) return 0;
        r_.sent += n;
        next_ += static_cast<long>(n) * period_;
        if (o_.block_delay.count() > 0 && chunk[from + n - 1] == o_.block_end) next_ += o_.block_delay;
        if (o_.progress && clock_.now() - last_report_ > 250ms) {
            last_report_ = clock_.now();
            report(false);
        }
        return n;
    }

    // Writes up to a burst of frames from `from`, ending early after an end of block that has a delay
    // after it. How many went: none when the write failed after a stop (the stop ends the run).
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
            if (stopped()) return 0;  // the stop came first: the run ends as stopped
            throw Error(e.code(), std::string(e.what()) + " (at frame " + std::to_string(r_.sent + 1) +
                                      (total_ ? " of " + std::to_string(total_) : std::string()) + ")");
        }
        return n;
    }
    bool blocked() {
        if (flow_ == Flow::xonxoff) return xonxoff_.paused();
        if (flow_ == Flow::rtscts && line_.modem()) return !line_.modem()->cts();
        return false;
    }

    void take_input(std::chrono::milliseconds wait) {
        std::uint8_t buf[64];
        ReadResult got = line_.read(buf, wait);
        std::size_t other = 0;  // the bytes besides XON and XOFF, moved to the front of buf
        for (std::size_t k = 0; k < got.count; ++k)
            if (!xonxoff_.receive(buf[k])) buf[other++] = buf[k];
        if (other && o_.other_input) o_.other_input({buf, other});
        if (got.end)
            throw Error(Errc::io,
                        line_.name() + ": the other side hung up after " + std::to_string(r_.sent) + " frame(s)");
    }

    void wait_for_xon() {
        auto start = clock_.now();
        while (!xonxoff_.seen_xon() && !stopped()) {
            take_input(100ms);
            // Compared in milliseconds: any xon_timeout fits, where a deadline in nanoseconds could overflow.
            auto waited = std::chrono::duration_cast<std::chrono::milliseconds>(clock_.now() - start);
            if (o_.xon_timeout.count() > 0 && waited >= o_.xon_timeout && !xonxoff_.seen_xon())
                throw Error(Errc::io, line_.name() + ": no DC1 (XON) from the other side within " +
                                          std::to_string(o_.xon_timeout.count() / 1000.0).substr(0, 4) + " s");
        }
        if (xonxoff_.paused()) xonxoff_ = XonXoff(o_.xon, o_.xoff);
    }

    void report(bool paused) {
        if (!o_.progress) return;
        double seconds = std::chrono::duration<double>(clock_.now() - start_).count();
        o_.progress(LineProgress{r_.sent, total_, xonxoff_.pauses(), paused,
                                 seconds > 0 ? static_cast<double>(r_.sent) / seconds : 0});
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

SendResult send_frames(Transport& line, FrameSource& frames, const SendOptions& options, Clock& clock) {
    if (options.rate != 0) frame_period(options.rate);  // refused here, before anything is sent
    Flow flow = options.flow.value_or(line.flow());
    if (flow == Flow::rtscts && !line.modem())
        throw Error(Errc::usage, line.name() + ": flow=rtscts, but this device has no modem lines");
    if ((flow == Flow::xonxoff || options.wait_xon) && (options.xon & 0x7F) == (options.xoff & 0x7F))
        throw Error(Errc::usage, "XON and XOFF are the same character");
    return Sender(line, options, clock).run(frames);
}

SendResult send_frames(Transport& line, std::span<const Frame> frames, const SendOptions& options, Clock& clock) {
    SpanSource source(frames);
    return send_frames(line, source, options, clock);
}

}  // namespace tape
