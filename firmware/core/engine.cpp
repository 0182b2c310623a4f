#include "core/engine.hpp"

namespace tapefw {
namespace {

constexpr std::uint16_t line_faults = status::tape_out | status::low_tape | status::chad_full | status::motor_fault |
                                      status::offline | status::punch_tape_out;
// What stops the punch: low tape is a warning only.
constexpr std::uint16_t punch_faults =
    status::punch_tape_out | status::chad_full | status::motor_fault | status::offline;

bool elapsed(std::uint32_t now, std::uint32_t since, std::uint32_t us) { return now - since >= us; }

}  // namespace

Engine::Engine(Hardware& hw, const Identity& id, Framing framing, const Config& defaults)
    : hw_(hw), id_(id), framing_(framing), config_(defaults) {
    hw_.configure(config_);
    hw_.configure_emulation(wiring_);
    hw_.drive(Drive::stop);
    last_status_ = static_cast<std::uint16_t>(hw_.status_lines() & line_faults);
}

void Engine::receive(const std::uint8_t* bytes, std::size_t n) {
    if (framing_ == Framing::packets) {
        Packet p;
        // A HID report comes padded to its fixed size; a bulk transfer holds the packet alone.
        if (decode_report(bytes, n, p) == PacketFault::none) {
            handle(p);
        } else {
            ++bad_packets_;
            reply_error(Packet{}, ErrorCode::bad_packet, 0);
        }
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
        switch (decoder_.feed(bytes[i])) {
            case StreamDecoder::Event::packet:
                handle(decoder_.packet());
                break;
            case StreamDecoder::Event::fault:
                ++bad_packets_;
                reply_error(Packet{}, ErrorCode::bad_packet, 0);
                break;
            case StreamDecoder::Event::none:
                break;
        }
    }
}

void Engine::on_row(std::uint8_t lines, std::uint8_t flags) {
    std::uint32_t head = head_;
    if (read_free() == 0) {
        if (!overrun_) overrun_frame_ = head;
        overrun_ = true;
        return;
    }
    std::uint8_t mask = static_cast<std::uint8_t>((1u << config_.tracks) - 1);
    rows_[head % read_ring] = static_cast<std::uint8_t>((lines ^ config_.data_invert) & mask);
    flags_[head % read_ring] = flags;
    last_row_us_ = hw_.now_us();
    head_ = head + 1;
    ++window_rows_;
}

void Engine::poll() {
    flush_outbox();
    std::uint32_t now = hw_.now_us();
    std::uint16_t lines = static_cast<std::uint16_t>(hw_.status_lines() & line_faults);

    if (config_.watchdog_ms && host_seen_ && busy() &&
        elapsed(now, last_host_us_, static_cast<std::uint32_t>(config_.watchdog_ms) * 1000)) {
        std::uint32_t frame = reading_ ? head_ : emulating_ ? emu_taken_ : punched_;
        stop_all();
        send_rows(true);
        send_status(status::watchdog, frame);
        orphan_ = last_event_;
    }
    if (emulating_) report_taken(now);
    if (reading_) watch_reading(now, lines);
    if (punch_queued() || feed_left_) drive_punch(lines);
    if (punched_ != credited_punched_ &&
        (elapsed(now, last_credit_us_, credit_every_us) || (!punch_queued() && !feed_left_)))
        send_credit(seq_++);

    if (overrun_) {
        overrun_ = false;
        reply_error(Packet{}, ErrorCode::overrun, overrun_frame_);
    }
    send_rows(elapsed(now, last_rows_sent_us_, rows_flush_us));
    if (lines != last_status_) {
        last_status_ = lines;
        send_status(0, head_);
    }
}

// The sprocket interrupt may store a row's time after poll() read `now`: a row newer than now is 0 µs old
// (now - last would wrap to a time-out, and end a good read as torn tape).
std::uint32_t Engine::since_row(std::uint32_t now) const {
    std::uint32_t age = now - last_row_us_;
    return age > 0x80000000u ? 0 : age;
}

void Engine::watch_reading(std::uint32_t now, std::uint16_t lines) {
    std::uint32_t read = head_ - start_frame_;
    if (lines & (status::tape_out | status::motor_fault | status::offline)) {
        end_read(0);
        last_status_ = lines;
    } else if (max_rows_ && read >= max_rows_) {
        end_read(status::read_done);
    } else if (driving_ && since_row(now) >= static_cast<std::uint32_t>(config_.sprocket_timeout_ms) * 1000) {
        end_read(status::torn);
    } else {
        if (elapsed(now, window_start_us_, 1000000)) {
            window_start_us_ = now;
            window_rows_ = 0;
        }
        bool room = read_free() > (paused_ ? read_ring / 2 : stop_margin);
        paused_ = !room;
        bool rate_held = rate_ && window_rows_ >= rate_;
        set_drive(room && !rate_held);
    }
}

void Engine::drive_punch(std::uint16_t lines) {
    if (lines & punch_faults) {
        punch_tail_ = punch_next_;
        feed_left_ = 0;
        send_status(0, punched_);
        last_status_ = lines;
    } else if (hw_.punch_ready()) {
        if (punch_queued())
            hw_.punch(punch_rows_[punch_tail_++ % punch_ring]);
        else {
            hw_.punch(0);
            --feed_left_;
        }
        ++punched_;
    }
}

void Engine::handle(const Packet& p) {
    last_host_us_ = hw_.now_us();
    host_seen_ = true;
    switch (static_cast<Msg>(p.type)) {
        case Msg::get_info:
            return send_info(p);
        case Msg::config:
            return configure(p);
        case Msg::read_start:
            return start_reading(p);
        case Msg::read_stop:
            reading_ = false;
            set_drive(false);
            return reply_ok(p);
        case Msg::punch:
            return queue_punch(p);
        case Msg::feed:
            return queue_feed(p);
        case Msg::ack:
            return take_ack(p);
        case Msg::resend:
            return resend(p);
        case Msg::reset:
            return reset(p);
        case Msg::wiring:
            return set_wiring(p);
        case Msg::emulate:
            return start_emulation(p);
        case Msg::frames:
            return queue_frames(p);
        case Msg::discard:
            return discard_frames(p);
        case Msg::echo: {
            Packet out = p;
            out.type = static_cast<std::uint8_t>(Msg::echo_reply);
            return post(out);
        }
        default:
            return reply_error(p, ErrorCode::unknown_message, 0);
    }
}

void Engine::send_info(const Packet& request) {
    Info info;
    for (int i = 0; i < 3; ++i) info.firmware[i] = id_.firmware[i];
    info.capabilities = id_.capabilities;
    info.tracks = id_.tracks;
    info.max_read_rate = id_.max_read_rate;
    info.max_punch_rate = id_.max_punch_rate;
    info.read_buffer = read_ring;
    info.punch_buffer = punch_ring;
    for (std::size_t i = 0; i < sizeof info.serial - 1 && id_.serial[i]; ++i) info.serial[i] = id_.serial[i];
    Packet out;
    info.encode(out);
    out.seq = request.seq;
    post(out);
}

void Engine::configure(const Packet& p) {
    if (busy()) return reply_error(p, ErrorCode::busy, 0);
    Config c;
    if (!c.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    config_ = c;
    hw_.configure(config_);
    reply_ok(p);
}

void Engine::start_reading(const Packet& p) {
    if (!(id_.capabilities & caps::reader)) return reply_error(p, ErrorCode::no_reader, 0);
    if (busy()) return reply_error(p, ErrorCode::busy, reading_ ? head_ : 0);
    ReadStart r;
    if (!r.decode(p) || (r.reverse && !(id_.capabilities & caps::reverse)))
        return reply_error(p, ErrorCode::bad_payload, 0);
    head_ = 0;
    base_ = sent_ = start_frame_ = 0;
    last_event_ = Status{};
    overrun_ = paused_ = false;
    reverse_ = r.reverse;
    max_rows_ = r.max_rows;
    rate_ = r.rate;
    window_start_us_ = last_rows_sent_us_ = hw_.now_us();
    last_row_us_ = window_start_us_;
    window_rows_ = 0;
    reading_ = true;
    reply_ok(p);
    set_drive(true);
}

void Engine::queue_punch(const Packet& p) {
    if (!(id_.capabilities & caps::punch)) return reply_error(p, ErrorCode::no_punch, 0);
    if (emulating_) return reply_error(p, ErrorCode::busy, 0);
    Punch r;
    if (!r.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    if (r.first > punch_next_) return reply_error(p, ErrorCode::out_of_order, punch_next_);
    // Rows already queued (a resend after a lost CREDIT) are taken once.
    for (std::uint32_t i = punch_next_ - r.first; i < r.count && punch_queued() < punch_ring; ++i)
        punch_rows_[punch_next_++ % punch_ring] = r.rows[i];
    send_credit(p.seq);
}

void Engine::queue_feed(const Packet& p) {
    if (!(id_.capabilities & caps::punch)) return reply_error(p, ErrorCode::no_punch, 0);
    if (emulating_) return reply_error(p, ErrorCode::busy, 0);
    Feed f;
    if (!f.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    feed_left_ += f.count;
    reply_ok(p);
}

void Engine::take_ack(const Packet& p) {
    FrameNumber f;
    if (!f.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    if (f.frame > base_) base_ = f.frame < sent_ ? f.frame : sent_;
}

void Engine::resend(const Packet& p) {
    FrameNumber f;
    if (!f.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    if (f.frame < base_ || f.frame > head_) return reply_error(p, ErrorCode::resend_gone, base_);
    sent_ = f.frame;
    send_rows(true);
    // A run that ended: its STATUS may be what the host lost, so it comes again.
    if (!reading_ && last_event_.bits) send_packet_status(last_event_);
}

void Engine::reset(const Packet& p) {
    stop_all();
    head_ = 0;
    base_ = sent_ = 0;
    punch_next_ = punch_tail_ = punched_ = credited_punched_ = 0;
    overrun_ = false;
    last_event_ = Status{};
    reply_ok(p);
    // A host that was gone when the watchdog stopped its run hears of it now.
    if (orphan_.bits) send_packet_status(orphan_);
    orphan_ = Status{};
}

bool Engine::send_packet(const Packet& p) {
    std::uint8_t out[max_framed];
    std::size_t n = framing_ == Framing::stream ? frame_packet(p, out) : encode_packet(p, out);
    return hw_.send(out, n);
}

void Engine::post(const Packet& p) {
    if (outbox_n_ == 0 && send_packet(p)) return;
    // The endpoint is full: kept for the next turn. Should even the box be full, the oldest goes; the
    // host asks a request again, and a lost STATUS again with RESEND.
    if (outbox_n_ == outbox_size) {
        for (std::size_t i = 1; i < outbox_size; ++i) outbox_[i - 1] = outbox_[i];
        --outbox_n_;
    }
    outbox_[outbox_n_++] = p;
}

void Engine::flush_outbox() {
    std::size_t sent = 0;
    while (sent < outbox_n_ && send_packet(outbox_[sent])) ++sent;
    for (std::size_t i = sent; i < outbox_n_; ++i) outbox_[i - sent] = outbox_[i];
    outbox_n_ -= sent;
}

void Engine::reply_ok(const Packet& request) {
    Packet out;
    Ok{request.type}.encode(out);
    out.seq = request.seq;
    post(out);
}

void Engine::reply_error(const Packet& request, ErrorCode code, std::uint32_t frame) {
    Packet out;
    ErrorReply{code, request.type, frame}.encode(out);
    out.seq = request.type ? request.seq : seq_++;
    post(out);
}

void Engine::send_status(std::uint16_t event_bits, std::uint32_t frame) {
    Status s;
    s.bits = static_cast<std::uint16_t>(status_bits() | event_bits);
    s.frame = frame;
    last_event_ = s;
    send_packet_status(s);
}

void Engine::send_packet_status(const Status& s) {
    Packet out;
    s.encode(out);
    out.seq = seq_++;
    post(out);
}

void Engine::send_credit(std::uint8_t seq) {
    Packet out;
    Credit c;
    c.next = punch_next_;
    c.punched = punched_;
    c.free = static_cast<std::uint16_t>(punch_ring - punch_queued());
    c.encode(out);
    out.seq = seq;
    if (send_packet(out)) {
        credited_punched_ = punched_;
        last_credit_us_ = hw_.now_us();
    }
}

void Engine::send_rows(bool partial) {
    while (sent_ < head_) {
        std::uint32_t pending = head_ - sent_;
        if (pending < Rows::max_rows && !partial) return;
        Rows r;
        r.first = sent_;
        r.count = static_cast<std::uint8_t>(pending < Rows::max_rows ? pending : Rows::max_rows);
        for (std::size_t i = 0; i < r.count; ++i) {
            r.rows[i] = rows_[(sent_ + i) % read_ring];
            r.flags[i] = flags_[(sent_ + i) % read_ring];
        }
        Packet out;
        // Flagged rows take two bytes more each: fewer rows go in such a packet.
        while (!r.encode(out) && r.count > 1) --r.count;
        out.seq = seq_++;
        if (!send_packet(out)) return;
        sent_ += r.count;
        last_rows_sent_us_ = hw_.now_us();
    }
}

void Engine::set_drive(bool on) {
    if (on == driving_) return;
    driving_ = on;
    if (on) last_row_us_ = hw_.now_us();  // the sprocket time-out counts from the start
    hw_.drive(on ? (reverse_ ? Drive::reverse : Drive::forward) : Drive::stop);
}

void Engine::end_read(std::uint16_t event_bits) {
    reading_ = false;
    set_drive(false);
    // The rows still held go out before the STATUS that ends the run.
    send_rows(true);
    send_status(event_bits, head_);
}

void Engine::stop_all() {
    emulating_ = false;
    reading_ = false;
    set_drive(false);
    punch_tail_ = punch_next_;
    feed_left_ = 0;
}

std::uint16_t Engine::status_bits() {
    std::uint16_t bits = static_cast<std::uint16_t>(hw_.status_lines() & line_faults);
    if (reading_) bits |= status::reading;
    if (punch_queued() || feed_left_) bits |= status::punching;
    if (emulating_) bits |= status::emulating;
    return bits;
}

}  // namespace tapefw
