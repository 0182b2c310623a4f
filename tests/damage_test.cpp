// The damage model: the same seed gives the same read, each kind of damage does what the header says and
// what the log says it did, and the rates come out as asked over many frames.
#include "tape/damage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tape/error.hpp"

using namespace tape;

namespace {

// 4 blank frames of leader, "%\nN1G0\n" in ISO (even parity on track 8), 4 blank frames of trailer.
const std::vector<Frame> small_tape = {0x00, 0x00, 0x00, 0x00, 0xA5, 0x0A, 0x4E, 0xB1,
                                       0x47, 0x30, 0x0A, 0x00, 0x00, 0x00, 0x00};
constexpr std::size_t small_first = 4, small_last = 10;  // the data: first and last punched frame

// Frames that are all different from their neighbours and none blank, so that any change shows.
std::vector<Frame> punched_tape(std::size_t n) {
    std::vector<Frame> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<Frame>(1 + i % 255);
    return t;
}

std::vector<Frame> blanks(std::size_t n) { return std::vector<Frame>(n, blank_frame); }

std::vector<Frame> joined(std::vector<Frame> a, const std::vector<Frame>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

std::vector<Frame> slice(const std::vector<Frame>& t, std::size_t from, std::size_t to) {
    return std::vector<Frame>(t.begin() + static_cast<std::ptrdiff_t>(from),
                              t.begin() + static_cast<std::ptrdiff_t>(to));
}

DamageOptions only(std::uint64_t seed) {
    DamageOptions o;
    o.seed = seed;
    return o;
}

std::size_t frames_of(const DamageLog& log, DamageKind kind) {
    std::size_t n = 0;
    for (const auto& e : log.events)
        if (e.kind == kind) n += e.frames;
    return n;
}

bool is_usage_error(const DamageOptions& o, std::span<const Frame> tape = small_tape) {
    try {
        damage(tape, o);
    } catch (const Error& e) {
        return e.code() == Errc::usage;
    }
    return false;
}

}  // namespace

TEST(Damage, NothingAskedReadsTheTapeAsItIs) {
    DamageLog log;
    EXPECT_EQ(damage(small_tape, only(7), &log), small_tape);
    EXPECT_TRUE(log.events.empty());
}

TEST(Damage, GoldenReadForASeed) {
    // Checked by hand, indices from 0: frame 2 (blank) dropped; frame 3 (blank) reads track 8 (0x80) at
    // read 2; frame 5 (LF) read twice; a burst garbles frames 7-8 ('1', 'G'); frame 10 (LF, 0x0A) reads
    // track 5 as well (0x1A). One frame dropped, one doubled: the read is as long as the tape.
    DamageOptions o = only(20260112);
    o.flips = o.drops = o.doubles = 0.1;
    o.bursts = 0.05;
    o.burst_length = 2;
    DamageLog log;
    std::vector<Frame> read = damage(small_tape, o, &log);
    const std::vector<Frame> golden = {0x00, 0x00, 0x80, 0xA5, 0x0A, 0x0A, 0x4E, 0x38,
                                       0xC5, 0x30, 0x1A, 0x00, 0x00, 0x00, 0x00};
    EXPECT_EQ(read, golden);
    std::vector<std::string> events;
    for (const auto& e : log.events)
        events.push_back(std::string(damage_kind_name(e.kind)) + " " + std::to_string(e.original) + " " +
                         std::to_string(e.read) + " " + std::to_string(e.frames) + " " + std::to_string(e.track));
    const std::vector<std::string> golden_events = {"drop 2 2 1 0", "flip 3 2 1 8", "double 5 4 1 0", "burst 7 7 2 0",
                                                    "flip 10 10 1 5"};
    EXPECT_EQ(events, golden_events);
    // The same again, and another seed reads differently.
    EXPECT_EQ(damage(small_tape, o), read);
    o.seed += 1;
    EXPECT_NE(damage(small_tape, o), read);
}

TEST(Damage, FlipsChangeExactlyOneHoleOfTheFrame) {
    std::vector<Frame> tape = punched_tape(2000);
    DamageOptions o = only(1);
    o.flips = 0.1;
    DamageLog log;
    std::vector<Frame> read = damage(tape, o, &log);
    ASSERT_EQ(read.size(), tape.size());
    ASSERT_GT(log.count(DamageKind::flip), 0U);
    EXPECT_EQ(log.count(DamageKind::flip), log.events.size());
    std::vector<bool> flipped(tape.size());
    for (const auto& e : log.events) {
        EXPECT_EQ(e.read, e.original);
        EXPECT_EQ(e.frames, 1U);
        ASSERT_TRUE(e.track >= 1 && e.track <= 8);
        EXPECT_EQ(read[e.read] ^ tape[e.original], 1 << (e.track - 1));
        flipped[e.original] = true;
    }
    for (std::size_t i = 0; i < tape.size(); ++i) {
        if (!flipped[i]) {
            EXPECT_EQ(read[i], tape[i]) << "frame " << i;
        }
    }
}

TEST(Damage, DropsShortenTheReadByTheFramesLogged) {
    std::vector<Frame> tape = punched_tape(2000);
    DamageOptions o = only(2);
    o.drops = 0.1;
    DamageLog log;
    std::vector<Frame> read = damage(tape, o, &log);
    ASSERT_GT(log.count(DamageKind::drop), 0U);
    EXPECT_EQ(read.size(), tape.size() - log.count(DamageKind::drop));
    std::vector<Frame> expected;
    std::size_t next = 0, dropped = 0;
    for (const auto& e : log.events) {
        EXPECT_EQ(e.read, e.original - dropped);  // where the frame would have been
        expected.insert(expected.end(), tape.begin() + static_cast<std::ptrdiff_t>(next),
                        tape.begin() + static_cast<std::ptrdiff_t>(e.original));
        next = e.original + 1;
        ++dropped;
    }
    expected.insert(expected.end(), tape.begin() + static_cast<std::ptrdiff_t>(next), tape.end());
    EXPECT_EQ(read, expected);
}

TEST(Damage, DoublesLengthenTheReadByTheFramesLogged) {
    std::vector<Frame> tape = punched_tape(2000);
    DamageOptions o = only(3);
    o.doubles = 0.1;
    DamageLog log;
    std::vector<Frame> read = damage(tape, o, &log);
    ASSERT_GT(log.count(DamageKind::double_read), 0U);
    EXPECT_EQ(read.size(), tape.size() + log.count(DamageKind::double_read));
    std::vector<Frame> expected = tape;
    for (auto e = log.events.rbegin(); e != log.events.rend(); ++e) {
        EXPECT_EQ(read[e->read], tape[e->original]);
        EXPECT_EQ(read[e->read + 1], tape[e->original]);
        expected.insert(expected.begin() + static_cast<std::ptrdiff_t>(e->original), tape[e->original]);
    }
    EXPECT_EQ(read, expected);
}

TEST(Damage, BurstsGarbleBurstLengthFramesEach) {
    std::vector<Frame> tape = punched_tape(5000);
    DamageOptions o = only(4);
    o.bursts = 0.01;
    o.burst_length = 6;
    DamageLog log;
    std::vector<Frame> read = damage(tape, o, &log);
    ASSERT_EQ(read.size(), tape.size());
    ASSERT_GT(log.count(DamageKind::burst), 0U);
    std::vector<bool> garbled(tape.size());
    std::size_t end_of_last = 0;
    for (const auto& e : log.events) {
        EXPECT_EQ(e.read, e.original);
        EXPECT_GE(e.original, end_of_last) << "bursts do not overlap";
        EXPECT_EQ(e.frames, std::min<std::size_t>(6, tape.size() - e.original));
        for (std::size_t i = e.original; i < e.original + e.frames; ++i) garbled[i] = true;
        end_of_last = e.original + e.frames;
    }
    for (std::size_t i = 0; i < tape.size(); ++i)
        EXPECT_EQ(read[i] != tape[i], garbled[i]) << "frame " << i << ": every garbled frame differs";
}

TEST(Damage, ABurstAtTheEndIsCutShort) {
    DamageOptions o = only(5);
    o.bursts = 1;
    o.burst_length = 5;
    DamageLog log;
    std::vector<Frame> tape = punched_tape(3);
    std::vector<Frame> read = damage(tape, o, &log);
    ASSERT_EQ(log.events.size(), 1U);
    EXPECT_EQ(log.events[0].frames, 3U);
    EXPECT_EQ(read.size(), 3U);
}

TEST(Damage, LeaderAddsBlankFrames) {
    DamageOptions o = only(6);
    o.leader = 7;
    DamageLog log;
    EXPECT_EQ(damage(small_tape, o, &log), joined(blanks(7), small_tape));
    ASSERT_EQ(log.events.size(), 1U);
    EXPECT_EQ(log.events[0].kind, DamageKind::leader_added);
    EXPECT_EQ(log.events[0].original, 0U);
    EXPECT_EQ(log.events[0].read, 0U);
    EXPECT_EQ(log.events[0].frames, 7U);
}

TEST(Damage, LeaderRemovesBlankFramesButNeverData) {
    DamageOptions o = only(7);
    o.leader = -3;
    DamageLog log;
    EXPECT_EQ(damage(small_tape, o, &log), slice(small_tape, 3, small_tape.size()));
    ASSERT_EQ(log.events.size(), 1U);
    EXPECT_EQ(log.events[0].kind, DamageKind::leader_removed);
    EXPECT_EQ(log.events[0].frames, 3U);
    o.leader = -100;
    EXPECT_EQ(damage(small_tape, o, &log), slice(small_tape, small_first, small_tape.size()));
    EXPECT_EQ(log.events[0].frames, small_first);
    o.leader = std::numeric_limits<long>::min();
    EXPECT_EQ(damage(small_tape, o), slice(small_tape, small_first, small_tape.size()));
    // No leader to remove: nothing done, nothing logged.
    EXPECT_EQ(damage(punched_tape(10), o, &log), punched_tape(10));
    EXPECT_TRUE(log.events.empty());
}

TEST(Damage, TornRemovesExactlyThatManyConsecutiveFramesInsideTheData) {
    std::vector<Frame> tape = joined(joined(blanks(50), punched_tape(100)), blanks(50));
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        DamageOptions o = only(seed);
        o.torn = 17;
        DamageLog log;
        std::vector<Frame> read = damage(tape, o, &log);
        ASSERT_EQ(log.events.size(), 1U);
        const DamageEvent& e = log.events[0];
        EXPECT_EQ(e.kind, DamageKind::torn);
        EXPECT_EQ(e.frames, 17U);
        EXPECT_GE(e.original, 50U);
        EXPECT_LE(e.original + 17, 150U);
        EXPECT_EQ(e.read, e.original);
        EXPECT_EQ(read, joined(slice(tape, 0, e.original), slice(tape, e.original + 17, tape.size())));
    }
}

