// The adapter's firmware core driven through a simulated reader and punch (tools/adapter_sim) on a
// virtual clock: the test plays the host with packets, as bytes on the CDC stream.
#include <gtest/gtest.h>

#include <deque>
#include <map>
#include <numeric>
#include <optional>
#include <vector>

#include "adapter_sim/sim_hardware.hpp"
#include "core/engine.hpp"
#include "core/packet.hpp"
#include "core/protocol.hpp"
#include "engine_host.hpp"

using namespace tapefw;
using engine_host::Bench;
using engine_host::test_tape;

namespace {

// Rows arrived in order, from first, into `into`; false at a gap or an overlap.
bool take_rows(Bench& b, std::vector<std::uint8_t>& into, std::vector<std::uint32_t>* firsts = nullptr) {
    while (auto p = b.take(Msg::rows)) {
        Rows r;
        if (!r.decode(*p) || r.first != into.size()) return false;
        if (firsts) firsts->push_back(r.first);
        into.insert(into.end(), r.rows, r.rows + r.count);
    }
    return true;
}

}  // namespace

TEST(AdapterEngine, InfoAnswersWithTheRequestsSeq) {
    Identity id;
    id.serial = "SIM00042";
    Bench b(test_tape(10), {}, id);
    std::uint8_t seq = b.send(Msg::get_info);
    auto p = b.take(Msg::info);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->seq, seq);
    Info info;
    ASSERT_TRUE(info.decode(*p));
    EXPECT_EQ(info.protocol, protocol_version);
    EXPECT_STREQ(info.serial, "SIM00042");
    EXPECT_EQ(info.max_read_rate, 1500);
    EXPECT_EQ(info.read_buffer, Engine::read_ring);
    EXPECT_EQ(info.capabilities & (caps::reader | caps::punch), caps::reader | caps::punch);
}

TEST(AdapterEngine, ReadsAWholeTapeAtTheReadersSpeedThenTapeOut) {
    auto tape = test_tape(6000);
    Bench b(tape);
    Packet p;
    ReadStart{}.encode(p);
    std::uint8_t seq = b.send(p);
    auto ok = b.take(Msg::ok);
    ASSERT_TRUE(ok);
    EXPECT_EQ(ok->seq, seq);
    std::vector<std::uint8_t> got;
    std::optional<Status> out;
    for (int ms = 0; ms < 10000 && !out; ms += 10) {
        b.run(10000);
        ASSERT_TRUE(take_rows(b, got)) << "gap or overlap at " << got.size();
        b.ack(got.size());
        if (auto s = b.take(Msg::status)) {
            Status st;
            ASSERT_TRUE(st.decode(*s));
            if (st.bits & status::tape_out) out = st;
        }
    }
    ASSERT_TRUE(out) << "no tape-out";
    EXPECT_EQ(out->frame, tape.size());
    EXPECT_EQ(got, tape);
    // 6000 frames at 1500 frames/s: 4 s, and the reader never had to stop for room.
    EXPECT_NEAR(static_cast<double>(b.hw.now()) / 1e6, 4.0, 0.1);
    EXPECT_EQ(b.hw.starts(), 1u);
    EXPECT_EQ(b.hw.drive_state(), Drive::stop);
}

TEST(AdapterEngine, AHostThatDoesNotAcknowledgeStopsTheReaderWithNothingLost) {
    auto tape = test_tape(5000);
    Bench b(tape);
    Packet p;
    ReadStart{}.encode(p);
    b.send(p);
    std::vector<std::uint8_t> got;
    // No ACK for 900 ms (the host speaks, so the watchdog stays quiet): the ring fills, the reader
    // stops with room for its stopping distance, and nothing is lost.
    for (int i = 0; i < 90; ++i) {
        b.run(10000);
        ASSERT_TRUE(take_rows(b, got));
        b.send(Msg::echo);  // keeps the watchdog quiet without acknowledging
    }
    EXPECT_LE(got.size(), Engine::read_ring);
    EXPECT_GE(got.size(), Engine::read_ring - Engine::stop_margin);
    EXPECT_EQ(b.hw.drive_state(), Drive::stop);
    EXPECT_EQ(b.engine.rows_read(), got.size());
    for (int i = 0; i < 500 && got.size() < tape.size(); ++i) {
        b.ack(got.size());
        b.run(10000);
        ASSERT_TRUE(take_rows(b, got));
    }
    EXPECT_EQ(got, tape);
    EXPECT_GT(b.hw.starts(), 1u);
    EXPECT_TRUE(!b.take(Msg::error)) << "no overrun";
}

