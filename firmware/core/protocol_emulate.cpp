// The emulate role's messages (WIRING, FRAMES, DISCARD, TAKEN): their payloads and the wiring's checks.
#include <initializer_list>

#include "core/payload.hpp"
#include "core/protocol.hpp"

namespace tapefw {

using payload::is;
using payload::Reader;
using payload::Writer;

bool Wiring::encode(Packet& p) const {
    Writer w(p, Msg::wiring);
    for (auto pin : data_pins) w.u8(pin);
    for (auto v : {strobe_pin, run_pin, reverse_pin, rewind_pin, data_invert, lines, tracks, braking}) w.u8(v);
    for (auto v : {rate, strobe_us, setup_us, hold_us, start_delay_us}) w.u16(v);
    return w.ok;
}

bool Wiring::decode(const Packet& p) {
    if (!is(p, Msg::wiring)) return false;
    Reader r{p};
    Wiring c;
    for (auto& pin : c.data_pins) pin = r.u8();
    for (auto* v :
         {&c.strobe_pin, &c.run_pin, &c.reverse_pin, &c.rewind_pin, &c.data_invert, &c.lines, &c.tracks, &c.braking})
        *v = r.u8();
    for (auto* v : {&c.rate, &c.strobe_us, &c.setup_us, &c.hold_us, &c.start_delay_us}) *v = r.u16();
    if (!r.done() || c.problem()) return false;
    *this = c;
    return true;
}

const char* Wiring::problem() const {
    if (tracks < 5 || tracks > 8) return "tracks: not 5 to 8";
    if (braking > max_braking) return "braking: not 0 to 2 frames";
    if (rate < 1 || rate > 4000) return "rate: not 1 to 4000 frames a second";
    if (strobe_us == 0) return "the strobe has no width";
    if (std::uint32_t{setup_us} + strobe_us + hold_us > period_us())
        return "set-up, strobe and hold take longer than a frame at this rate";
    // Every line in use on a pin of its own; data, strobe and start/stop are required.
    std::uint8_t used[4 + 8] = {strobe_pin, run_pin, reverse_pin, rewind_pin};
    for (std::uint8_t i = 0; i < tracks; ++i) used[4 + i] = data_pins[i];
    std::uint8_t n = static_cast<std::uint8_t>(4 + tracks);
    for (std::uint8_t i = 0; i < n; ++i) {
        bool optional = i == 2 || i == 3;
        if (used[i] == no_pin && optional) continue;
        if (used[i] > max_pin) return "a pin number is not 0 to 63";
        for (std::uint8_t k = 0; k < i; ++k)
            if (used[k] == used[i]) return "two lines on one pin";
    }
    return nullptr;
}

bool Frames::encode(Packet& p) const {
    if (count > max_frames) return false;
    Writer w(p, Msg::frames);
    w.u32(first);
    w.u8(turn);
    for (std::size_t i = 0; i < count; ++i) w.u8(frames[i]);
    return w.ok;
}

bool Frames::decode(const Packet& p) {
    if (!is(p, Msg::frames) || p.length < 5) return false;
    Reader r{p};
    first = r.u32();
    turn = r.u8();
    count = static_cast<std::uint8_t>(p.length - 5);
    for (std::size_t i = 0; i < count; ++i) frames[i] = r.u8();
    return r.done();
}

bool Discard::encode(Packet& p) const {
    Writer w(p, Msg::discard);
    w.u32(from);
    w.u8(until_start);
    return w.ok;
}

bool Discard::decode(const Packet& p) {
    if (!is(p, Msg::discard)) return false;
    Reader r{p};
    from = r.u32();
    until_start = r.u8();
    return r.done() && until_start <= 1;
}

bool Taken::encode(Packet& p) const {
    Writer w(p, Msg::taken);
    w.u32(next);
    w.u32(taken);
    w.u16(free);
    w.u8(drive);
    w.u8(turn);
    w.u16(stops);
    w.u8(rewinds);
    return w.ok;
}

bool Taken::decode(const Packet& p) {
    if (!is(p, Msg::taken)) return false;
    Reader r{p};
    next = r.u32();
    taken = r.u32();
    free = r.u16();
    drive = r.u8();
    turn = r.u8();
    stops = r.u16();
    rewinds = r.u8();
    return r.done() && taken <= next;
}

}  // namespace tapefw
