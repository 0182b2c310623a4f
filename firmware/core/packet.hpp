// Packets of the tape adapter protocol (docs/adapter-protocol.md), the same on every transport:
//
//   type (1) | seq (1) | length (1) | payload (length, at most 56) | CRC-16/CCITT-FALSE (2, low byte first)
//
// the CRC over type, seq, length and payload. On a byte stream (CDC serial) a packet travels COBS
// encoded and ends with a zero byte: at most 63 + 1 = 64 bytes, one full-speed USB packet. In a
// 64-byte HID report or on a bulk endpoint it travels as it is, one packet per transfer.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tapefw {

inline constexpr std::size_t max_payload = 56;
inline constexpr std::size_t packet_overhead = 5;  ///< type, seq, length, CRC
inline constexpr std::size_t max_packet = max_payload + packet_overhead;
/// A COBS-framed packet with its terminating zero.
inline constexpr std::size_t max_framed = max_packet + max_packet / 254 + 2;

struct Packet {
    std::uint8_t type = 0;
    std::uint8_t seq = 0;
    std::uint8_t length = 0;
    std::uint8_t payload[max_payload] = {};
};

/// Why bytes are no packet.
enum class PacketFault : std::uint8_t {
    none,
    framing,    ///< not a COBS encoding
    too_short,  ///< fewer bytes than a header and a CRC
    too_long,   ///< more bytes than the longest packet
    length,     ///< the length byte disagrees with the bytes received
    crc,        ///< the CRC does not match
};

/// The packet as bytes, CRC appended, into out (room for max_packet). Returns the bytes written.
std::size_t encode_packet(const Packet& p, std::uint8_t* out);
/// Checks and unpacks n bytes holding exactly one packet.
PacketFault decode_packet(const std::uint8_t* in, std::size_t n, Packet& p);

/// Checks and unpacks one packet at the start of a fixed-size transfer (a 64-byte HID report), whose
/// bytes after the packet are padding: the length byte says where the packet ends.
PacketFault decode_report(const std::uint8_t* in, std::size_t n, Packet& p);
/// Bytes in a HID report (without the report id byte): every packet fits one.
inline constexpr std::size_t report_size = 64;

/// The packet COBS-encoded with its terminating zero, into out (room for max_framed). Returns the bytes written.
std::size_t frame_packet(const Packet& p, std::uint8_t* out);

/// Takes a byte stream one byte at a time and gives back the packets in it. Bytes that make no packet
/// are reported once per zero-terminated run and skipped: the next zero puts it back in step.
class StreamDecoder {
public:
    enum class Event : std::uint8_t { none, packet, fault };
    /// Feeds one byte. On Event::packet the packet is in packet(); on Event::fault the reason is in fault().
    Event feed(std::uint8_t byte);
    const Packet& packet() const { return packet_; }
    PacketFault fault() const { return fault_; }
    /// Forgets a partial packet (after a reset).
    void clear() {
        used_ = 0;
        overflow_ = false;
    }

private:
    std::uint8_t buffer_[max_framed] = {};
    std::size_t used_ = 0;
    bool overflow_ = false;
    Packet packet_{};
    PacketFault fault_ = PacketFault::none;
};

}  // namespace tapefw