TEST(AdapterEngine, ResendGivesTheRowsAgainFromAFrame) {
    auto tape = test_tape(400);
    Bench b(tape);
    Packet p;
    ReadStart{}.encode(p);
    b.send(p);
    b.run(100000);
    std::vector<std::uint8_t> got;
    ASSERT_TRUE(take_rows(b, got));
    ASSERT_GE(got.size(), 120u);
    b.ack(50);
    Packet resend;
    FrameNumber{100}.encode(resend, Msg::resend);
    b.send(resend);
    auto again = b.take(Msg::rows);
    ASSERT_TRUE(again);
    Rows r;
    ASSERT_TRUE(r.decode(*again));
    EXPECT_EQ(r.first, 100u);
    EXPECT_EQ(r.rows[0], tape[100]);
    // Rows acknowledged are forgotten: a resend of them is refused, naming the oldest still held.
    b.inbox.clear();
    FrameNumber{10}.encode(resend, Msg::resend);
    b.send(resend);
    auto err = b.take(Msg::error);
    ASSERT_TRUE(err);
    ErrorReply e;
    ASSERT_TRUE(e.decode(*err));
    EXPECT_EQ(e.code, ErrorCode::resend_gone);
    EXPECT_EQ(e.frame, 50u);
}

TEST(AdapterEngine, TornTapeIsReportedAtItsFrame) {
    tapesim::SimOptions o;
    o.torn_at = 700;
    Bench b(test_tape(2000), o);
    Packet p;
    ReadStart{}.encode(p);
    b.send(p);
    std::vector<std::uint8_t> got;
    std::optional<Status> torn;
    for (int i = 0; i < 200 && !torn; ++i) {
        b.run(10000);
        ASSERT_TRUE(take_rows(b, got));
        b.ack(got.size());
        if (auto s = b.take(Msg::status)) {
            Status st;
            st.decode(*s);
            if (st.bits & status::torn) torn = st;
        }
    }
    ASSERT_TRUE(torn);
    EXPECT_EQ(torn->frame, 700u);
    EXPECT_EQ(got.size(), 700u);
    EXPECT_FALSE(torn->bits & status::tape_out);
    EXPECT_EQ(b.hw.drive_state(), Drive::stop);
}

TEST(AdapterEngine, MaxRowsStopsTheReaderAndItsStoppingDistanceIsStillRead) {
    tapesim::SimOptions o;
    o.stop_frames = 3;
    auto tape = test_tape(3000);
    Bench b(tape, o);
    Packet p;
    ReadStart{0, 0, 1000}.encode(p);
    b.send(p);
    std::vector<std::uint8_t> got;
    for (int i = 0; i < 100; ++i) {
        b.run(20000);
        ASSERT_TRUE(take_rows(b, got));
        b.ack(got.size());
    }
    auto s = b.take(Msg::status);
    ASSERT_TRUE(s);
    Status st;
    st.decode(*s);
    EXPECT_TRUE(st.bits & status::read_done);
    // The rows passing the head while the reader brakes are read too: nothing skipped on a restart.
    EXPECT_GE(got.size(), 1000u);
    EXPECT_LE(got.size(), 1004u);
    EXPECT_EQ(b.hw.position(), got.size());
    EXPECT_TRUE(std::equal(got.begin(), got.end(), tape.begin()));
}