TEST(Damage, TornCanTakeTheWholeDataButNoMore) {
    DamageOptions o = only(8);
    o.torn = small_last - small_first + 1;
    EXPECT_EQ(damage(small_tape, o), joined(blanks(small_first), blanks(small_tape.size() - small_last - 1)));
    o.torn += 1;
    EXPECT_TRUE(is_usage_error(o));
    o.torn = 1;
    EXPECT_TRUE(is_usage_error(o, blanks(20))) << "a blank tape has no data to tear";
}

TEST(Damage, StartLateAndStopEarlyLeaveFramesUnread) {
    DamageOptions o = only(9);
    o.start_late = 3;
    o.stop_early = 2;
    DamageLog log;
    EXPECT_EQ(damage(small_tape, o, &log), slice(small_tape, 3, small_tape.size() - 2));
    ASSERT_EQ(log.events.size(), 2U);
    EXPECT_EQ(log.events[0].kind, DamageKind::start_late);
    EXPECT_EQ(log.events[0].original, 0U);
    EXPECT_EQ(log.events[0].read, 0U);
    EXPECT_EQ(log.events[0].frames, 3U);
    EXPECT_EQ(log.events[1].kind, DamageKind::stop_early);
    EXPECT_EQ(log.events[1].original, small_tape.size() - 2);
    EXPECT_EQ(log.events[1].read, small_tape.size() - 5);
    EXPECT_EQ(log.events[1].frames, 2U);
    // More than there is: nothing is read, and the log says what was there to miss.
    o.start_late = 10;
    o.stop_early = 10;
    EXPECT_TRUE(damage(small_tape, o, &log).empty());
    EXPECT_EQ(log.events[0].frames, 10U);
    EXPECT_EQ(log.events[1].frames, small_tape.size() - 10);
}

