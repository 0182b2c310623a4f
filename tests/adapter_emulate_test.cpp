// The adapter's emulate role in its firmware core, on a virtual clock: the test plays the host with
// packets, the simulated control (tools/adapter_sim/sim_control) reads through the board's strobe and
// stops and starts the reader.
#include <gtest/gtest.h>

#include <algorithm>

#include "engine_host.hpp"

using namespace tapefw;
using engine_host::Bench;
using engine_host::test_tape;

namespace {

Identity emulator() {
    Identity id;
    id.capabilities |= caps::emulate;
    return id;
}

tapesim::SimOptions with_control(tapesim::ControlOptions c = {}) {
    tapesim::SimOptions o;
    o.control = c;
    return o;
}

// The host's side: frames sent by credit from the TAKEN packets, the last TAKEN kept.
struct Host {
    Bench& b;
    const std::vector<std::uint8_t>& tape;
    std::size_t limit;  ///< frames it has to give (the host stalls there)
    Taken last{};
    std::uint32_t sent = 0;

    void start() {
        auto seq = b.send(Msg::emulate);
        auto ok = b.take(Msg::ok);
        ASSERT_TRUE(ok);
        EXPECT_EQ(ok->seq, seq);
        turn();
    }
    // Takes the TAKEN packets that came, then sends what the queue has room for, and keeps the watchdog
    // quiet (with nothing left to send, frames queued last longer than its 500 ms).
    void turn() {
        b.ack(0);
        while (auto p = b.take(Msg::taken)) {
            Taken t;
            ASSERT_TRUE(t.decode(*p));
            if (t.turn != last.turn) sent = t.next;
            last = t;
        }
        std::uint32_t room = last.next + last.free;
        while (sent < std::min<std::size_t>(room, limit)) {
            Frames f;
            f.first = sent;
            f.turn = last.turn;
            f.count = static_cast<std::uint8_t>(std::min<std::size_t>({Frames::max_frames, room - sent, limit - sent}));
            std::copy_n(tape.begin() + sent, f.count, f.frames);
            Packet p;
            f.encode(p);
            b.send(p);
            sent += f.count;
        }
    }
    /// Runs the clock us on, the host taking its turn every 5 ms.
    void run(std::uint64_t us) {
        for (std::uint64_t t = 0; t < us; t += 5000) {
            b.run(5000);
            turn();
        }
    }
};

std::uint8_t configure_wiring(Bench& b, const Wiring& w) {
    Packet p;
    w.encode(p);
    return b.send(p);
}

// The adapter wired as w (which it must accept) and a host giving it the whole tape, for us microseconds
// of the clock: the control's frames are then in b.hw.control().
void emulate_wired(Bench& b, const Wiring& w, const std::vector<std::uint8_t>& tape, std::uint64_t us) {
    configure_wiring(b, w);
    ASSERT_TRUE(b.take(Msg::ok));
    Host h{b, tape, tape.size()};
    h.start();
    h.run(us);
}

}  // namespace

TEST(AdapterEmulate, AnAdapterWithoutTheRoleRefusesIt) {
    Bench b({}, with_control());
    b.send(Msg::emulate);
    auto e = b.take(Msg::error);
    ASSERT_TRUE(e);
    ErrorReply r;
    ASSERT_TRUE(r.decode(*e));
    EXPECT_EQ(r.code, ErrorCode::no_emulator);
}

TEST(AdapterEmulate, EveryFrameIsTakenOnceInOrderAndAStopWithinTheBrakingDistance) {
    auto tape = test_tape(60000);
    for (std::uint8_t braking : {0, 1, 2}) {
        Bench b({}, with_control({.stops = 40, .seed = braking + 1u, .stop_at_program_end = false}), emulator());
        Wiring w;
        w.braking = braking;
        ASSERT_NO_FATAL_FAILURE(emulate_wired(b, w, tape, 45'000'000));
        const auto* c = b.hw.control();
        ASSERT_EQ(c->taken().size(), tape.size()) << "braking " << int(braking);
        EXPECT_EQ(c->taken(), tape);
        EXPECT_EQ(b.engine.frames_taken(), tape.size());
        ASSERT_EQ(c->frames_after_stop().size(), 40u);
        auto most = *std::max_element(c->frames_after_stop().begin(), c->frames_after_stop().end());
        EXPECT_EQ(most, braking) << "braking " << int(braking);
        EXPECT_LE(c->longest_restart_us(), 2000u);
        // Running, a frame every slot: the host never let the queue run dry.
        EXPECT_LE(c->longest_gap_us(), w.period_us() + 1);
    }
}

