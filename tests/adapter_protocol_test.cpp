// The adapter protocol on byte arrays: CRC, COBS, packets, the stream decoder's resynchronisation,
// and every message both ways (firmware/core, shared by the adapter and the host).
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "core/cobs.hpp"
#include "core/crc16.hpp"
#include "core/packet.hpp"
#include "core/protocol.hpp"

using namespace tapefw;

namespace {

std::vector<std::uint8_t> framed(const Packet& p) {
    std::vector<std::uint8_t> out(max_framed);
    out.resize(frame_packet(p, out.data()));
    return out;
}

Packet make(Msg type, std::uint8_t seq, std::vector<std::uint8_t> payload) {
    Packet p;
    p.type = static_cast<std::uint8_t>(type);
    p.seq = seq;
    p.length = static_cast<std::uint8_t>(payload.size());
    if (!payload.empty()) std::memcpy(p.payload, payload.data(), payload.size());
    return p;
}

bool same(const Packet& a, const Packet& b) {
    return a.type == b.type && a.seq == b.seq && a.length == b.length &&
           std::memcmp(a.payload, b.payload, a.length) == 0;
}

// Everything the decoder gives back for a stream: packets and faults in order.
struct Decoded {
    std::vector<Packet> packets;
    std::vector<PacketFault> faults;
};
Decoded decode_stream(const std::vector<std::uint8_t>& bytes) {
    StreamDecoder d;
    Decoded out;
    for (auto b : bytes) {
        auto e = d.feed(b);
        if (e == StreamDecoder::Event::packet) out.packets.push_back(d.packet());
        if (e == StreamDecoder::Event::fault) out.faults.push_back(d.fault());
    }
    return out;
}

}  // namespace

TEST(AdapterCrc, CcittFalseCheckValue) {
    const char* check = "123456789";
    EXPECT_EQ(crc16(reinterpret_cast<const std::uint8_t*>(check), 9), 0x29B1);
    EXPECT_EQ(crc16(nullptr, 0), 0xFFFF);
    // Continuing from a partial CRC gives the CRC of the whole.
    std::uint16_t part = crc16(reinterpret_cast<const std::uint8_t*>(check), 4);
    EXPECT_EQ(crc16(reinterpret_cast<const std::uint8_t*>(check) + 4, 5, part), 0x29B1);
}

TEST(AdapterCobs, KnownEncodings) {
    // The examples of the COBS paper and its common test vectors.
    struct Case {
        std::vector<std::uint8_t> in, out;
    } cases[] = {
        {{}, {0x01}},
        {{0x00}, {0x01, 0x01}},
        {{0x00, 0x00}, {0x01, 0x01, 0x01}},
        {{0x11, 0x22, 0x00, 0x33}, {0x03, 0x11, 0x22, 0x02, 0x33}},
        {{0x11, 0x00, 0x00, 0x00}, {0x02, 0x11, 0x01, 0x01, 0x01}},
    };
    for (const auto& c : cases) {
        std::vector<std::uint8_t> out(cobs_max_encoded(c.in.size()));
        out.resize(cobs_encode(c.in.data(), c.in.size(), out.data()));
        EXPECT_EQ(out, c.out);
        std::vector<std::uint8_t> back(out.size());
        int n = cobs_decode(out.data(), out.size(), back.data());
        ASSERT_EQ(n, static_cast<int>(c.in.size()));
        back.resize(static_cast<std::size_t>(n));
        EXPECT_EQ(back, c.in);
    }
}

TEST(AdapterCobs, RoundTripAtBlockEdgesWithNoZeroInside) {
    std::mt19937 rng(7);
    for (std::size_t n : {1u, 2u, 253u, 254u, 255u, 256u, 508u, 509u, 700u}) {
        for (int zeros : {0, 1, 3}) {
            std::vector<std::uint8_t> in(n);
            for (auto& b : in) b = static_cast<std::uint8_t>(1 + rng() % 255);
            for (int z = 0; z < zeros; ++z) in[rng() % n] = 0;
            std::vector<std::uint8_t> enc(cobs_max_encoded(n));
            std::size_t m = cobs_encode(in.data(), n, enc.data());
            ASSERT_LE(m, cobs_max_encoded(n));
            for (std::size_t i = 0; i < m; ++i) ASSERT_NE(enc[i], 0) << "n=" << n << " at " << i;
            std::vector<std::uint8_t> back(m);
            ASSERT_EQ(cobs_decode(enc.data(), m, back.data()), static_cast<int>(n)) << "n=" << n;
            back.resize(n);
            EXPECT_EQ(back, in) << "n=" << n;
        }
    }
}

