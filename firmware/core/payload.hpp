// Payload writing and reading for the message structs (protocol.cpp, protocol_emulate.cpp): little-endian,
// with bounds, so that a short payload fails instead of reading past it.
#pragma once

#include "core/protocol.hpp"

namespace tapefw::payload {

struct Writer {
    Packet& p;
    explicit Writer(Packet& packet, Msg type) : p(packet) {
        p.type = static_cast<std::uint8_t>(type);
        p.length = 0;
    }
    bool ok = true;
    void u8(std::uint8_t v) {
        if (p.length >= max_payload) {
            ok = false;
            return;
        }
        p.payload[p.length++] = v;
    }
    void u16(std::uint16_t v) {
        u8(static_cast<std::uint8_t>(v));
        u8(static_cast<std::uint8_t>(v >> 8));
    }
    void u32(std::uint32_t v) {
        u16(static_cast<std::uint16_t>(v));
        u16(static_cast<std::uint16_t>(v >> 16));
    }
};

struct Reader {
    const Packet& p;
    std::size_t at = 0;
    bool ok = true;
    std::uint8_t u8() {
        if (at >= p.length) {
            ok = false;
            return 0;
        }
        return p.payload[at++];
    }
    std::uint16_t u16() {
        std::uint16_t lo = u8();
        return static_cast<std::uint16_t>(lo | (u8() << 8));
    }
    std::uint32_t u32() {
        std::uint32_t lo = u16();
        return lo | (static_cast<std::uint32_t>(u16()) << 16);
    }
    bool done() const { return ok && at == p.length; }
};

inline bool is(const Packet& p, Msg type) { return p.type == static_cast<std::uint8_t>(type); }

}  // namespace tapefw::payload