TEST(Damage, StepsBeforeReadingComeInTheDocumentedOrder) {
    // The leader added, then the reader starts late into it; the torn stretch is found in the read.
    std::vector<Frame> tape = joined(joined(blanks(5), punched_tape(40)), blanks(5));
    DamageOptions o = only(10);
    o.torn = 4;
    o.leader = 6;
    o.start_late = 2;
    o.stop_early = 1;
    DamageLog log;
    std::vector<Frame> read = damage(tape, o, &log);
    ASSERT_EQ(log.events.size(), 4U);
    EXPECT_EQ(log.events[0].kind, DamageKind::torn);
    EXPECT_EQ(log.events[1].kind, DamageKind::leader_added);
    EXPECT_EQ(log.events[2].kind, DamageKind::start_late);
    EXPECT_EQ(log.events[3].kind, DamageKind::stop_early);
    const DamageEvent& torn = log.events[0];
    EXPECT_EQ(torn.read, torn.original + 6 - 2);
    EXPECT_EQ(read[torn.read], tape[torn.original + 4]);
    EXPECT_EQ(read.size(), tape.size() - 4 + 6 - 2 - 1);
    EXPECT_EQ(log.events[2].read, 0U);
    EXPECT_EQ(log.events[3].read, read.size());
    EXPECT_EQ(log.events[3].original, tape.size() - 1);
}

