#include "core/packet.hpp"

#include "core/cobs.hpp"
#include "core/crc16.hpp"

namespace tapefw {

std::size_t encode_packet(const Packet& p, std::uint8_t* out) {
    std::size_t length = p.length > max_payload ? max_payload : p.length;
    out[0] = p.type;
    out[1] = p.seq;
    out[2] = static_cast<std::uint8_t>(length);
    for (std::size_t i = 0; i < length; ++i) out[3 + i] = p.payload[i];
    std::uint16_t crc = crc16(out, 3 + length);
    out[3 + length] = static_cast<std::uint8_t>(crc & 0xFF);
    out[4 + length] = static_cast<std::uint8_t>(crc >> 8);
    return length + packet_overhead;
}

PacketFault decode_packet(const std::uint8_t* in, std::size_t n, Packet& p) {
    if (n < packet_overhead) return PacketFault::too_short;
    if (n > max_packet) return PacketFault::too_long;
    if (in[2] != n - packet_overhead) return PacketFault::length;
    std::uint16_t crc = crc16(in, n - 2);
    if (in[n - 2] != (crc & 0xFF) || in[n - 1] != (crc >> 8)) return PacketFault::crc;
    p.type = in[0];
    p.seq = in[1];
    p.length = in[2];
    for (std::size_t i = 0; i < p.length; ++i) p.payload[i] = in[3 + i];
    return PacketFault::none;
}

PacketFault decode_report(const std::uint8_t* in, std::size_t n, Packet& p) {
    if (n < packet_overhead) return PacketFault::too_short;
    std::size_t used = in[2] + packet_overhead;
    return decode_packet(in, used < n ? used : n, p);
}

std::size_t frame_packet(const Packet& p, std::uint8_t* out) {
    std::uint8_t raw[max_packet];
    std::size_t n = encode_packet(p, raw);
    std::size_t m = cobs_encode(raw, n, out);
    out[m] = 0;
    return m + 1;
}

StreamDecoder::Event StreamDecoder::feed(std::uint8_t byte) {
    if (byte != 0) {
        if (used_ < sizeof buffer_)
            buffer_[used_++] = byte;
        else
            overflow_ = true;
        return Event::none;
    }
    std::size_t n = used_;
    bool overflow = overflow_;
    clear();
    if (n == 0) return Event::none;  // zeros between packets are allowed (a resynchronising sender)
    if (overflow) {
        fault_ = PacketFault::too_long;
        return Event::fault;
    }
    int decoded = cobs_decode(buffer_, n, buffer_);
    if (decoded < 0) {
        fault_ = PacketFault::framing;
        return Event::fault;
    }
    fault_ = decode_packet(buffer_, static_cast<std::size_t>(decoded), packet_);
    return fault_ == PacketFault::none ? Event::packet : Event::fault;
}

}  // namespace tapefw