TEST(AdapterEngine, PolarityAndTracksFromConfig) {
    tapesim::SimOptions o;
    o.active_low = 0xFF;  // this unit's data lines are low for a hole
    auto tape = test_tape(300);
    Bench b(tape, o);
    Config c;
    c.data_invert = 0xFF;
    c.tracks = 5;
    Packet p;
    c.encode(p);
    b.send(p);
    ASSERT_TRUE(b.take(Msg::ok));
    EXPECT_EQ(b.hw.config().tracks, 5);
    ReadStart{}.encode(p);
    b.send(p);
    b.run(300000);
    std::vector<std::uint8_t> got;
    ASSERT_TRUE(take_rows(b, got));
    ASSERT_EQ(got.size(), tape.size());
    for (std::size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i], tape[i] & 0x1F) << i;
    // A config while reading is refused.
    b.inbox.clear();
    ReadStart{}.encode(p);
    b.send(p);
    c.encode(p);
    b.send(p);
    auto err = b.take(Msg::error);
    ASSERT_TRUE(err);
    ErrorReply e;
    e.decode(*err);
    EXPECT_EQ(e.code, ErrorCode::busy);
}

TEST(AdapterEngine, PunchesAtThePunchsRateWithCredit) {
    Bench b(test_tape(0));
    auto rows = test_tape(600);
    std::uint32_t next = 0, free = 0;
    // The first PUNCH learns the credit.
    std::size_t sent = 0;
    auto send_from = [&](std::size_t from, std::size_t n) {
        Punch pu;
        pu.first = static_cast<std::uint32_t>(from);
        pu.count = static_cast<std::uint8_t>(n);
        std::copy(rows.begin() + static_cast<long>(from), rows.begin() + static_cast<long>(from + n), pu.rows);
        Packet p;
        pu.encode(p);
        return b.send(p);
    };
    std::uint8_t seq = send_from(0, Punch::max_rows);
    sent = Punch::max_rows;
    auto c = b.take(Msg::credit);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->seq, seq);
    Credit cr;
    ASSERT_TRUE(cr.decode(*c));
    EXPECT_EQ(cr.next, Punch::max_rows);
    // The same rows again (a lost CREDIT) are taken once.
    send_from(0, Punch::max_rows);
    ASSERT_TRUE((c = b.take(Msg::credit)));
    cr.decode(*c);
    EXPECT_EQ(cr.next, Punch::max_rows);
    // Rows past the next expected are refused, naming it.
    send_from(Punch::max_rows + 10, 5);
    auto err = b.take(Msg::error);
    ASSERT_TRUE(err);
    ErrorReply e;
    e.decode(*err);
    EXPECT_EQ(e.code, ErrorCode::out_of_order);
    EXPECT_EQ(e.frame, Punch::max_rows);
    next = cr.next;
    free = cr.free;
    while (b.hw.punched().size() < rows.size() && b.hw.now() < 10000000) {
        while (sent < rows.size() && sent < next + free) {
            std::size_t n = std::min<std::size_t>({Punch::max_rows, rows.size() - sent, next + free - sent});
            send_from(sent, n);
            sent += n;
        }
        b.run(10000);
        Packet keepalive;
        FrameNumber{0}.encode(keepalive, Msg::ack);  // the watchdog would stop a punch whose host is silent
        b.send(keepalive);
        while (auto cp = b.take(Msg::credit)) {
            cr.decode(*cp);
            next = cr.next;
            free = cr.free;
        }
    }
    EXPECT_EQ(b.hw.punched(), rows);
    // 600 rows at 150 a second: 4 s.
    EXPECT_NEAR(static_cast<double>(b.hw.now()) / 1e6, 4.0, 0.1);
    EXPECT_EQ(cr.punched, rows.size());
}

