// libFuzzer target: the host's side of the tape adapter protocol (src/device/adapter_session.cpp)
// against a hostile device. The first byte picks what the host does (read, punch, configure and echo,
// feed); the rest is what the adapter answers, record by record:
//     flags (1) | type (1) | length (1) | payload (length, at most 56)
// flags bit 0: the packet carries the seq of the host's last packet (else flags & 0xF8); bit 1: it
// failed its CRC (counted, skipped); bit 2: nothing came in time. When the records run out the adapter
// is gone. Whatever comes, the host ends with Error(Errc::io) or a result, never loops and never
// reads out of bounds; rows it gives are in order, each once, and its memory stays bounded.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "device/adapter_session.hpp"
#include "tape/error.hpp"

namespace {

using tapefw::Packet;

class FuzzPipe : public tape::adapter::PacketPipe {
public:
    explicit FuzzPipe(std::span<const std::uint8_t> data) : data_(data) {}
    void send(const Packet& p) override {
        last_seq_ = p.seq;
        if (++sent_ > 200000) throw tape::adapter::adapter_gone(name());  // a host that only talks
    }
    std::optional<Packet> receive(std::chrono::milliseconds) override {
        for (;;) {
            if (data_.size() < 3) throw tape::adapter::adapter_gone(name());
            std::uint8_t flags = data_[0];
            Packet p;
            p.type = data_[1];
            p.length =
                static_cast<std::uint8_t>(std::min<std::size_t>({data_[2], tapefw::max_payload, data_.size() - 3}));
            std::copy_n(data_.begin() + 3, p.length, p.payload);
            p.seq = (flags & 1) ? last_seq_ : static_cast<std::uint8_t>(flags & 0xF8);
            data_ = data_.subspan(3 + p.length);
            if (flags & 2) {
                ++bad_;
                continue;
            }
            if (flags & 4) return std::nullopt;
            return p;
        }
    }
    std::uint64_t bad_packets() const override { return bad_; }
    std::string name() const override { return "fuzz"; }

private:
    std::span<const std::uint8_t> data_;
    std::uint8_t last_seq_ = 0;
    std::uint64_t bad_ = 0, sent_ = 0;
};

void read_all(tape::adapter::Session& s, bool reverse) {
    tapefw::ReadStart start;
    start.reverse = reverse;
    std::uint8_t buffer[300];
    std::uint64_t total = 0;
    for (;;) {
        tape::ReadResult r = s.read(buffer, std::chrono::milliseconds(5), start);
        total += r.count;
        if (total != s.rows_read() && total > s.rows_read()) __builtin_trap();  // given before they came
        if (r.end) break;
    }
    if (s.take_doubts().size() > tape::adapter::Session::max_doubts) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    std::uint8_t mode = data[0];
    try {
        tape::adapter::Session s(std::make_unique<FuzzPipe>(std::span(data + 1, size - 1)));
        switch (mode % 4) {
            case 0:
                read_all(s, mode & 0x10);
                break;
            case 1: {
                std::vector<std::uint8_t> rows(1 + (mode >> 2) * 9, 0x55);
                s.punch(rows);
                s.drain();
                if (s.rows_punched() < rows.size()) __builtin_trap();
                break;
            }
            case 2: {
                s.configure(tapefw::Config{});
                std::vector<std::uint8_t> payload(mode >> 2, 0xA5);
                s.echo(payload);
                break;
            }
            default:
                s.feed(static_cast<std::uint16_t>(mode >> 2));
                break;
        }
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::io) __builtin_trap();
    }
    return 0;
}