TEST(AdapterCobs, MalformedIsRefused) {
    std::uint8_t out[8];
    const std::uint8_t past_end[] = {0x05, 0x11, 0x22};
    EXPECT_EQ(cobs_decode(past_end, sizeof past_end, out), -1);
    const std::uint8_t zero_code[] = {0x00, 0x11};
    EXPECT_EQ(cobs_decode(zero_code, sizeof zero_code, out), -1);
    const std::uint8_t zero_inside[] = {0x03, 0x11, 0x00};
    EXPECT_EQ(cobs_decode(zero_inside, sizeof zero_inside, out), -1);
}

TEST(AdapterPacket, EveryPacketFitsOneFullSpeedUsbPacket) {
    Packet p = make(Msg::rows, 255, std::vector<std::uint8_t>(max_payload, 0x00));
    EXPECT_LE(framed(p).size(), 64u);
    p = make(Msg::rows, 255, std::vector<std::uint8_t>(max_payload, 0xFF));
    EXPECT_LE(framed(p).size(), 64u);
    std::uint8_t raw[max_packet];
    EXPECT_EQ(encode_packet(p, raw), max_packet);
    EXPECT_LE(max_packet, 64u);
}

TEST(AdapterPacket, RoundTripAndEveryFault) {
    Packet p = make(Msg::echo, 42, {1, 2, 0, 4, 0});
    std::uint8_t raw[max_packet];
    std::size_t n = encode_packet(p, raw);
    ASSERT_EQ(n, 10u);
    EXPECT_EQ(raw[0], 0x0A);
    EXPECT_EQ(raw[1], 42);
    EXPECT_EQ(raw[2], 5);
    std::uint16_t crc = crc16(raw, 8);
    EXPECT_EQ(raw[8], crc & 0xFF);  // low byte first
    EXPECT_EQ(raw[9], crc >> 8);
    Packet back;
    ASSERT_EQ(decode_packet(raw, n, back), PacketFault::none);
    EXPECT_TRUE(same(p, back));

    for (std::size_t i = 0; i < n; ++i)
        for (int bit = 0; bit < 8; ++bit) {
            std::uint8_t bad[max_packet];
            std::memcpy(bad, raw, n);
            bad[i] ^= static_cast<std::uint8_t>(1 << bit);
            PacketFault f = decode_packet(bad, n, back);
            // A flipped length byte is caught before the CRC; any other single flip by the CRC.
            EXPECT_EQ(f, i == 2 ? PacketFault::length : PacketFault::crc) << "byte " << i << " bit " << bit;
        }
    EXPECT_EQ(decode_packet(raw, 4, back), PacketFault::too_short);
    std::uint8_t big[max_packet + 1] = {};
    EXPECT_EQ(decode_packet(big, sizeof big, back), PacketFault::too_long);
    EXPECT_EQ(decode_packet(raw, n - 1, back), PacketFault::length);
}

TEST(AdapterStream, PacketsBackToBackInAnyPieces) {
    std::vector<Packet> sent;
    std::vector<std::uint8_t> bytes;
    for (int i = 0; i < 20; ++i) {
        std::vector<std::uint8_t> payload(static_cast<std::size_t>(i * 3 % 57));
        for (std::size_t k = 0; k < payload.size(); ++k) payload[k] = static_cast<std::uint8_t>(k * i);
        sent.push_back(make(Msg::rows, static_cast<std::uint8_t>(i), payload));
        auto f = framed(sent.back());
        bytes.insert(bytes.end(), f.begin(), f.end());
    }
    Decoded d = decode_stream(bytes);
    EXPECT_TRUE(d.faults.empty());
    ASSERT_EQ(d.packets.size(), sent.size());
    for (std::size_t i = 0; i < sent.size(); ++i) EXPECT_TRUE(same(d.packets[i], sent[i])) << i;
}

TEST(AdapterStream, ResynchronisesAfterGarbage) {
    Packet a = make(Msg::ok, 1, {0x03});
    Packet b = make(Msg::status, 2, {1, 0, 9, 0, 0, 0});
    std::vector<std::uint8_t> bytes = {0x12, 0x34, 0xFF, 0x00};  // joined mid-packet: garbage then a zero
    auto fa = framed(a);
    bytes.insert(bytes.end(), fa.begin(), fa.end());
    std::vector<std::uint8_t> long_garbage(300, 0x55);  // longer than any packet
    bytes.insert(bytes.end(), long_garbage.begin(), long_garbage.end());
    bytes.push_back(0);
    bytes.push_back(0);  // zeros between packets are allowed
    auto fb = framed(b);
    fb[2] ^= 0x40;  // a damaged packet (its seq byte)
    bytes.insert(bytes.end(), fb.begin(), fb.end());
    fb = framed(b);
    bytes.insert(bytes.end(), fb.begin(), fb.end());
    Decoded d = decode_stream(bytes);
    ASSERT_EQ(d.packets.size(), 2u);
    EXPECT_TRUE(same(d.packets[0], a));
    EXPECT_TRUE(same(d.packets[1], b));
    ASSERT_EQ(d.faults.size(), 3u);
    EXPECT_NE(d.faults[0], PacketFault::none);
    EXPECT_EQ(d.faults[1], PacketFault::too_long);
    EXPECT_EQ(d.faults[2], PacketFault::crc);
}

