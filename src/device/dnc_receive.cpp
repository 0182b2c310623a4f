// Receiving frames from a line: everything kept as it arrives, the run ended by the program's end,
// a quiet line, a hang-up or the user.
#include "tape/dnc.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

using namespace std::chrono_literals;

// DC1-DC4 come from the other side's line control, with whatever it does to bit 8: an ISO control
// on 8N1 may send DC3 as 0x13 (no parity bit) or 0x93 (even parity). No other ISO frame has those
// seven bits, so both are dropped. On EIA tape 0x11-0x14 are characters ('3' is 0x13): there only
// frames the table reads as DC1-DC4 are dropped.
bool is_flow_code(Frame f, const FrameCode& code) {
    if (code.code() == Code::iso) return (f & 0x7F) >= dc1 && (f & 0x7F) <= dc4;
    if (code.kind(f) != FrameKind::character) return false;
    char c = code.character(f);
    return c >= dc1 && c <= dc4;
}

// A 7-bit line's UART checked and removed the parity bit: the frame is punched back as the encoder
// punches that character under the tape's rule (mark: track 8 always; space, none: never; even, odd:
// by the count of holes), blank tape staying blank under every rule. Only ISO comes over such a line.
Frame with_track_8(std::uint8_t b, const FrameCode& iso) { return iso.frame_for(b & 0x7F).value_or(b & 0x7F); }

// RTS says "we accept data" on a line with modem lines: up while receiving, down however the run ends.
class RtsWhileReceiving {
public:
    explicit RtsWhileReceiving(Transport& line) : modem_(line.modem()) {
        if (modem_) modem_->set_rts(true);
    }
    ~RtsWhileReceiving() { drop(); }
    RtsWhileReceiving(const RtsWhileReceiving&) = delete;
    RtsWhileReceiving& operator=(const RtsWhileReceiving&) = delete;

    void drop() noexcept {
        if (!modem_) return;
        try {
            modem_->set_rts(false);
        } catch (const Error&) {  // a line already gone has no RTS to drop
        }
        modem_ = nullptr;
    }

private:
    ModemLines* modem_;
};

class Receiver {
public:
    Receiver(Transport& line, const ReceiveOptions& o, Clock& clock)
        : line_(line),
          o_(o),
          clock_(clock),
          code_(FrameCode::make(o.code, o.parity, o.eia_table)),
          seven_bit_(line.seven_bit()),
          rts_(line) {}

    ReceiveResult run() {
        auto last_frame = clock_.now(), start = clock_.now(), last_report = start;
        if (!o_.first.empty() && take(o_.first)) {
            r_.end = ReceiveResult::End::program_end;
            return r_;
        }
        for (;;) {
            if (o_.stop && o_.stop->load()) {
                finish_after_stop();
                r_.end = ReceiveResult::End::stopped;
                return r_;
            }
            ReadResult got = line_.read(buf_, 100ms);
            if (got.count) {
                last_frame = clock_.now();
                bool done = take({buf_, got.count});
                if (o_.progress && clock_.now() - last_report > 250ms) {
                    last_report = clock_.now();
                    double s = std::chrono::duration<double>(clock_.now() - start).count();
                    o_.progress(LineProgress{r_.frames, 0, 0, false, s > 0 ? static_cast<double>(r_.frames) / s : 0});
                }
                if (done) {
                    r_.end = ReceiveResult::End::program_end;
                    return r_;
                }
                if (o_.gather.count() > 0 && !got.end) clock_.sleep_until(clock_.now() + o_.gather);
            }
            if (got.end) {
                r_.end = ReceiveResult::End::hangup;
                return r_;
            }
            // Compared in milliseconds: any idle_timeout fits, where nanoseconds could overflow.
            if (o_.idle_timeout.count() > 0 &&
                std::chrono::duration_cast<std::chrono::milliseconds>(clock_.now() - last_frame) >= o_.idle_timeout) {
                r_.end = ReceiveResult::End::idle;
                return r_;
            }
        }
    }

private:
    Transport& line_;
    const ReceiveOptions& o_;
    Clock& clock_;
    FrameCode code_;
    bool seven_bit_;
    RtsWhileReceiving rts_;
    ProgramEndWatch watch_;
    ReceiveResult r_;
    std::vector<Frame> kept_;
    std::uint8_t buf_[512];

    // Keeps the frames of one read, by the same rules before and after a stop. True at the program's end.
    bool take(std::span<const std::uint8_t> bytes) {
        kept_.clear();
        bool done = false, ended = false;
        for (std::size_t i = 0; i < bytes.size() && !done; ++i) {
            Frame f = seven_bit_ ? with_track_8(bytes[i], code_) : bytes[i];
            if (o_.drop_flow_codes && is_flow_code(f, code_)) continue;
            kept_.push_back(f);
            if (o_.ends_after && o_.ends_after(f)) ended = true;
            if (o_.until_program_end && code_.kind(f) == FrameKind::character &&
                watch_.feed(code_.character(f)) == ProgramEndWatch::Event::next_percent)
                done = true;
        }
        if (o_.sink && !kept_.empty()) o_.sink(kept_);
        r_.frames += kept_.size();
        return done || ended;
    }

    // Asks the other side to stop, in band and by RTS, and still takes what it sends on in the next moments.
    void finish_after_stop() {
        rts_.drop();
        std::uint8_t xoff = dc3;
        try {
            line_.write({&xoff, 1});
        } catch (const Error&) {  // a file, or a line already gone: nothing to ask
        }
        auto grace_end = clock_.now() + 300ms;
        while (clock_.now() < grace_end) {
            ReadResult got = line_.read(buf_, 50ms);
            if (got.count && take({buf_, got.count})) break;
            if (got.end) break;
        }
    }
};

}  // namespace

ReceiveResult receive_frames(Transport& line, const ReceiveOptions& o, Clock& clock) {
    if (line.seven_bit() && o.code != Code::iso)
        throw Error(
            Errc::usage,
            line.name() +
                ": a 7-bit line carries ISO tapes only (the UART's parity stands for track 8): use bits=8 for EIA");
    return Receiver(line, o, clock).run();
}

}  // namespace tape
