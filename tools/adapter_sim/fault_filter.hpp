// Faults injected on the simulated adapter's way out: the engine's packets (cut out of its COBS stream,
// or one per transfer), and chosen ROWS packets are dropped, sent twice or damaged before they go on the line; an INFO
// can claim another protocol version. A desync puts, before a ROWS packet, either line noise ending in
// a delimiter (a packet that fails its CRC) or the first half of that packet with no delimiter, which
// runs into the whole one after it (both lost as one bad packet), in turn; in a transfer of its own, noise.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/packet.hpp"

namespace tapesim {

struct Faults {
    std::uint64_t drop_rows_packet = 0;  ///< the K-th ROWS packet (from 1) is not sent; 0: none
    std::uint64_t drop_times = 1;        ///< ...nor its next resends, this many sendings in all
    std::uint64_t duplicate_rows_packet = 0;
    std::uint64_t corrupt_rows_packet = 0;  ///< one byte of it flipped: the host sees a CRC failure
    std::uint64_t corrupt_times = 1;        ///< ...and of its next resends, this many sendings in all
    std::uint64_t garbage_every = 0;        ///< before every K-th ROWS packet, a desync on the line; 0: none
    int protocol = -1;                      ///< INFO claims this protocol version (-1: the real one)
    std::uint64_t drop_taken_every = 0;     ///< every K-th TAKEN packet is lost on the way (emulating); 0: none
};

class FaultFilter {
public:
    explicit FaultFilter(Faults f) : f_(f) {}
    /// Takes the engine's bytes on a byte stream (CDC); appends what goes on the line to out.
    void pass(const std::uint8_t* bytes, std::size_t n, std::string& out);
    /// Takes one packet the engine sends in a transfer of its own (bulk, HID); appends the transfers
    /// that go on the wire instead (none, one, two, or one damaged) to out.
    void pass_packet(const std::uint8_t* bytes, std::size_t n, std::vector<std::vector<std::uint8_t>>& out);
    std::uint64_t rows_packets() const { return rows_packets_; }
    std::uint64_t dropped() const { return dropped_; }
    std::uint64_t corrupted() const { return corrupted_; }
    std::uint64_t desyncs() const { return desyncs_; }

private:
    Faults f_;
    tapefw::StreamDecoder decoder_;
    std::uint64_t rows_packets_ = 0, dropped_ = 0, corrupted_ = 0, desyncs_ = 0, taken_packets_ = 0;
    std::uint32_t drop_first_ = 0, corrupt_first_ = 0;  ///< the first frame of the packet hit
    /// The faults applied to one packet: emit is called for each sending of it, damaged or not, and
    /// desync once before it when a desync is due.
    void filter(tapefw::Packet p, const std::function<void(const tapefw::Packet&, bool corrupt)>& emit,
                const std::function<void(const tapefw::Packet&)>& desync);
};

}  // namespace tapesim