TEST(AdapterEngine, WatchdogStopsReaderAndPunchWhenTheHostIsSilent) {
    Bench b(test_tape(100000));
    Packet p;
    ReadStart{}.encode(p);
    b.send(p);
    Feed{1000}.encode(p);
    b.send(p);
    b.run(400000);
    EXPECT_EQ(b.hw.drive_state(), Drive::forward);
    EXPECT_TRUE(!b.take(Msg::status));
    b.run(200000);  // 600 ms without a word from the host
    EXPECT_EQ(b.hw.drive_state(), Drive::stop);
    std::optional<Status> st;
    while (auto s = b.take(Msg::status)) {
        Status x;
        x.decode(*s);
        if (x.bits & status::watchdog) st = x;
    }
    ASSERT_TRUE(st);
    EXPECT_FALSE(st->bits & status::reading);
    std::size_t punched = b.hw.punched().size();
    EXPECT_NEAR(static_cast<double>(punched), 75, 2);  // 500 ms of 150 rows/s
    b.run(500000);
    EXPECT_EQ(b.hw.punched().size(), punched) << "the punch stays off";
}

TEST(AdapterEngine, PunchFaultStopsThePunchAndIsReported) {
    Bench b(test_tape(0));
    Packet p;
    Feed{100}.encode(p);
    b.send(p);
    b.run(200000);
    b.hw.forced_status = status::chad_full;
    b.send(Msg::echo);
    b.run(100000);
    std::size_t punched = b.hw.punched().size();
    EXPECT_GT(punched, 20u);
    EXPECT_LT(punched, 40u);
    std::optional<Status> st;
    while (auto s = b.take(Msg::status)) {
        Status x;
        x.decode(*s);
        st = x;
    }
    ASSERT_TRUE(st);
    EXPECT_TRUE(st->bits & status::chad_full);
    EXPECT_EQ(st->frame, punched);
}

TEST(AdapterEngine, GarbageIsReportedAndResetResynchronises) {
    Bench b(test_tape(100));
    std::uint8_t garbage[] = {0x41, 0x54, 0x0D, 0x0A, 0x00};  // "AT\r\n": a modem prober
    b.engine.receive(garbage, sizeof garbage);
    auto err = b.take(Msg::error);
    ASSERT_TRUE(err);
    ErrorReply e;
    e.decode(*err);
    EXPECT_EQ(e.code, ErrorCode::bad_packet);
    EXPECT_EQ(b.engine.bad_packets(), 1u);
    // A partial packet, then a zero and RESET: the adapter is back in step.
    std::uint8_t partial[] = {0x05, 0x09, 0x01};
    b.engine.receive(partial, sizeof partial);
    std::uint8_t zero = 0;
    b.engine.receive(&zero, 1);
    b.inbox.clear();
    std::uint8_t seq = b.send(Msg::reset);
    auto ok = b.take(Msg::ok);
    ASSERT_TRUE(ok);
    EXPECT_EQ(ok->seq, seq);
    Ok o;
    o.decode(*ok);
    EXPECT_EQ(o.about, static_cast<std::uint8_t>(Msg::reset));
    b.send(static_cast<Msg>(0x55));
    err = b.take(Msg::error);
    ASSERT_TRUE(err);
    e.decode(*err);
    EXPECT_EQ(e.code, ErrorCode::unknown_message);
    EXPECT_EQ(e.about, 0x55);
}

TEST(AdapterEngine, EchoReturnsThePayload) {
    Bench b(test_tape(1));
    Packet p;
    p.type = static_cast<std::uint8_t>(Msg::echo);
    p.length = max_payload;
    std::iota(p.payload, p.payload + max_payload, std::uint8_t{0});
    std::uint8_t seq = b.send(p);
    auto r = b.take(Msg::echo_reply);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->seq, seq);
    ASSERT_EQ(r->length, max_payload);
    EXPECT_TRUE(std::equal(r->payload, r->payload + max_payload, p.payload));
}

TEST(AdapterEngine, ARateBelowTheReadersIsKeptByStartingAndStopping) {
    Bench b(test_tape(5000));
    Packet p;
    ReadStart{0, 300, 0}.encode(p);
    b.send(p);
    std::vector<std::uint8_t> got;
    for (int i = 0; i < 200; ++i) {  // 2 s
        b.run(10000);
        ASSERT_TRUE(take_rows(b, got));
        b.ack(got.size());
    }
    // 300 rows a second for two seconds, give or take a stopping distance each second.
    EXPECT_GE(got.size(), 590u);
    EXPECT_LE(got.size(), 610u);
    EXPECT_GE(b.hw.starts(), 2u);
}

