// The host's side of the tape adapter protocol: requests with replies matched by seq and retried,
// rows taken in frame order with gaps asked for again (RESEND), punching by credit, keep-alives for
// the adapter's watchdog. Every end of a run is decided only once every row before it is here.
#include "adapter_session.hpp"

#include <algorithm>
#include <cstdio>

#include "tape/error.hpp"

namespace tape::adapter {

using namespace std::chrono_literals;
using tapefw::Msg;
using tapefw::Packet;

namespace {

std::string msg_name(std::uint8_t type) {
    switch (static_cast<Msg>(type)) {
        case Msg::get_info:
            return "GET_INFO";
        case Msg::config:
            return "CONFIG";
        case Msg::read_start:
            return "READ_START";
        case Msg::read_stop:
            return "READ_STOP";
        case Msg::punch:
            return "PUNCH";
        case Msg::feed:
            return "FEED";
        case Msg::reset:
            return "RESET";
        case Msg::echo:
            return "ECHO";
        case Msg::wiring:
            return "WIRING";
        case Msg::emulate:
            return "EMULATE";
        case Msg::discard:
            return "DISCARD";
        default:
            return "message " + std::to_string(type);
    }
}

// "2.3 s"
std::string seconds_text(std::chrono::steady_clock::duration d) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", std::chrono::duration<double>(d).count());
    return text;
}

// What stopped a run, in words, from the status bits (the first that applies).
std::string fault_text(std::uint16_t bits) {
    namespace s = tapefw::status;
    if (bits & s::torn) return "torn tape: no sprocket hole within the time-out";
    if (bits & s::watchdog) return "the adapter's watchdog stopped the reader and the punch (the host was silent)";
    if (bits & s::motor_fault) return "motor fault";
    if (bits & s::offline) return "the unit is off-line";
    if (bits & s::chad_full) return "the chad box is full";
    if (bits & s::punch_tape_out) return "the punch is out of tape";
    if (bits & s::tape_out) return "tape out";
    return "stopped";
}

}  // namespace

Session::Session(std::unique_ptr<PacketPipe> pipe, SessionTiming timing) : pipe_(std::move(pipe)), t_(timing) {
    // RESET first: whatever a previous run left (a reader running, a half-sent packet), both sides
    // start again in step, on every transport, without unplugging.
    Packet p;
    p.type = static_cast<std::uint8_t>(Msg::reset);
    request(p, Msg::ok);
    p = Packet{};
    p.type = static_cast<std::uint8_t>(Msg::get_info);
    Packet reply = request(p, Msg::info);
    if (!info_.decode(reply)) fail(0, "the adapter's INFO reply is malformed");
    if (info_.protocol != tapefw::protocol_version)
        throw Error(Errc::io, name() + ": the adapter speaks protocol version " + std::to_string(info_.protocol) +
                                  ", this tape speaks version " + std::to_string(tapefw::protocol_version) +
                                  ": update " +
                                  (info_.protocol < tapefw::protocol_version ? "the adapter's firmware" : "tape"));
    credit_free_ = info_.punch_buffer;
}

Session::~Session() {
    // A run ended before its end (Ctrl-C, a failure): the reader is stopped, a punch with rows still
    // queued is reset, so that it stops now and not when its queue has run out, and an emulating adapter
    // gives the control no more frames.
    bool punch_left = punching_ && punched_ < rows_queued() + feeds_;
    if (!reading_ && !punch_left && !emulating_) return;
    try {
        Packet p;
        p.type = static_cast<std::uint8_t>(reading_ ? Msg::read_stop : Msg::reset);
        send(p);
    } catch (const Error&) {  // an adapter already gone has nothing to stop
    }
}

void Session::fail(std::uint64_t frame, const std::string& what) const {
    // Before a run has started no frame is concerned: opening, info, self-test.
    bool run = reading_ || punching_ || expected_ > 0 || emulating_;
    throw Error(Errc::io, name() + ": " + (run ? "frame " + std::to_string(frame) + ": " : "") + what);
}