TEST(Damage, FiveTrackTapeStaysFiveTrack) {
    std::vector<Frame> tape(3000);
    for (std::size_t i = 0; i < tape.size(); ++i) tape[i] = static_cast<Frame>(i % 32);
    DamageOptions o = only(11);
    o.flips = 0.2;
    o.bursts = 0.05;
    o.tracks = 5;
    DamageLog log;
    std::vector<Frame> read = damage(tape, o, &log);
    EXPECT_GT(log.count(DamageKind::flip), 0U);
    EXPECT_GT(log.count(DamageKind::burst), 0U);
    EXPECT_TRUE(std::all_of(read.begin(), read.end(), [](Frame f) { return f < 0x20; }));
}

TEST(Damage, RatesAreChecked) {
    for (double bad : {-0.1, 1.5, std::nan("")}) {
        DamageOptions o = only(1);
        o.flips = bad;
        EXPECT_TRUE(is_usage_error(o)) << bad;
        o = only(1);
        o.bursts = bad;
        EXPECT_TRUE(is_usage_error(o)) << bad;
    }
    DamageOptions o = only(1);
    o.flips = o.drops = 0.6;
    EXPECT_TRUE(is_usage_error(o)) << "more than one event a frame";
    o.flips = o.drops = 0.5;
    EXPECT_FALSE(is_usage_error(o));
    o = only(1);
    o.bursts = 0.1;
    o.burst_length = 0;
    EXPECT_TRUE(is_usage_error(o));
    o = only(1);
    o.tracks = 9;
    EXPECT_TRUE(is_usage_error(o));
}

TEST(Damage, MixedDamageSpreadsOneRateOverTheFourKinds) {
    DamageOptions o = mixed_damage(0.2, 99, 5);
    EXPECT_EQ(o.seed, 99U);
    EXPECT_DOUBLE_EQ(o.flips, 0.05);
    EXPECT_DOUBLE_EQ(o.drops, 0.05);
    EXPECT_DOUBLE_EQ(o.doubles, 0.05);
    EXPECT_DOUBLE_EQ(o.bursts, 0.01);
    EXPECT_EQ(o.burst_length, 5U);
}

// Over 10^5 frames each count lies within 5 standard deviations of what its rate asks (a binomial count),
// so that the test is sure to pass for a right model and fails for a rate off by a tenth or more.
TEST(Damage, RatesHoldOver100000Frames) {
    const std::size_t n = 100'000;
    std::vector<Frame> tape = punched_tape(n);
    auto within = [](double count, double expected, double p) {
        double sd = std::sqrt(expected * (1 - p));
        return std::abs(count - expected) <= 5 * sd;
    };
    struct Case {
        double DamageOptions::*rate;
        DamageKind kind;
    };
    for (Case c : {Case{&DamageOptions::flips, DamageKind::flip}, Case{&DamageOptions::drops, DamageKind::drop},
                   Case{&DamageOptions::doubles, DamageKind::double_read}}) {
        DamageOptions o = only(12);
        o.*c.rate = 0.03;
        DamageLog log;
        damage(tape, o, &log);
        EXPECT_TRUE(within(static_cast<double>(log.count(c.kind)), 0.03 * n, 0.03))
            << damage_kind_name(c.kind) << ": " << log.count(c.kind);
    }
    // Bursts start only at frames outside a burst: 1 + p (L - 1) frames pass per draw.
    DamageOptions o = only(13);
    o.bursts = 0.005;
    o.burst_length = 4;
    DamageLog log;
    damage(tape, o, &log);
    double draws = n / (1 + 0.005 * 3);
    EXPECT_TRUE(within(static_cast<double>(log.count(DamageKind::burst)), 0.005 * draws, 0.005))
        << log.count(DamageKind::burst);
    // The mixed rate: about that fraction of the frames damaged.
    damage(tape, mixed_damage(0.1, 14), &log);
    std::size_t damaged = log.count(DamageKind::flip) + log.count(DamageKind::drop) +
                          log.count(DamageKind::double_read) + frames_of(log, DamageKind::burst);
    EXPECT_NEAR(static_cast<double>(damaged) / n, 0.1, 0.01) << damaged;
}