TEST(AdapterStream, RandomNoiseNeverGivesAPacketWithABadCrc) {
    // Whatever noise makes of a stream, every packet given back passed its CRC: re-encoding it gives
    // the same bytes the decoder accepted.
    std::mt19937 rng(11);
    StreamDecoder d;
    int packets = 0;
    for (int i = 0; i < 200000; ++i) {
        std::uint8_t b = static_cast<std::uint8_t>(rng() % 7 == 0 ? 0 : rng());
        if (d.feed(b) == StreamDecoder::Event::packet) {
            ++packets;
            std::uint8_t raw[max_packet];
            std::size_t n = encode_packet(d.packet(), raw);
            Packet back;
            EXPECT_EQ(decode_packet(raw, n, back), PacketFault::none);
        }
    }
    EXPECT_LT(packets, 5);  // CRC-16: about one in 65536 noise runs of the right length passes
}

TEST(AdapterMessages, EveryMessageBothWays) {
    Packet p;
    Info info;
    info.firmware[0] = 1;
    info.firmware[1] = 2;
    info.firmware[2] = 3;
    info.capabilities = caps::reader | caps::punch | caps::reverse;
    info.tracks = 0x0F;
    info.max_read_rate = 1500;
    info.max_punch_rate = 150;
    info.read_buffer = 1024;
    info.punch_buffer = 256;
    std::strcpy(info.serial, "TP0001A");
    ASSERT_TRUE(info.encode(p));
    EXPECT_EQ(p.type, static_cast<std::uint8_t>(Msg::info));
    Info info2;
    ASSERT_TRUE(info2.decode(p));
    EXPECT_EQ(info2.protocol, protocol_version);
    EXPECT_EQ(info2.firmware[2], 3);
    EXPECT_EQ(info2.capabilities, info.capabilities);
    EXPECT_EQ(info2.max_read_rate, 1500);
    EXPECT_EQ(info2.punch_buffer, 256);
    EXPECT_STREQ(info2.serial, "TP0001A");
    // Another protocol version: only the version is read, so that the host can name both.
    p.payload[0] = protocol_version + 1;
    Info other;
    ASSERT_TRUE(other.decode(p));
    EXPECT_EQ(other.protocol, protocol_version + 1);

    Config c;
    c.data_invert = 0xA5;
    c.lines = line_bit::sprocket_low | line_bit::drive_pulse;
    c.tracks = 5;
    c.sample_delay_us = 120;
    c.punch_pulse_us = 3000;
    c.drive_pulse_us = 800;
    c.sprocket_timeout_ms = 40;
    c.watchdog_ms = 250;
    ASSERT_TRUE(c.encode(p));
    Config c2;
    ASSERT_TRUE(c2.decode(p));
    EXPECT_EQ(c2.data_invert, 0xA5);
    EXPECT_EQ(c2.lines, c.lines);
    EXPECT_EQ(c2.tracks, 5);
    EXPECT_EQ(c2.sample_delay_us, 120);
    EXPECT_EQ(c2.punch_pulse_us, 3000);
    EXPECT_EQ(c2.drive_pulse_us, 800);
    EXPECT_EQ(c2.sprocket_timeout_ms, 40);
    EXPECT_EQ(c2.watchdog_ms, 250);
    c.tracks = 9;
    c.encode(p);
    EXPECT_FALSE(c2.decode(p)) << "9 tracks";

    ReadStart rs{1, 300, 100000};
    ASSERT_TRUE(rs.encode(p));
    ReadStart rs2;
    ASSERT_TRUE(rs2.decode(p));
    EXPECT_EQ(rs2.reverse, 1);
    EXPECT_EQ(rs2.rate, 300);
    EXPECT_EQ(rs2.max_rows, 100000u);

    for (Msg m : {Msg::ack, Msg::resend}) {
        ASSERT_TRUE(FrameNumber{0x01020304}.encode(p, m));
        EXPECT_EQ(p.type, static_cast<std::uint8_t>(m));
        FrameNumber f;
        ASSERT_TRUE(f.decode(p));
        EXPECT_EQ(f.frame, 0x01020304u);
    }

    Rows r;
    r.first = 70000;
    r.count = Rows::max_rows;
    for (std::size_t i = 0; i < r.count; ++i) r.rows[i] = static_cast<std::uint8_t>(i * 5);
    ASSERT_TRUE(r.encode(p));
    EXPECT_EQ(p.length, max_payload);
    Rows r2;
    ASSERT_TRUE(r2.decode(p));
    EXPECT_EQ(r2.first, 70000u);
    ASSERT_EQ(r2.count, Rows::max_rows);
    EXPECT_EQ(std::memcmp(r2.rows, r.rows, r.count), 0);
    // Flags travel as (index, flags) pairs after the rows, so a packet of flagged rows holds fewer.
    r.flags[3] = row_flag::timing;
    EXPECT_FALSE(r.encode(p));
    r.count = 10;
    r.flags[9] = row_flag::no_sprocket | row_flag::marginal;
    ASSERT_TRUE(r.encode(p));
    ASSERT_TRUE(r2.decode(p));
    EXPECT_EQ(r2.flags[3], row_flag::timing);
    EXPECT_EQ(r2.flags[9], row_flag::no_sprocket | row_flag::marginal);
    EXPECT_EQ(r2.flags[0], 0);

    Punch pu;
    pu.first = 12;
    pu.count = Punch::max_rows;
    for (std::size_t i = 0; i < pu.count; ++i) pu.rows[i] = static_cast<std::uint8_t>(255 - i);
    ASSERT_TRUE(pu.encode(p));
    Punch pu2;
    ASSERT_TRUE(pu2.decode(p));
    EXPECT_EQ(pu2.first, 12u);
    ASSERT_EQ(pu2.count, Punch::max_rows);
    EXPECT_EQ(std::memcmp(pu2.rows, pu.rows, pu.count), 0);

    Credit cr{1000, 990, 200};
    ASSERT_TRUE(cr.encode(p));
    Credit cr2;
    ASSERT_TRUE(cr2.decode(p));
    EXPECT_EQ(cr2.next, 1000u);
    EXPECT_EQ(cr2.punched, 990u);
    EXPECT_EQ(cr2.free, 200);

    Feed fe{500};
    ASSERT_TRUE(fe.encode(p));
    Feed fe2;
    ASSERT_TRUE(fe2.decode(p));
    EXPECT_EQ(fe2.count, 500);

    Status st{status::tape_out | status::reading, 123456};
    ASSERT_TRUE(st.encode(p));
    Status st2;
    ASSERT_TRUE(st2.decode(p));
    EXPECT_EQ(st2.bits, st.bits);
    EXPECT_EQ(st2.frame, 123456u);

    ErrorReply er{ErrorCode::out_of_order, static_cast<std::uint8_t>(Msg::punch), 77};
    ASSERT_TRUE(er.encode(p));
    ErrorReply er2;
    ASSERT_TRUE(er2.decode(p));
    EXPECT_EQ(er2.code, ErrorCode::out_of_order);
    EXPECT_EQ(er2.about, static_cast<std::uint8_t>(Msg::punch));
    EXPECT_EQ(er2.frame, 77u);
    EXPECT_STREQ(error_name(ErrorCode::out_of_order), "out of order");

    Ok ok{static_cast<std::uint8_t>(Msg::reset)};
    ASSERT_TRUE(ok.encode(p));
    Ok ok2;
    ASSERT_TRUE(ok2.decode(p));
    EXPECT_EQ(ok2.about, static_cast<std::uint8_t>(Msg::reset));
}

TEST(AdapterMessages, WrongTypeOrSizeIsRefused) {
    Packet p;
    Status{1, 2}.encode(p);
    Credit c;
    EXPECT_FALSE(c.decode(p)) << "a status is no credit";
    p.type = static_cast<std::uint8_t>(Msg::credit);
    EXPECT_FALSE(c.decode(p)) << "a status payload is too short for a credit";
    Ok{1}.encode(p);
    p.length = 2;
    Ok ok;
    EXPECT_FALSE(ok.decode(p)) << "trailing bytes";
    Rows r;
    p = make(Msg::rows, 0, {0, 0, 0, 0, 2, 7, 8, 5, 1});  // a flag for row 5 of 2
    EXPECT_FALSE(r.decode(p));
    p = make(Msg::punch, 0, {1, 2, 3});
    Punch pu;
    EXPECT_FALSE(pu.decode(p));
}
