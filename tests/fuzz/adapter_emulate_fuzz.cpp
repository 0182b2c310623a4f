// libFuzzer target: any bytes as the adapter's CDC stream into the host's side of an EMULATE session
// (adapter::Session): the packets in it (TAKEN, STATUS, ERROR and whatever else) are taken while the
// host offers frames, and now and then discards them, as tape emulate does. The host never sends a frame
// past the room the adapter last gave, nor for another turn than the last it heard of; a fault it
// cannot go on after is an Error, never a crash (ASan and UBSan watch).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "core/packet.hpp"
#include "core/protocol.hpp"
#include "device/adapter_session.hpp"
#include "tape/error.hpp"

namespace {

using namespace tapefw;

// The adapter's side: requests answered at once as an adapter with the emulate role would, then the
// fuzzer's packets, one a receive.
class FuzzPipe final : public tape::adapter::PacketPipe {
public:
    explicit FuzzPipe(std::deque<Packet> stream) : stream_(std::move(stream)) {}
    void send(const Packet& p) override {
        switch (static_cast<Msg>(p.type)) {
            case Msg::reset:
            case Msg::emulate:
                return answer(p, [&](Packet& r) { Ok{p.type}.encode(r); });
            case Msg::get_info:
                return answer(p, [](Packet& r) {
                    Info info;
                    info.capabilities = caps::emulate;
                    info.punch_buffer = 256;
                    info.encode(r);
                });
            case Msg::discard:
                return answer(p, [this](Packet& r) {
                    Taken t = last_;
                    t.next = t.taken;
                    t.encode(r);
                });
            case Msg::frames: {
                Frames f;
                if (!f.decode(p)) __builtin_trap();
                // Within the room last given, for the turn last heard of.
                if (f.first + f.count > std::uint64_t{last_.next} + last_.free || f.turn != last_.turn)
                    __builtin_trap();
                return;
            }
            default:
                return;
        }
    }
    std::optional<Packet> receive(std::chrono::milliseconds) override {
        std::deque<Packet>& from = replies_.empty() ? stream_ : replies_;
        if (from.empty()) return std::nullopt;
        Packet p = from.front();
        from.pop_front();
        Taken t;
        if (t.decode(p)) last_ = t;
        return p;
    }
    std::uint64_t bad_packets() const override { return 0; }
    std::string name() const override { return "adapter:fuzz"; }
    bool done() const { return stream_.empty() && replies_.empty(); }

private:
    std::deque<Packet> stream_, replies_;
    Taken last_{};
    template <typename F>
    void answer(const Packet& request, F make) {
        Packet r;
        make(r);
        r.seq = request.seq;
        replies_.push_back(r);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::deque<Packet> stream;
    StreamDecoder d;
    for (std::size_t i = 0; i < std::min<std::size_t>(size, 16384); ++i)
        if (d.feed(data[i]) == StreamDecoder::Event::packet) stream.push_back(d.packet());
    auto owned = std::make_unique<FuzzPipe>(std::move(stream));
    FuzzPipe* pipe = owned.get();
    std::vector<std::uint8_t> tape(4096);
    for (std::size_t i = 0; i < tape.size(); ++i) tape[i] = static_cast<std::uint8_t>(i);
    try {
        tape::adapter::Session s(std::move(owned));
        s.start_emulation();
        for (int turn = 0; !pipe->done() && turn < 10000; ++turn) {
            std::uint32_t base = std::min<std::uint32_t>(s.taken().taken, static_cast<std::uint32_t>(tape.size()));
            s.offer(base, {tape.data() + base, tape.size() - base});
            s.pump_emulation(std::chrono::milliseconds(0));
            if (turn % 8 == 7) s.discard(s.taken().taken, turn % 16 == 15);
        }
    } catch (const tape::Error&) {  // a fault the host reports: the end of the session, as it should be
    }
    return 0;
}