void Session::protocol_error(std::uint64_t frame, const std::string& what) const {
    fail(frame, "protocol error: " + what + " (update the adapter's firmware, or report it)");
}

std::string Session::silence(const std::string& what) const {
    std::uint64_t bad = pipe_->bad_packets() - bad_when_heard_;
    if (bad == 0) return what;
    return "the link is damaging every packet: " + std::to_string(bad) +
           " from the adapter failed their CRC since the last good one (a bad cable, hub or connector?)";
}

void Session::heard() {
    last_heard_ = clock::now();
    bad_when_heard_ = pipe_->bad_packets();
}

std::uint64_t Session::position() const {
    if (emulating_) return std::uint64_t{taken_.taken} + 1;
    return (reading_ || !punching_ ? expected_ : punched_) + 1;
}

// The pipe's failures (an adapter unplugged) get the frame position the session knows.
[[noreturn]] void Session::rethrow(const Error& e) const {
    std::string what = e.what();
    std::string prefix = name() + ": ";
    if (what.starts_with(prefix)) what = what.substr(prefix.size());
    fail(position(), what);
}

std::uint8_t Session::send(Packet p) {
    p.seq = ++seq_;
    try {
        pipe_->send(p);
    } catch (const Error& e) {
        rethrow(e);
    }
    last_sent_ = clock::now();
    return p.seq;
}

std::optional<Packet> Session::receive(std::chrono::milliseconds timeout) {
    try {
        return pipe_->receive(timeout);
    } catch (const Error& e) {
        rethrow(e);
    }
}

Packet Session::request(const Packet& p, Msg reply) {
    std::uint64_t bad_before = pipe_->bad_packets();
    for (int attempt = 0; attempt < t_.tries; ++attempt) {
        std::uint8_t seq = send(p);
        auto deadline = clock::now() + t_.reply;
        for (auto now = clock::now(); now < deadline; now = clock::now()) {
            auto got = receive(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now) + 1ms);
            if (!got) continue;
            heard();
            if (got->seq == seq && got->type == static_cast<std::uint8_t>(reply)) return *got;
            tapefw::ErrorReply e;
            if (got->seq == seq && e.decode(*got) && e.about == p.type)
                fail(expected_ + 1, "the adapter refused " + msg_name(p.type) + ": " + tapefw::error_name(e.code));
            handle(*got);
        }
    }
    std::uint64_t bad = pipe_->bad_packets() - bad_before;
    fail(expected_ + 1, "no answer to " + msg_name(p.type) + " after " + std::to_string(t_.tries) + " tries: " +
                            (bad ? "the link is damaging every packet (" + std::to_string(bad) +
                                       " from the adapter failed their CRC: a bad cable, hub or connector?)"
                                 : std::string("time-out (is it a tape adapter?)")));
}

void Session::configure(const tapefw::Config& config) {
    Packet p;
    config.encode(p);
    request(p, Msg::ok);
}