TEST(AdapterEmulate, AHostThatStallsHoldsTheStrobeAndNoFrameIsWrongOrDoubled) {
    auto tape = test_tape(6000);
    Bench b({}, with_control(), emulator());
    Packet p;
    Config slow;
    slow.watchdog_ms = 5000;
    slow.encode(p);
    b.send(p);
    ASSERT_TRUE(b.take(Msg::ok));
    Host h{b, tape, 1000};
    h.start();
    h.run(2'000'000);  // the host has given 1000 frames and stalls for more than a second
    EXPECT_EQ(b.hw.control()->taken().size(), 1000u);
    h.limit = tape.size();
    h.run(4'000'000);
    EXPECT_EQ(b.hw.control()->taken(), tape);
    EXPECT_GE(b.hw.control()->longest_gap_us(), 1'000'000u);
}

TEST(AdapterEmulate, TheWatchdogStopsTheFramesAndSaysSoAgainAfterTheNextReset) {
    auto tape = test_tape(6000);
    Bench b({}, with_control(), emulator());
    Host h{b, tape, 3000};
    h.start();
    h.run(1'000'000);
    std::size_t taken = b.hw.control()->taken().size();
    EXPECT_NEAR(static_cast<double>(taken), 1500, 10);  // a frame a slot at 1500 frames/s, after the start delay
    b.run(1'000'000);  // the host is gone: silent for longer than the watchdog's 500 ms
    auto s = b.take(Msg::status);
    ASSERT_TRUE(s);
    Status st;
    ASSERT_TRUE(st.decode(*s));
    EXPECT_TRUE(st.bits & status::watchdog);
    EXPECT_FALSE(b.engine.emulating());
    EXPECT_EQ(st.frame, b.hw.control()->taken().size());
    EXPECT_LT(b.hw.control()->taken().size(), 3000u);  // the frames queued were not given
    b.inbox.clear();
    b.send(Msg::reset);  // a host again
    ASSERT_TRUE(b.take(Msg::ok));
    auto again = b.take(Msg::status);
    ASSERT_TRUE(again);
    Status st2;
    ASSERT_TRUE(st2.decode(*again));
    EXPECT_TRUE(st2.bits & status::watchdog);
    EXPECT_EQ(st2.frame, st.frame);
}

