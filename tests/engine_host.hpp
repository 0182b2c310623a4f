// The adapter's firmware core on a virtual clock (tools/adapter_sim's simulated units) with the test as
// its host, sending packets as bytes on the CDC stream: the engine tests' bench.
#pragma once

#include <deque>
#include <optional>
#include <vector>

#include "adapter_sim/sim_hardware.hpp"
#include "core/engine.hpp"
#include "core/packet.hpp"
#include "core/protocol.hpp"

namespace engine_host {

using namespace tapefw;

/// n frames of every value, in an order that repeats only after a long stretch.
inline std::vector<std::uint8_t> test_tape(std::size_t n) {
    std::vector<std::uint8_t> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<std::uint8_t>((i * 37 + i / 256) & 0xFF);
    return t;
}

// The adapter on a virtual clock with the test as its host.
struct Bench {
    tapesim::SimHardware hw;
    Engine engine;
    StreamDecoder decoder;
    std::deque<Packet> inbox;
    std::vector<PacketFault> faults;
    std::uint8_t seq = 0;

    Bench(std::vector<std::uint8_t> tape, tapesim::SimOptions o = {}, Identity id = {})
        : hw(std::move(tape), o), engine(hw, id) {
        hw.on_send = [this](const std::uint8_t* b, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i) {
                auto e = decoder.feed(b[i]);
                if (e == StreamDecoder::Event::packet) inbox.push_back(decoder.packet());
                if (e == StreamDecoder::Event::fault) faults.push_back(decoder.fault());
            }
            return true;
        };
    }

    std::uint8_t send(Packet p) {
        p.seq = ++seq;
        std::uint8_t out[max_framed];
        engine.receive(out, frame_packet(p, out));
        return p.seq;
    }
    std::uint8_t send(Msg type) {
        Packet p;
        p.type = static_cast<std::uint8_t>(type);
        return send(p);
    }
    /// ACK of every row before frame.
    std::uint8_t ack(std::size_t frame) {
        Packet p;
        FrameNumber{static_cast<std::uint32_t>(frame)}.encode(p, Msg::ack);
        return send(p);
    }
    /// Runs the virtual clock on by us microseconds in steps of 100.
    void run(std::uint64_t us) {
        std::uint64_t end = hw.now() + us;
        while (hw.now() < end) {
            hw.advance_to(hw.now() + 100, engine);
            engine.poll();
        }
    }
    /// The first packet of a type in the inbox, removed, or nullopt.
    std::optional<Packet> take(Msg type) {
        for (auto it = inbox.begin(); it != inbox.end(); ++it)
            if (it->type == static_cast<std::uint8_t>(type)) {
                Packet p = *it;
                inbox.erase(it);
                return p;
            }
        return std::nullopt;
    }
};

}  // namespace engine_host