void Session::handle(const Packet& p) {
    switch (static_cast<Msg>(p.type)) {
        case Msg::rows:
            return handle_rows(p);
        case Msg::status:
            return handle_status(p);
        case Msg::taken:
            return handle_taken(p);
        case Msg::credit:
            return handle_credit(p);
        case Msg::error: {
            tapefw::ErrorReply e;
            if (!e.decode(p)) return;
            switch (e.code) {
                case tapefw::ErrorCode::bad_packet:
                    // One of ours was damaged on the way: the time-outs send it again.
                    ++bad_out_;
                    return;
                case tapefw::ErrorCode::out_of_order:
                    // A PUNCH (or FRAMES) was lost: from the one expected. One the adapter has taken since
                    // (this error overtaken by a CREDIT) is stale; one never sent cannot be expected.
                    if (emulating_) {
                        emu_sent_to_ = std::min(emu_sent_to_, e.frame);
                        return;
                    }
                    if (e.frame > rows_queued())
                        protocol_error(e.frame + 1, "the adapter expects punch row " + std::to_string(e.frame + 1) +
                                                        ", and only " + std::to_string(rows_queued()) + " were sent");
                    if (e.frame >= credit_next_) sent_to_ = std::min(sent_to_, e.frame);
                    return;
                case tapefw::ErrorCode::resend_gone:
                    fail(expected_ + 1, "frames " + std::to_string(expected_ + 1) + "-" +
                                            std::to_string(gap_end_.value_or(expected_ + 1)) +
                                            " lost: the adapter no longer holds them");
                case tapefw::ErrorCode::not_emulating:
                    if (!emulating_) return;  // a FRAMES of a session already ended
                    fail(std::uint64_t{e.frame} + 1, "the adapter is no longer emulating the reader");
                case tapefw::ErrorCode::overrun:
                    if (!pending_) pending_ = Pending{e.frame, "the adapter's buffer overran: frames lost from here"};
                    return;
                default:
                    fail(expected_ + 1, std::string("the adapter reports: ") + tapefw::error_name(e.code));
            }
        }
        default:
            return;  // OK and replies to requests already given up
    }
}

void Session::handle_rows(const Packet& p) {
    tapefw::Rows r;
    if (!reading_ || !r.decode(p)) return;
    if (r.first > expected_) {
        // Rows missing before these: asked for again, these dropped (the resend brings them too).
        // The missing rows end where the first packet seen after them starts.
        gap_end_ = std::min(gap_end_.value_or(r.first), r.first);
        if (gap_tries_ == 0) start_gap();
        return;
    }
    std::uint32_t end = r.first + r.count;
    for (std::uint32_t f = expected_; f < end; ++f) {
        ready_.push_back(r.rows[f - r.first]);
        if (r.flags[f - r.first]) note_flags(f, r.flags[f - r.first]);
    }
    if (end > expected_) expected_ = end;
    if (gap_tries_ && (!gap_end_ || expected_ >= *gap_end_)) {
        // Only a gap seen is named: a resend after a damaged packet may have had nothing to fill.
        if (gap_end_) recovered_.emplace_back(gap_first_ + 1, *gap_end_);
        gap_end_.reset();
        gap_tries_ = 0;
    }
}

void Session::handle_credit(const Packet& p) {
    tapefw::Credit c;
    if (!c.decode(p)) return;
    // Credit is the adapter's word on its queue: one that cannot be true would have rows lost or sent twice.
    if (c.free > info_.punch_buffer)
        protocol_error(std::uint64_t{punched_} + 1, "the adapter gives credit for " + std::to_string(c.free) +
                                                        " rows, more than its queue of " +
                                                        std::to_string(info_.punch_buffer));
    if (c.next > rows_queued())
        protocol_error(std::uint64_t{punched_} + 1, "the adapter's credit counts " + std::to_string(c.next) +
                                                        " rows queued, of " + std::to_string(rows_queued()) + " sent");
    credit_next_ = std::max(credit_next_, c.next);
    credit_free_ = c.free;
    punched_ = std::max(punched_, c.punched);
    last_credit_ = clock::now();
    // Rows the adapter has queued are never sent again: they leave the host's window.
    while (rows_base_ < credit_next_ && rows_base_ < sent_to_ && !rows_.empty()) {
        rows_.pop_front();
        ++rows_base_;
    }
}

void Session::note_flags(std::uint32_t row, std::uint8_t flags) {
    std::uint64_t frame = std::uint64_t{row} + 1;
    if (!doubts_.empty() && doubts_.back().last + 1 == frame && doubts_.back().flags == flags)
        doubts_.back().last = frame;
    else if (doubts_.size() < max_doubts)
        doubts_.push_back({frame, frame, flags});
    else
        ++unkept_doubts_;
}

