// The engine's emulate role: standing in for a tape reader toward a control. The host's frames are
// queued by credit; the board's frame clock takes one a slot while the control's start line is on.
// The control's stop is obeyed here, in the interrupts, within Wiring::braking frames: no round trip
// to the host. An empty queue (the host behind) holds the strobe: a slow reader, never a wrong frame.
#include "core/engine.hpp"

namespace tapefw {
namespace {

bool elapsed(std::uint32_t now, std::uint32_t since, std::uint32_t us) { return now - since >= us; }

constexpr std::uint8_t turn_lines = drive_bit::reverse | drive_bit::rewind;

}  // namespace

void Engine::on_drive(std::uint8_t lines) {
    std::uint8_t was = drive_in_;
    drive_in_ = lines;
    if (!emulating_) return;
    // Frames queued for the old way or the old place are not the control's any more: dropped, and the
    // host told by the turn counter; until it sends frames for this turn, slots hold.
    bool turned = ((was ^ lines) & turn_lines) != 0;
    if (turned) {
        turn_ = static_cast<std::uint8_t>(turn_ + 1);
        emu_next_ = emu_taken_;
    }
    // Counted apart: a rewind set and released between two reports is still seen.
    if (lines & ~was & drive_bit::rewind) rewinds_ = static_cast<std::uint8_t>(rewinds_ + 1);
    if ((was & drive_bit::run) && !(lines & drive_bit::run)) {
        stops_ = static_cast<std::uint16_t>(stops_ + 1);
        braking_left_ = turned ? 0 : wiring_.braking;
    }
    if (!(was & drive_bit::run) && (lines & drive_bit::run)) {
        braking_left_ = 0;
        started_at_ = emu_taken_;
        until_start_ = false;
        hw_.frame_clock(wiring_.start_delay_us);
    }
}

Slot Engine::next_frame(std::uint8_t& levels) {
    if (!emulating_) return Slot::stop;
    if (!(drive_in_ & drive_bit::run)) {
        if (braking_left_ == 0) return Slot::stop;
        braking_left_ = static_cast<std::uint8_t>(braking_left_ - 1);
    }
    std::uint32_t taken = emu_taken_;
    if (taken == emu_next_ || until_start_) return Slot::hold;
    std::uint8_t mask = static_cast<std::uint8_t>((1u << wiring_.tracks) - 1);
    levels = static_cast<std::uint8_t>((emu_frames_[taken % emulate_ring] & mask) ^ wiring_.data_invert);
    emu_taken_ = taken + 1;
    return Slot::frame;
}

void Engine::set_wiring(const Packet& p) {
    if (busy()) return reply_error(p, ErrorCode::busy, 0);
    Wiring w;
    if (!w.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    wiring_ = w;
    hw_.configure_emulation(wiring_);
    reply_ok(p);
}

void Engine::start_emulation(const Packet& p) {
    if (!(id_.capabilities & caps::emulate)) return reply_error(p, ErrorCode::no_emulator, 0);
    if (busy()) return reply_error(p, ErrorCode::busy, 0);
    if (p.length != 0) return reply_error(p, ErrorCode::bad_payload, 0);
    hw_.critical(true);
    emu_taken_ = emu_next_ = 0;
    turn_ = 0;
    stops_ = 0;
    rewinds_ = 0;
    braking_left_ = 0;
    started_at_ = 0;
    until_start_ = false;
    drive_in_ = hw_.drive_inputs();
    emulating_ = true;
    hw_.critical(false);
    last_event_ = Status{};
    reply_ok(p);
    reported_ = Taken{};
    reported_.drive = 0xFF;  // reported at the next turn of the loop
    // A control already asking for frames gets them as soon as the host has sent some.
    if (drive_in_ & drive_bit::run) hw_.frame_clock(wiring_.start_delay_us);
}

void Engine::queue_frames(const Packet& p) {
    if (!emulating_) return reply_error(p, ErrorCode::not_emulating, emu_taken_);
    Frames f;
    if (!f.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    // Frames meant before the control's last turn are not for where the tape is now.
    if (f.turn != turn_) return static_cast<void>(send_taken(p.seq));
    if (f.first > emu_next_) return reply_error(p, ErrorCode::out_of_order, emu_next_);
    hw_.critical(true);
    // Frames already queued (a resend after a lost TAKEN) are taken once.
    for (std::uint32_t i = emu_next_ - f.first; i < f.count && emu_next_ - emu_taken_ < emulate_ring; ++i)
        emu_frames_[emu_next_++ % emulate_ring] = f.frames[i];
    hw_.critical(false);
    send_taken(p.seq);
}

void Engine::discard_frames(const Packet& p) {
    if (!emulating_) return reply_error(p, ErrorCode::not_emulating, emu_taken_);
    Discard d;
    if (!d.decode(p)) return reply_error(p, ErrorCode::bad_payload, 0);
    hw_.critical(true);
    std::uint32_t from = d.from > emu_taken_ ? d.from : emu_taken_;
    if (from < emu_next_) emu_next_ = from;
    if (d.until_start && started_at_ < d.from) until_start_ = true;
    hw_.critical(false);
    send_taken(p.seq);
}

void Engine::report_taken(std::uint32_t now) {
    bool changed = reported_.drive != drive_in_ || reported_.turn != turn_ || reported_.stops != stops_ ||
                   reported_.rewinds != rewinds_;
    bool moved = reported_.taken != emu_taken_ && elapsed(now, last_taken_us_, taken_every_us);
    if (changed || moved || elapsed(now, last_taken_us_, taken_idle_us)) send_taken(seq_++);
}

bool Engine::send_taken(std::uint8_t seq) {
    Taken t;
    hw_.critical(true);
    t.next = emu_next_;
    t.taken = emu_taken_;
    t.drive = drive_in_;
    t.turn = turn_;
    t.stops = stops_;
    t.rewinds = rewinds_;
    hw_.critical(false);
    t.free = static_cast<std::uint16_t>(emulate_ring - (t.next - t.taken));
    Packet out;
    t.encode(out);
    out.seq = seq;
    if (!send_packet(out)) return false;
    reported_ = t;
    last_taken_us_ = hw_.now_us();
    return true;
}

}  // namespace tapefw
