#include "fault_filter.hpp"

#include <iterator>

#include "core/protocol.hpp"

namespace tapesim {

// Bytes that are no packet, with no zero among them (a zero would end a COBS frame).
constexpr std::uint8_t line_noise[] = {0x55, 0xAA, 0x13, 0xFF, 0x01, 0x80, 0x7E};

void FaultFilter::pass(const std::uint8_t* bytes, std::size_t n, std::string& out) {
    for (std::size_t i = 0; i < n; ++i) {
        if (decoder_.feed(bytes[i]) != tapefw::StreamDecoder::Event::packet) continue;
        filter(
            decoder_.packet(),
            [&out](const tapefw::Packet& p, bool corrupt) {
                std::uint8_t framed[tapefw::max_framed];
                std::size_t m = tapefw::frame_packet(p, framed);
                // One byte in the middle changed, never to a zero (that would cut the packet in two instead).
                if (corrupt) {
                    framed[m / 2] ^= 0x01;
                    if (framed[m / 2] == 0) framed[m / 2] = 0x02;
                }
                out.append(reinterpret_cast<const char*>(framed), m);
            },
            [this, &out](const tapefw::Packet& p) {
                if (desyncs_++ % 2 == 0) {
                    // Noise: bytes that are no packet (no zero among them), then the delimiter.
                    out.append(reinterpret_cast<const char*>(line_noise), sizeof line_noise);
                    out.push_back('\0');
                    return;
                }
                // A packet cut off: its first half, without the delimiter that would end it.
                std::uint8_t framed[tapefw::max_framed];
                std::size_t m = tapefw::frame_packet(p, framed);
                out.append(reinterpret_cast<const char*>(framed), m / 2);
            });
    }
}

void FaultFilter::pass_packet(const std::uint8_t* bytes, std::size_t n, std::vector<std::vector<std::uint8_t>>& out) {
    tapefw::Packet packet;
    if (tapefw::decode_packet(bytes, n, packet) != tapefw::PacketFault::none) {
        out.emplace_back(bytes, bytes + n);  // the engine's own bytes are always a packet; kept as they are
        return;
    }
    filter(
        packet,
        [&out](const tapefw::Packet& p, bool corrupt) {
            std::vector<std::uint8_t> raw(tapefw::max_packet);
            raw.resize(tapefw::encode_packet(p, raw.data()));
            if (corrupt) raw[raw.size() / 2] ^= 0x01;
            out.push_back(std::move(raw));
        },
        [this, &out](const tapefw::Packet&) {
            ++desyncs_;
            out.emplace_back(std::begin(line_noise), std::end(line_noise));  // a transfer that is no packet
        });
}

void FaultFilter::filter(tapefw::Packet p, const std::function<void(const tapefw::Packet&, bool)>& emit,
                         const std::function<void(const tapefw::Packet&)>& desync) {
    if (p.type == static_cast<std::uint8_t>(tapefw::Msg::info) && f_.protocol >= 0) {
        p.payload[0] = static_cast<std::uint8_t>(f_.protocol);
    }
    if (p.type == static_cast<std::uint8_t>(tapefw::Msg::taken) && f_.drop_taken_every &&
        ++taken_packets_ % f_.drop_taken_every == 0) {
        ++dropped_;
        return;
    }
    tapefw::Rows rows;
    if (!rows.decode(p)) {  // not ROWS: passed as it is
        emit(p, false);
        return;
    }
    ++rows_packets_;
    std::uint32_t first = rows.first;
    if (rows_packets_ == f_.drop_rows_packet) {
        drop_first_ = first;
        dropped_ = 0;
    }
    if (f_.drop_rows_packet && rows_packets_ >= f_.drop_rows_packet && first == drop_first_ &&
        dropped_ < f_.drop_times) {
        ++dropped_;
        return;
    }
    if (rows_packets_ == f_.corrupt_rows_packet) {
        corrupt_first_ = first;
        corrupted_ = 0;
    }
    bool corrupt = f_.corrupt_rows_packet && rows_packets_ >= f_.corrupt_rows_packet && first == corrupt_first_ &&
                   corrupted_ < f_.corrupt_times;
    if (corrupt) ++corrupted_;
    if (f_.garbage_every && rows_packets_ % f_.garbage_every == 0) desync(p);
    emit(p, corrupt);
    if (rows_packets_ == f_.duplicate_rows_packet) emit(p, false);
}

}  // namespace tapesim