void Session::handle_status(const Packet& p) {
    tapefw::Status s;
    if (!s.decode(p)) return;
    namespace st = tapefw::status;
    if (reading_) {
        // Every row before the one a STATUS names was read before it happened: naming an earlier one
        // than the rows already sent is no state of a reader.
        if ((s.bits & (st::torn | st::watchdog | st::motor_fault | st::offline | st::tape_out | st::read_done)) &&
            s.frame < expected_)
            protocol_error(s.frame + 1, "the adapter's STATUS (" + fault_text(s.bits) + ") names frame " +
                                            std::to_string(s.frame + 1) + ", before the " + std::to_string(expected_) +
                                            " frames it has sent");
        if (s.bits & (st::torn | st::watchdog | st::motor_fault | st::offline)) {
            if (!pending_) pending_ = Pending{s.frame, fault_text(s.bits)};
        } else if (s.bits & (st::tape_out | st::read_done)) {
            end_at_ = s.frame;
        } else {
            return;
        }
        // Rows before the end not here yet: they are asked for as a gap.
        if (expected_ < s.frame && gap_tries_ == 0) {
            gap_end_ = s.frame;
            start_gap();
        }
        return;
    }
    if (emulating_) {
        if (s.bits & (st::watchdog | st::offline | st::motor_fault))
            fail(std::uint64_t{s.frame} + 1,
                 fault_text(s.bits) + "; " + std::to_string(s.frame) + " frame(s) taken by the control");
        return;
    }
    if (punching_ || feeds_) {
        std::uint16_t stop = st::punch_tape_out | st::chad_full | st::motor_fault | st::offline | st::watchdog;
        if (s.bits & stop) fail(std::uint64_t{s.frame} + 1, fault_text(s.bits & stop));
    } else if (!expected_ && (s.bits & st::watchdog)) {
        orphaned_ = s;  // told after this session's RESET: a run of a host that was gone
    }
}

void Session::keep_alive() {
    // Also after a quarter of the adapter's buffer: a fast link must not wait for the period to free it.
    bool many = expected_ - acked_ >= std::max<std::uint32_t>(1, info_.read_buffer / 4);
    if (!many && clock::now() - last_sent_ < t_.ack_every) return;
    Packet p;
    tapefw::FrameNumber{expected_}.encode(p, Msg::ack);
    send(p);
    acked_ = expected_;
}

void Session::check_gap() {
    // A packet of ours or of the adapter's damaged: a gap may be there with nothing after it to show
    // it, so the adapter is asked from the next row expected (a no-op when nothing is missing).
    std::uint64_t bad = pipe_->bad_packets();
    if (bad != bad_seen_) {
        bad_seen_ = bad;
        if (reading_ && gap_tries_ == 0) start_gap();
    }
    if (!gap_tries_) return;
    bool real_gap = gap_end_ || end_at_ || pending_;
    // Given up after so many requests and so long since the first, both: a host slowed down (a loaded
    // machine) must not count its own haste as the link's failure, nor wait on for ever.
    auto open_for = clock::now() - gap_since_;
    if (real_gap && gap_tries_ >= t_.resend_tries && open_for >= t_.lost_after)
        fail(gap_first_ + 1, "frames " + std::to_string(gap_first_ + 1) + "-" +
                                 std::to_string(gap_end_.value_or(end_at_.value_or(gap_first_ + 1))) +
                                 " lost: not received after " + std::to_string(gap_tries_) + " requests to resend in " +
                                 seconds_text(open_for) + " (CRC failures or a bad link)");
    if (clock::now() - gap_asked_ < t_.resend_after) return;
    if (!real_gap) {
        // A resend after a damaged packet that showed no gap: nothing was missing.
        gap_tries_ = 0;
        return;
    }
    ++gap_tries_;
    ask_resend();
}

void Session::start_gap() {
    gap_since_ = clock::now();
    gap_first_ = expected_;
    gap_tries_ = 1;
    ask_resend();
}