TEST(AdapterEngine, OnePacketPerTransferForHidAndBulk) {
    tapesim::SimHardware hw(test_tape(200), {});
    std::vector<std::vector<std::uint8_t>> transfers;
    hw.on_send = [&](const std::uint8_t* b, std::size_t n) {
        transfers.emplace_back(b, b + n);
        return true;
    };
    Engine engine(hw, Identity{}, Framing::packets);
    auto send = [&](const Packet& p) {
        std::uint8_t raw[max_packet];
        engine.receive(raw, encode_packet(p, raw));
    };
    Packet p;
    p.type = static_cast<std::uint8_t>(Msg::get_info);
    p.seq = 9;
    send(p);
    ASSERT_EQ(transfers.size(), 1u);
    EXPECT_LE(transfers[0].size(), 64u);
    Packet reply;
    ASSERT_EQ(decode_packet(transfers[0].data(), transfers[0].size(), reply), PacketFault::none);
    EXPECT_EQ(reply.type, static_cast<std::uint8_t>(Msg::info));
    EXPECT_EQ(reply.seq, 9);
    ReadStart{}.encode(p);
    send(p);
    for (int i = 0; i < 300; ++i) {
        hw.advance_to(hw.now() + 1000, engine);
        engine.poll();
    }
    std::vector<std::uint8_t> got;
    for (const auto& t : transfers) {
        Packet q;
        ASSERT_EQ(decode_packet(t.data(), t.size(), q), PacketFault::none);
        Rows r;
        if (!r.decode(q)) continue;
        ASSERT_EQ(r.first, got.size());
        got.insert(got.end(), r.rows, r.rows + r.count);
    }
    EXPECT_EQ(got, test_tape(200));
    // A damaged transfer is reported, not taken.
    transfers.clear();
    std::uint8_t raw[max_packet];
    p.type = static_cast<std::uint8_t>(Msg::echo);
    p.length = 0;
    std::size_t n = encode_packet(p, raw);
    raw[n - 1] ^= 0xFF;
    engine.receive(raw, n);
    ASSERT_EQ(transfers.size(), 1u);
    Packet e;
    ASSERT_EQ(decode_packet(transfers[0].data(), transfers[0].size(), e), PacketFault::none);
    ErrorReply er;
    ASSERT_TRUE(er.decode(e));
    EXPECT_EQ(er.code, ErrorCode::bad_packet);
}