TEST(AdapterEmulate, AControlsTurnDropsTheQueueAndFramesForTheOldWayAreRefused) {
    auto tape = test_tape(2000);
    Bench b({}, with_control({.running = false}), emulator());
    Host h{b, tape, tape.size()};
    h.start();
    h.run(50'000);
    EXPECT_EQ(h.last.next, Engine::emulate_ring);
    b.engine.on_drive(drive_bit::reverse);  // the control turns the reader (stopped)
    b.run(1000);
    auto p = b.take(Msg::taken);
    ASSERT_TRUE(p);
    Taken t;
    ASSERT_TRUE(t.decode(*p));
    EXPECT_EQ(t.turn, 1);
    EXPECT_EQ(t.next, 0u);
    EXPECT_EQ(t.drive, drive_bit::reverse);
    // A FRAMES sent before the host heard of the turn is not queued.
    Frames old;
    old.count = 10;
    Packet q;
    old.encode(q);
    b.send(q);
    auto reply = b.take(Msg::taken);
    ASSERT_TRUE(reply);
    ASSERT_TRUE(t.decode(*reply));
    EXPECT_EQ(t.next, 0u);
    old.turn = 1;
    old.encode(q);
    b.send(q);
    reply = b.take(Msg::taken);
    ASSERT_TRUE(reply && t.decode(*reply));
    EXPECT_EQ(t.next, 10u);
}

TEST(AdapterEmulate, DiscardDropsOnlyFramesNotYetTaken) {
    auto tape = test_tape(2000);
    Bench b({}, with_control(), emulator());
    Host h{b, tape, 400};
    h.start();
    h.run(100'000);  // 150 frames taken, 250 queued
    Packet p;
    Discard{10}.encode(p);
    b.send(p);
    auto r = b.take(Msg::taken);
    ASSERT_TRUE(r);
    Taken t;
    ASSERT_TRUE(t.decode(*r));
    EXPECT_EQ(t.next, t.taken);
    EXPECT_GE(t.taken, 140u);
    b.run(100'000);
    EXPECT_EQ(b.hw.control()->taken().size(), t.taken);
}

TEST(AdapterEmulate, AWiringThatCannotWorkIsRefusedAndNoneWhileEmulating) {
    Bench b({}, with_control(), emulator());
    Wiring w;
    w.setup_us = 600;  // with a strobe of 100 us: longer than a frame at 1500 frames/s
    configure_wiring(b, w);
    auto e = b.take(Msg::error);
    ASSERT_TRUE(e);
    EXPECT_STREQ(w.problem(), "set-up, strobe and hold take longer than a frame at this rate");
    Wiring shared;
    shared.run_pin = shared.data_pins[3];
    EXPECT_STREQ(shared.problem(), "two lines on one pin");
    b.send(Msg::emulate);
    ASSERT_TRUE(b.take(Msg::ok));
    configure_wiring(b, Wiring{});
    e = b.take(Msg::error);
    ASSERT_TRUE(e);
    ErrorReply r;
    ASSERT_TRUE(r.decode(*e));
    EXPECT_EQ(r.code, ErrorCode::busy);
}

TEST(AdapterEmulate, TheDataLinesCarryTheFramesInvertedAsWiredAndMaskedToTheTracks) {
    auto tape = test_tape(600);
    Bench b({}, with_control(), emulator());
    Wiring w;
    w.data_invert = 0x0F;
    w.tracks = 7;
    w.data_pins[7] = Wiring::no_pin;
    ASSERT_NO_FATAL_FAILURE(emulate_wired(b, w, tape, 1'000'000));
    std::vector<std::uint8_t> seven(tape.size());
    std::transform(tape.begin(), tape.end(), seven.begin(), [](std::uint8_t f) { return f & 0x7F; });
    EXPECT_EQ(b.hw.control()->taken(), seven);
}

TEST(AdapterEmulate, AfterADiscardUntilStartTheFramesWaitForTheControlsNextStartUnlessItCameAlready) {
    auto tape = test_tape(3000);
    Bench b({}, with_control({.running = false}), emulator());
    Host h{b, tape, 100};
    h.start();
    b.engine.on_drive(drive_bit::run);
    h.run(200'000);  // the control takes the 100 frames given and waits for more
    ASSERT_EQ(b.hw.control()->taken().size(), 100u);
    Packet p;
    Discard{100, 1}.encode(p);
    b.send(p);
    h.limit = 200;
    h.run(200'000);  // still running since before frame 100: the new frames wait
    EXPECT_EQ(b.engine.frames_taken(), 100u);
    b.engine.on_drive(0);
    b.engine.on_drive(drive_bit::run);  // stopped and started again: they go
    h.run(200'000);
    EXPECT_EQ(b.engine.frames_taken(), 200u);
    // A start that came after the last frame before `from` was taken counts: no wait.
    b.engine.on_drive(0);
    b.engine.on_drive(drive_bit::run);
    Discard{200, 1}.encode(p);
    b.send(p);
    h.limit = 300;
    h.run(200'000);
    EXPECT_EQ(b.engine.frames_taken(), 300u);
}