void Session::ask_resend() {
    gap_asked_ = clock::now();
    Packet q;
    tapefw::FrameNumber{expected_}.encode(q, Msg::resend);
    send(q);
}

ReadResult Session::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout,
                         const tapefw::ReadStart& start) {
    if (!reading_) {
        if (!(info_.capabilities & tapefw::caps::reader)) fail(1, "this adapter has no reader");
        Packet p;
        start.encode(p);
        request(p, Msg::ok);
        reading_ = true;
        heard();
    }
    auto deadline = clock::now() + timeout;
    for (;;) {
        if (!ready_.empty()) {
            std::size_t n = std::min(buffer.size(), ready_.size());
            std::copy_n(ready_.begin(), n, buffer.begin());
            ready_.erase(ready_.begin(), ready_.begin() + static_cast<std::ptrdiff_t>(n));
            return {n, false};
        }
        if (pending_ && expected_ >= pending_->frame) fail(std::uint64_t{pending_->frame} + 1, pending_->what);
        if (end_at_ && expected_ >= *end_at_) {
            reading_ = false;
            return {0, true};
        }
        check_gap();
        keep_alive();
        auto now = clock::now();
        if (now - last_heard_ > t_.silent) fail(expected_ + 1, silence("the adapter stopped answering: time-out"));
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now);
        auto got = receive(std::clamp(left, 0ms, 20ms));
        if (got) {
            heard();
            handle(*got);
        } else if (clock::now() >= deadline) {
            return {};
        }
    }
}

void Session::pump(std::chrono::milliseconds wait) {
    while (sent_to_ < rows_queued() && sent_to_ < credit_next_ + credit_free_) {
        tapefw::Punch pu;
        pu.first = sent_to_;
        std::size_t n = std::min<std::size_t>(
            {tapefw::Punch::max_rows, rows_queued() - sent_to_, credit_next_ + credit_free_ - sent_to_});
        pu.count = static_cast<std::uint8_t>(n);
        std::copy_n(rows_.begin() + (sent_to_ - rows_base_), n, pu.rows);
        Packet p;
        pu.encode(p);
        send(p);
        sent_to_ += static_cast<std::uint32_t>(n);
    }
    keep_alive();
    auto got = receive(wait);
    while (got) {
        heard();
        handle(*got);
        got = receive(0ms);
    }
    // Rows sent but neither taken nor refused: a PUNCH or its CREDIT was lost; from the one expected again.
    if (sent_to_ > credit_next_ && clock::now() - last_credit_ > t_.reply) {
        sent_to_ = credit_next_;
        last_credit_ = clock::now();
    }
}

void Session::punch(std::span<const std::uint8_t> rows) {
    if (!(info_.capabilities & tapefw::caps::punch)) fail(1, "this adapter has no punch");
    if (!punching_) {
        punching_ = true;
        heard();
        last_credit_ = clock::now();
    }
    rows_.insert(rows_.end(), rows.begin(), rows.end());
    pump(0ms);
    // The host stays at most one queue ahead of the punch, so that a caller's pacing and progress mean something.
    while (rows_queued() - credit_next_ > info_.punch_buffer) {
        pump(20ms);
        if (clock::now() - last_heard_ > t_.silent)
            fail(std::uint64_t{punched_} + 1, silence("the adapter stopped answering: time-out"));
    }
}

ReadResult Session::punch_input(std::chrono::milliseconds timeout) {
    pump(timeout);
    return {};
}

void Session::feed(std::uint16_t count) {
    drain();
    Packet p;
    tapefw::Feed{count}.encode(p);
    request(p, Msg::ok);
    feeds_ += count;
    drain();
}

void Session::drain() {
    std::uint32_t total = rows_queued() + feeds_;
    auto last_progress = clock::now();
    std::uint32_t seen = punched_;
    while (punched_ < total) {
        pump(20ms);
        if (punched_ != seen) {
            seen = punched_;
            last_progress = clock::now();
        } else if (clock::now() - last_progress > t_.silent) {
            fail(std::uint64_t{punched_} + 1,
                 silence("the punch punched nothing for " + std::to_string(t_.silent.count() / 1000.0).substr(0, 3) +
                         " s: time-out"));
        }
    }
}