TEST(AdapterEngine, ReadsBackwardsFromWhereTheTapeStandsWithTheRowFlagsTheBoardSets) {
    tapesim::SimOptions o;
    o.row_flags = {{10, row_flag::timing}, {250, row_flag::no_sprocket | row_flag::marginal}};
    auto tape = test_tape(300);
    Identity id;
    id.capabilities = caps::reader | caps::reverse | caps::row_flags;
    Bench b(tape, o, id);
    // Forwards to the end first: 300 rows, two of them flagged where the board flagged them.
    Packet p;
    ReadStart{}.encode(p);
    b.send(p);
    b.run(400000);
    std::vector<Rows> packets;
    std::vector<std::uint8_t> got;
    std::map<std::uint32_t, std::uint8_t> flagged;
    auto collect = [&] {
        while (auto q = b.take(Msg::rows)) {
            Rows r;
            ASSERT_TRUE(r.decode(*q));
            ASSERT_EQ(r.first, got.size());
            for (std::size_t i = 0; i < r.count; ++i) {
                got.push_back(r.rows[i]);
                if (r.flags[i]) flagged[static_cast<std::uint32_t>(r.first + i)] = r.flags[i];
            }
        }
    };
    collect();
    ASSERT_EQ(got, tape);
    EXPECT_EQ(flagged, (std::map<std::uint32_t, std::uint8_t>{{10, row_flag::timing},
                                                              {250, row_flag::no_sprocket | row_flag::marginal}}));
    // Then backwards, from the end to the start: the same frames, last first, numbered from 0 again.
    b.inbox.clear();
    ReadStart back;
    back.reverse = 1;
    back.encode(p);
    b.send(p);
    ASSERT_TRUE(b.take(Msg::ok));
    EXPECT_EQ(b.hw.drive_state(), Drive::reverse);
    b.run(400000);
    got.clear();
    flagged.clear();
    collect();
    ASSERT_EQ(got, std::vector<std::uint8_t>(tape.rbegin(), tape.rend()));
    EXPECT_EQ(flagged, (std::map<std::uint32_t, std::uint8_t>{{289, row_flag::timing},
                                                              {49, row_flag::no_sprocket | row_flag::marginal}}));
    // The start of the tape has passed the head: tape out ends the run (the last STATUS; an earlier
    // one told that tape out went off when the reader moved back from the end).
    std::optional<Packet> st;
    while (auto q = b.take(Msg::status)) st = q;
    ASSERT_TRUE(st);
    Status s;
    ASSERT_TRUE(s.decode(*st));
    EXPECT_TRUE(s.bits & status::tape_out);
    EXPECT_EQ(s.frame, 300u);
    EXPECT_EQ(b.hw.position(), 0u);
}

TEST(AdapterEngine, ReverseIsRefusedByAReaderThatCannot) {
    Bench b(test_tape(50));  // the default identity: no reverse
    Packet p;
    ReadStart back;
    back.reverse = 1;
    back.encode(p);
    b.send(p);
    auto err = b.take(Msg::error);
    ASSERT_TRUE(err);
    ErrorReply e;
    ASSERT_TRUE(e.decode(*err));
    EXPECT_EQ(e.code, ErrorCode::bad_payload);
    EXPECT_EQ(b.hw.drive_state(), Drive::stop);
}

// On a board the sprocket interrupt can store a row between poll() reading the time and checking the
// sprocket time-out (the emulated RP2040 did so within a second of reading): that row is newer than poll's
// `now`, and must not read as 2^32 µs old, a torn tape.
namespace {
struct RowDuringPoll final : Hardware {
    Engine* engine = nullptr;
    std::uint32_t t = 1000;
    bool row_in_poll = false, sent_torn = false;
    std::uint32_t now_us() override {
        std::uint32_t now = t;
        if (row_in_poll && engine) {
            row_in_poll = false;
            ++t;  // the interrupt comes a microsecond after poll read the time
            engine->on_row(0x55);
        }
        return now;
    }
    bool send(const std::uint8_t* b, std::size_t n) override {
        StreamDecoder d;
        for (std::size_t i = 0; i < n; ++i)
            if (d.feed(b[i]) == StreamDecoder::Event::packet &&
                d.packet().type == static_cast<std::uint8_t>(Msg::status)) {
                Status s;
                if (s.decode(d.packet()) && (s.bits & status::torn)) sent_torn = true;
            }
        return true;
    }
    void drive(Drive) override {}
    bool punch_ready() override { return true; }
    void punch(std::uint8_t) override {}
    std::uint16_t status_lines() override { return 0; }
    void configure(const Config&) override {}
};
}  // namespace

TEST(AdapterEngine, ARowStoredWhilePollRunsIsNoTornTape) {
    RowDuringPoll hw;
    Engine engine(hw, Identity{});
    hw.engine = &engine;
    Packet p;
    ReadStart{}.encode(p);
    p.seq = 1;
    std::uint8_t out[max_framed];
    engine.receive(out, frame_packet(p, out));
    for (int i = 0; i < 100; ++i) {
        hw.t += 600;
        engine.on_row(0x2A);
        hw.row_in_poll = true;
        engine.poll();
    }
    EXPECT_TRUE(engine.reading());
    EXPECT_FALSE(hw.sent_torn);
}
