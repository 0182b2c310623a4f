#include "core/protocol.hpp"

#include "core/payload.hpp"

namespace tapefw {

using payload::is;
using payload::Reader;
using payload::Writer;

const char* error_name(ErrorCode code) {
    switch (code) {
        case ErrorCode::none:
            return "none";
        case ErrorCode::unknown_message:
            return "unknown message";
        case ErrorCode::bad_payload:
            return "bad payload";
        case ErrorCode::no_reader:
            return "no reader";
        case ErrorCode::no_punch:
            return "no punch";
        case ErrorCode::busy:
            return "busy";
        case ErrorCode::out_of_order:
            return "out of order";
        case ErrorCode::resend_gone:
            return "rows to resend already forgotten";
        case ErrorCode::overrun:
            return "buffer overrun";
        case ErrorCode::bad_packet:
            return "bad packet";
        case ErrorCode::no_emulator:
            return "no emulate role";
        case ErrorCode::not_emulating:
            return "not emulating";
    }
    return "unknown error";
}

bool Info::encode(Packet& p) const {
    Writer w(p, Msg::info);
    w.u8(protocol);
    for (auto v : firmware) w.u8(v);
    w.u8(capabilities);
    w.u8(tracks);
    w.u16(max_read_rate);
    w.u16(max_punch_rate);
    w.u16(read_buffer);
    w.u16(punch_buffer);
    for (std::size_t i = 0; i < sizeof serial - 1 && serial[i]; ++i) w.u8(static_cast<std::uint8_t>(serial[i]));
    return w.ok;
}

bool Info::decode(const Packet& p) {
    // The protocol version comes first in every version, so that a mismatch can always be named.
    if (!is(p, Msg::info) || p.length < 1) return false;
    Reader r{p};
    protocol = r.u8();
    if (protocol != protocol_version) return true;
    for (auto& v : firmware) v = r.u8();
    capabilities = r.u8();
    tracks = r.u8();
    max_read_rate = r.u16();
    max_punch_rate = r.u16();
    read_buffer = r.u16();
    punch_buffer = r.u16();
    std::size_t n = 0;
    while (r.ok && r.at < p.length && n < sizeof serial - 1) serial[n++] = static_cast<char>(r.u8());
    serial[n] = 0;
    return r.done();
}

bool Config::encode(Packet& p) const {
    Writer w(p, Msg::config);
    w.u8(data_invert);
    w.u8(lines);
    w.u8(tracks);
    w.u16(sample_delay_us);
    w.u16(punch_pulse_us);
    w.u16(drive_pulse_us);
    w.u16(sprocket_timeout_ms);
    w.u16(watchdog_ms);
    return w.ok;
}

bool Config::decode(const Packet& p) {
    if (!is(p, Msg::config)) return false;
    Reader r{p};
    Config c;
    c.data_invert = r.u8();
    c.lines = r.u8();
    c.tracks = r.u8();
    c.sample_delay_us = r.u16();
    c.punch_pulse_us = r.u16();
    c.drive_pulse_us = r.u16();
    c.sprocket_timeout_ms = r.u16();
    c.watchdog_ms = r.u16();
    if (!r.done() || c.tracks < 5 || c.tracks > 8 || c.sprocket_timeout_ms == 0) return false;
    *this = c;
    return true;
}

bool ReadStart::encode(Packet& p) const {
    Writer w(p, Msg::read_start);
    w.u8(reverse);
    w.u16(rate);
    w.u32(max_rows);
    return w.ok;
}

bool ReadStart::decode(const Packet& p) {
    if (!is(p, Msg::read_start)) return false;
    Reader r{p};
    reverse = r.u8();
    rate = r.u16();
    max_rows = r.u32();
    return r.done() && reverse <= 1;
}

bool FrameNumber::encode(Packet& p, Msg type) const {
    Writer w(p, type);
    w.u32(frame);
    return w.ok;
}

bool FrameNumber::decode(const Packet& p) {
    Reader r{p};
    frame = r.u32();
    return r.done();
}

bool Rows::encode(Packet& p) const {
    Writer w(p, Msg::rows);
    if (count > max_rows) return false;
    w.u32(first);
    w.u8(count);
    for (std::size_t i = 0; i < count; ++i) w.u8(rows[i]);
    for (std::size_t i = 0; i < count && w.ok; ++i)
        if (flags[i]) {
            if (p.length + 2u > max_payload) return false;
            w.u8(static_cast<std::uint8_t>(i));
            w.u8(flags[i]);
        }
    return w.ok;
}

bool Rows::decode(const Packet& p) {
    if (!is(p, Msg::rows)) return false;
    Reader r{p};
    first = r.u32();
    count = r.u8();
    if (!r.ok || count > max_rows) return false;
    for (std::size_t i = 0; i < count; ++i) {
        rows[i] = r.u8();
        flags[i] = 0;
    }
    while (r.ok && r.at < p.length) {
        std::uint8_t index = r.u8();
        std::uint8_t f = r.u8();
        if (index >= count) return false;
        flags[index] = f;
    }
    return r.done();
}

bool Punch::encode(Packet& p) const {
    if (count > max_rows) return false;
    Writer w(p, Msg::punch);
    w.u32(first);
    for (std::size_t i = 0; i < count; ++i) w.u8(rows[i]);
    return w.ok;
}

bool Punch::decode(const Packet& p) {
    if (!is(p, Msg::punch) || p.length < 4) return false;
    Reader r{p};
    first = r.u32();
    count = static_cast<std::uint8_t>(p.length - 4);
    for (std::size_t i = 0; i < count; ++i) rows[i] = r.u8();
    return r.done();
}

bool Credit::encode(Packet& p) const {
    Writer w(p, Msg::credit);
    w.u32(next);
    w.u32(punched);
    w.u16(free);
    return w.ok;
}

bool Credit::decode(const Packet& p) {
    if (!is(p, Msg::credit)) return false;
    Reader r{p};
    next = r.u32();
    punched = r.u32();
    free = r.u16();
    return r.done();
}

bool Feed::encode(Packet& p) const {
    Writer w(p, Msg::feed);
    w.u16(count);
    return w.ok;
}

bool Feed::decode(const Packet& p) {
    if (!is(p, Msg::feed)) return false;
    Reader r{p};
    count = r.u16();
    return r.done();
}

bool Status::encode(Packet& p) const {
    Writer w(p, Msg::status);
    w.u16(bits);
    w.u32(frame);
    return w.ok;
}

bool Status::decode(const Packet& p) {
    if (!is(p, Msg::status)) return false;
    Reader r{p};
    bits = r.u16();
    frame = r.u32();
    return r.done();
}

bool ErrorReply::encode(Packet& p) const {
    Writer w(p, Msg::error);
    w.u8(static_cast<std::uint8_t>(code));
    w.u8(about);
    w.u32(frame);
    return w.ok;
}

bool ErrorReply::decode(const Packet& p) {
    if (!is(p, Msg::error)) return false;
    Reader r{p};
    code = static_cast<ErrorCode>(r.u8());
    about = r.u8();
    frame = r.u32();
    return r.done();
}

bool Ok::encode(Packet& p) const {
    Writer w(p, Msg::ok);
    w.u8(about);
    return w.ok;
}

bool Ok::decode(const Packet& p) {
    if (!is(p, Msg::ok)) return false;
    Reader r{p};
    about = r.u8();
    return r.done();
}

}  // namespace tapefw