void Session::handle_taken(const Packet& p) {
    tapefw::Taken t;
    if (!emulating_ || !t.decode(p)) return;
    // After a turn of the control (or a DISCARD) the adapter expects frames from its next again.
    if (t.turn != taken_.turn || t.next < taken_.next) emu_sent_to_ = t.next;
    if (t.next != taken_.next) last_taken_ = clock::now();
    taken_ = t;
}

void Session::set_wiring(const tapefw::Wiring& wiring) {
    Packet p;
    wiring.encode(p);
    request(p, Msg::ok);
}

void Session::start_emulation() {
    if (!(info_.capabilities & tapefw::caps::emulate))
        fail(0, "this adapter cannot stand in for a tape reader (no emulate role)");
    Packet p;
    p.type = static_cast<std::uint8_t>(Msg::emulate);
    taken_ = tapefw::Taken{};
    taken_.free = 0;
    emu_sent_to_ = 0;
    request(p, Msg::ok);
    emulating_ = true;
    heard();
    last_taken_ = clock::now();
}

void Session::stop_emulation() {
    if (!emulating_) return;
    emulating_ = false;
    Packet p;
    p.type = static_cast<std::uint8_t>(Msg::reset);
    request(p, Msg::ok);
}

void Session::offer(std::uint32_t first, std::span<const std::uint8_t> frames) {
    std::uint32_t end = first + static_cast<std::uint32_t>(frames.size());
    std::uint32_t limit = std::min(end, taken_.next + taken_.free);
    // Frames sent but not queued for a while (the adapter's TAKEN tells): a FRAMES was lost; from the one
    // expected again.
    if (emu_sent_to_ > taken_.next && clock::now() - last_taken_ > t_.reply) {
        emu_sent_to_ = taken_.next;
        last_taken_ = clock::now();
    }
    emu_sent_to_ = std::max({emu_sent_to_, taken_.next, first});
    while (emu_sent_to_ < limit) {
        tapefw::Frames f;
        f.first = emu_sent_to_;
        f.turn = taken_.turn;
        f.count = static_cast<std::uint8_t>(std::min<std::uint32_t>(tapefw::Frames::max_frames, limit - emu_sent_to_));
        std::copy_n(frames.begin() + (emu_sent_to_ - first), f.count, f.frames);
        Packet p;
        f.encode(p);
        send(p);
        emu_sent_to_ += f.count;
    }
}

void Session::discard(std::uint32_t from, bool until_start) {
    Packet p;
    tapefw::Discard{from, static_cast<std::uint8_t>(until_start)}.encode(p);
    handle_taken(request(p, Msg::taken));
    emu_sent_to_ = taken_.next;
}

void Session::pump_emulation(std::chrono::milliseconds wait) {
    keep_alive();
    // A few packets a turn: on a slow link the adapter's news could otherwise keep this side listening
    // for ever, and its keep-alives unsent.
    auto got = receive(wait);
    for (int n = 1; got; ++n) {
        heard();
        handle(*got);
        got = n < 16 ? receive(0ms) : std::nullopt;
    }
    keep_alive();
    if (clock::now() - last_heard_ > t_.silent)
        fail(std::uint64_t{taken_.taken} + 1, silence("the adapter stopped answering: time-out"));
}

std::vector<std::uint8_t> Session::echo(std::span<const std::uint8_t> payload) {
    Packet p;
    p.type = static_cast<std::uint8_t>(Msg::echo);
    p.length = static_cast<std::uint8_t>(std::min(payload.size(), tapefw::max_payload));
    std::copy_n(payload.begin(), p.length, p.payload);
    Packet r = request(p, Msg::echo_reply);
    return {r.payload, r.payload + r.length};
}

}  // namespace tape::adapter
