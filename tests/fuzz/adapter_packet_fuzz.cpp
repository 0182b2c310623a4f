// libFuzzer target: any bytes as the CDC stream into a tape adapter (firmware/core). Every packet the
// stream decoder gives back passed its CRC and re-encodes to the same bytes; every message a packet
// decodes to encodes back to the same packet; and the adapter's engine (with the emulate role, the
// control's lines and frame slots driven from the same bytes) takes the whole stream as host input
// without going wrong (its buffers stay in bounds: ASan and UBSan watch).
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "core/engine.hpp"
#include "core/packet.hpp"
#include "core/protocol.hpp"

namespace {

using namespace tapefw;

// The lowest level only: a board whose clock moves on by a millisecond at each call, a reader that
// never gives a row unless told to, a punch always ready.
struct FuzzBoard final : Hardware {
    std::uint32_t t = 0;
    std::uint32_t now_us() override { return t += 1000; }
    bool send(const std::uint8_t* bytes, std::size_t n) override {
        // What the engine sends is always well-formed.
        StreamDecoder d;
        for (std::size_t i = 0; i < n; ++i)
            if (d.feed(bytes[i]) == StreamDecoder::Event::fault) __builtin_trap();
        return true;
    }
    void drive(Drive) override {}
    bool punch_ready() override { return true; }
    void punch(std::uint8_t) override {}
    std::uint16_t status_lines() override { return 0; }
    void configure(const Config& c) override {
        if (c.tracks < 5 || c.tracks > 8) __builtin_trap();
    }
};

bool same(const Packet& a, const Packet& b) {
    return a.type == b.type && a.length == b.length && std::memcmp(a.payload, b.payload, a.length) == 0;
}

// A message decoded from p must encode back to p's payload.
template <typename M>
void round_trip(const Packet& p) {
    M m;
    if (!m.decode(p)) return;
    Packet back;
    if (!m.encode(back)) __builtin_trap();
    if (!same(p, back)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    StreamDecoder d;
    for (std::size_t i = 0; i < size; ++i) {
        if (d.feed(data[i]) != StreamDecoder::Event::packet) continue;
        const Packet& p = d.packet();
        std::uint8_t raw[max_packet];
        std::size_t n = encode_packet(p, raw);
        Packet again;
        if (decode_packet(raw, n, again) != PacketFault::none || !same(p, again)) __builtin_trap();
        round_trip<Config>(p);
        round_trip<ReadStart>(p);
        // Rows' flag pairs may come in any order and with zero flags: they come back sorted, so only
        // a second round is exact.
        Rows rows;
        Packet once, twice;
        if (rows.decode(p) && rows.encode(once) && (!rows.decode(once) || !rows.encode(twice) || !same(once, twice)))
            __builtin_trap();
        round_trip<Punch>(p);
        round_trip<Credit>(p);
        round_trip<Feed>(p);
        round_trip<Status>(p);
        round_trip<ErrorReply>(p);
        round_trip<Ok>(p);
        round_trip<Wiring>(p);
        round_trip<Frames>(p);
        round_trip<Discard>(p);
        round_trip<Taken>(p);
        Info info;
        if (info.decode(p) && info.protocol == protocol_version) {
            Packet back;
            // The serial is NUL-terminated text: a payload with a zero in it does not come back whole.
            if (info.encode(back) && std::memchr(p.payload + 15, 0, p.length > 15 ? p.length - 15 : 0) == nullptr &&
                !same(p, back))
                __builtin_trap();
        }
    }
    FuzzBoard board;
    Identity id;
    id.capabilities |= caps::emulate;
    Engine engine(board, id);
    // The stream in pieces, with the engine's turn and a row from the reader between them.
    for (std::size_t at = 0; at < size; at += 17) {
        engine.receive(data + at, size - at < 17 ? size - at : 17);
        engine.on_row(data[at]);
        // The control's lines and a frame slot, from the same bytes: the emulate role's interrupts.
        engine.on_drive(static_cast<std::uint8_t>(data[at] >> 5));
        std::uint8_t levels = 0;
        engine.next_frame(levels);
        engine.poll();
    }
    return 0;
}
