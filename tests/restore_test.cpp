// Alignment and restoration on reads with known damage: each status, the refusal of unrelated reads,
// repair decisions, and the property that a frame clean in some read is never worse in the output.
#include "tape/restore.hpp"

#include <gtest/gtest.h>

#include <random>

#include "tape/damage.hpp"
#include "tape/encode.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

std::vector<Frame> sample_tape() {
    return encode(read_text(sample_path("gost-20999-format-example.txt")), EncodeOptions{.leader = 20, .trailer = 20});
}

RestoreResult restore_all(const std::vector<std::vector<Frame>>& reads, Dialect d = Dialect::gost) {
    std::vector<std::span<const Frame>> spans(reads.begin(), reads.end());
    return restore(spans, RestoreOptions{.code = FrameCode::iso(), .dialect = d});
}

const RestoreProblem* problem_at(const RestoreResult& r, std::uint64_t frame) {
    for (const auto& p : r.problems)
        if (p.frame == frame) return &p;
    return nullptr;
}

// The frame of the first occurrence of character c after `from`.
std::size_t find_char(const std::vector<Frame>& t, char c, std::size_t from = 0) {
    auto f = *FrameCode::iso().frame_for(static_cast<unsigned char>(c));
    return static_cast<std::size_t>(std::find(t.begin() + static_cast<std::ptrdiff_t>(from), t.end(), f) - t.begin());
}

}  // namespace

TEST(Align, ReadsOfDifferentLeadersDropsAndDoublesShareColumns) {
    auto tape = sample_tape();
    auto a = tape, b = tape;
    a.insert(a.begin(), 7, blank_frame);  // a longer leader
    b.erase(b.begin() + 60);              // a dropped frame
    b.insert(b.begin() + 90, b[90]);      // a frame read twice
    std::vector<std::span<const Frame>> reads{tape, a, b};
    ReadAlignment al = align_reads(reads);
    EXPECT_EQ(al.reference(), 1U);  // the longest
    // Every frame of the tape is in a column with the same frame of every read that has it.
    std::size_t checked = 0;
    for (std::size_t c = 0; c < al.columns(); ++c) {
        std::int32_t t = al.frame(c, 0), x = al.frame(c, 1);
        if (t != ReadAlignment::none && x != ReadAlignment::none) {
            EXPECT_EQ(tape[static_cast<std::size_t>(t)], a[static_cast<std::size_t>(x)]) << "column " << c;
            ++checked;
        }
    }
    EXPECT_EQ(checked, tape.size());
}

TEST(Align, ReadsOfAnotherTapeAreRefused) {
    auto tape = sample_tape();
    auto other = encode(read_text(sample_path("16k20f3s5-turning.txt")), EncodeOptions{.leader = 20, .trailer = 20});
    std::vector<std::span<const Frame>> reads{tape, other};
    try {
        align_reads(reads);
        FAIL() << "unrelated reads were aligned";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("different tapes"), std::string::npos) << e.what();
    }
}

TEST(Restore, ThreeReadsWithMixedDamageComeBackExact) {
    auto tape = sample_tape();
    auto a = tape, b = tape, c = tape;
    a[50] ^= 0x04;                                  // a flipped hole
    b.erase(b.begin() + 70);                        // a dropped frame
    c.insert(c.begin() + 80, c[80]);                // a doubled frame
    for (int i = 0; i < 4; ++i) a[100 + i] = 0x5A;  // a stain garbles four frames
    auto r = restore_all({a, b, c});
    EXPECT_EQ(r.frames, tape);
    EXPECT_TRUE(r.complete());
    EXPECT_EQ(r.count(FrameStatus::extra), 1U);
    EXPECT_GE(r.count(FrameStatus::voted), 6U);
    EXPECT_EQ(r.count(FrameStatus::unresolved) + r.count(FrameStatus::contested), 0U);
}

// A digit of X+10.: 1 and 3 both make a word that fits, so nothing decides.
TEST(Restore, ContestedWhenTwoGoodReadsDisagree) {
    auto tape = sample_tape();
    auto a = tape, b = tape;
    std::size_t x = find_char(tape, 'X', 30) + 2;
    b[x] = *FrameCode::iso().frame_for('3');  // good parity, another digit
    auto r = restore_all({a, b});
    const RestoreProblem* p = problem_at(r, x + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::contested);
    EXPECT_FALSE(r.complete());
    EXPECT_EQ(r.frames.size(), tape.size());
}

TEST(Restore, UnstableWhenEveryReadSawSomethingElse) {
    auto tape = sample_tape();
    auto a = tape, b = tape, c = tape;
    std::size_t x = find_char(tape, 'X', 30) + 2;
    a[x] = *FrameCode::iso().frame_for('3');
    b[x] = *FrameCode::iso().frame_for('5');
    auto r = restore_all({a, b, c});
    const RestoreProblem* p = problem_at(r, x + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::unstable);
}

// Good readings that disagree where only one makes the block fit: "Y+10. Y+20." repeats Y, so the
// program's rules vote X, and the reason says so.
TEST(Restore, GoodReadingsTheRulesChooseBetweenAreVoted) {
    auto tape = sample_tape();
    auto a = tape, b = tape;
    std::size_t x = find_char(tape, 'X', 30);
    b[x] = *FrameCode::iso().frame_for('Y');  // good parity, another letter
    auto r = restore_all({a, b});
    EXPECT_EQ(r.frames, tape);
    const RestoreProblem* p = problem_at(r, x + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::voted);
    EXPECT_NE(p->reason.find("the program's rules leave one"), std::string::npos) << p->reason;
    EXPECT_TRUE(r.complete());
}

TEST(Restore, AParityErrorOutvotedByGoodReads) {
    auto tape = sample_tape();
    auto a = tape, b = tape;
    a[40] ^= 0x10;
    auto r = restore_all({a, b});
    EXPECT_EQ(r.frames, tape);
    const RestoreProblem* p = problem_at(r, 41);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::voted);
    EXPECT_NE(p->reason.find("parity"), std::string::npos) << p->reason;
}

TEST(Restore, SingleReadRepairWhenExactlyOneChangeFitsTheBlock) {
    auto tape = sample_tape();
    auto a = tape;
    // A decimal point: of its eight single-hole changes only '.' makes "X+10." a word ('/' would be
    // a block skip out of place, letters and digits there read as other words that break the block).
    std::size_t g = find_char(tape, '.', 30);
    a[g] ^= 0x01;
    auto r = restore_all({a});
    const RestoreProblem* p = problem_at(r, g + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::inferred) << p->reason << " candidates " << p->candidates.size();
    EXPECT_EQ(r.frames, tape);
}

// Two damaged frames in one block are tried together: alone, each would be checked against a block
// still holding the other's damage, and nothing would fit.
TEST(Restore, DamagedFramesOfOneBlockAreRepairedTogether) {
    auto tape = sample_tape();
    auto a = tape;
    std::size_t x = find_char(tape, '.', 30);  // "X+10." and "Y+20." of one block
    std::size_t y = find_char(tape, '.', x + 1);
    ASSERT_LT(y - x, 8U);
    a[x] ^= 0x01;
    a[y] ^= 0x01;
    auto r = restore_all({a});
    for (std::size_t i : {x, y}) {
        const RestoreProblem* p = problem_at(r, i + 1);
        ASSERT_NE(p, nullptr);
        EXPECT_EQ(p->status, FrameStatus::inferred) << p->reason << " candidates " << p->candidates.size();
        EXPECT_NE(p->reason.find("other damaged frames"), std::string::npos) << p->reason;
    }
    EXPECT_EQ(r.frames, tape);
}

TEST(Restore, AmbiguousRepairStaysUnresolvedAsRead) {
    auto tape = sample_tape();
    auto a = tape;
    // The G of "G90": D90, B90, N90, V90 and F90 read as well as G90 does, so nothing is guessed.
    std::size_t g = find_char(tape, 'G', 30);
    a[g] ^= 0x01;
    auto r = restore_all({a});
    const RestoreProblem* p = problem_at(r, g + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::unresolved) << p->reason;
    EXPECT_EQ(r.frames[g], a[g]);  // written as read
    EXPECT_GT(p->candidates.size(), 1U);
    EXPECT_NE(std::find(p->candidates.begin(), p->candidates.end(), tape[g]), p->candidates.end());
}

TEST(Restore, MissingStartWhenNoReadHasLeader) {
    auto tape = sample_tape();
    std::vector<Frame> late(tape.begin() + 25, tape.end());
    auto r = restore_all({late, late});
    EXPECT_EQ(r.missing_start, 1U);
    EXPECT_EQ(r.count(FrameStatus::missing), 1U);
    EXPECT_FALSE(r.complete());
}

TEST(Restore, BinaryTapesAreMergedByVoteAlone) {
    std::mt19937 rng(7);
    std::vector<Frame> tape(3000);
    for (auto& f : tape) f = static_cast<Frame>(rng());
    tape.insert(tape.begin(), 30, blank_frame);
    tape.insert(tape.end(), 30, blank_frame);
    auto a = tape, b = tape, c = tape;
    a[500] ^= 0x80;
    b.erase(b.begin() + 900);
    c[1500] ^= 0x01;
    std::vector<std::span<const Frame>> reads{a, b, c};
    auto r = restore(reads, RestoreOptions{});
    EXPECT_EQ(r.frames, tape);
}

// Never worse: over random damage, wherever a read has the right frame and it is good, the output
// holds the right frame or says it could not decide (contested, unstable); it is never silently wrong.
TEST(Restore, AFrameCleanInSomeReadIsNeverWorseInTheOutput) {
    auto tape = sample_tape();
    for (unsigned seed = 1; seed <= 30; ++seed) {
        std::mt19937 rng(seed);
        std::vector<std::vector<Frame>> reads;
        for (int k = 0; k < 3; ++k) {
            auto read = tape;
            for (std::size_t i = 0; i < read.size(); ++i)
                if (rng() % 100 == 0) read[i] ^= static_cast<Frame>(1U << (rng() % 8));
            reads.push_back(read);
        }
        auto r = restore_all(reads);
        ASSERT_EQ(r.frames.size(), tape.size()) << "seed " << seed;
        for (std::size_t i = 0; i < tape.size(); ++i) {
            if (r.frames[i] == tape[i]) continue;
            const RestoreProblem* p = problem_at(r, i + 1);
            ASSERT_NE(p, nullptr) << "seed " << seed << " frame " << i + 1 << " silently wrong";
            EXPECT_TRUE(p->status == FrameStatus::contested || p->status == FrameStatus::unstable ||
                        p->status == FrameStatus::unresolved)
                << "seed " << seed << " frame " << i + 1 << " " << status_name(p->status);
            bool clean_somewhere = false;
            for (const auto& read : reads) clean_somewhere |= read[i] == tape[i];
            if (clean_somewhere) {
                EXPECT_NE(p->status, FrameStatus::unresolved) << "seed " << seed;
            }
        }
    }
}

// Reads that each lost a different one of two neighbouring frames, the longest read (the reference)
// among them: two frames the reference lacks must not be paired with each other as one misread frame.
TEST(Restore, NeighbouringFramesLostByDifferentReads) {
    auto tape = sample_tape();
    std::size_t x = find_char(tape, 'X', 30);
    auto a = tape, b = tape, c = tape;
    a.erase(a.begin() + static_cast<std::ptrdiff_t>(x));      // the reference: the first of the longest
    b.erase(b.begin() + static_cast<std::ptrdiff_t>(x + 1));  // the next frame
    c.erase(c.begin() + 200);                                 // elsewhere, so that no read is longer
    auto r = restore_all({a, b, c});
    EXPECT_EQ(r.frames, tape);
    // Two reads slipped in one stretch: each frame is written as two of three have it, and said to be
    // in doubt, since one slip can hide another there.
    for (std::size_t i : {x, x + 1}) {
        const RestoreProblem* p = problem_at(r, i + 1);
        ASSERT_NE(p, nullptr);
        EXPECT_EQ(p->status, FrameStatus::contested) << p->reason;
    }
}

// A stain on the reference read in blank leader: its frames are misreadings, and the leader the
// other reads have is kept, however the blank frames pair.
TEST(Restore, AStainInTheLeaderOfTheReference) {
    auto tape = sample_tape();
    auto a = tape, b = tape, c = tape;
    const Frame stain[] = {0x88, 0xF3, 0x0A, 0xF9};  // the second and fourth fail parity
    for (std::size_t i = 0; i < 4; ++i) a[5 + i] = stain[i];
    a.insert(a.begin() + 150, a[150]);  // and the longest
    auto r = restore_all({a, b, c});
    EXPECT_EQ(r.frames, tape);
    EXPECT_TRUE(r.complete());
}

// A stain whose last garbled frame was equal to the frame before it: dynamic programming may pair
// that frame either way in each read; the reads that read it well must still share its column.
TEST(Restore, AStainNextToAnEqualFrame) {
    auto tape = sample_tape();
    // Find a frame equal to the one four places on: "...39 0a 4e b1 39...".
    std::size_t x = 30;
    while (x + 5 < tape.size() && !(tape[x] == tape[x + 4] && tape[x] != blank_frame && tape[x + 1] != tape[x])) ++x;
    ASSERT_LT(x + 5, tape.size());
    auto a = tape, b = tape, c = tape;
    const Frame stain[] = {0xC8, 0x7B, 0x3B, 0x63};
    for (std::size_t i = 0; i < 4; ++i) a[x + 1 + i] = stain[i];
    a.insert(a.begin() + 150, a[150]);  // the longest: the reference
    auto r = restore_all({a, b, c});
    EXPECT_EQ(r.frames, tape);
    EXPECT_TRUE(r.complete());
}

// Two of three reads lost the same frame, unlike its neighbours: no read twice made it, so the one
// read that has it is not outvoted into silence. It is written, and contested.
namespace {

// Three reads of tape, two of which lost frame x.
RestoreResult lost_by_two_of_three(const std::vector<Frame>& tape, std::size_t x) {
    auto a = tape, b = tape, c = tape;
    b.erase(b.begin() + static_cast<std::ptrdiff_t>(x));
    c.erase(c.begin() + static_cast<std::ptrdiff_t>(x));
    return restore_all({a, b, c});
}

}  // namespace

// The 2 of "Y+20." lost by two reads of three: "Y+0." is a word too, so nothing decides.
TEST(Restore, AFrameTwoReadsLostIsContestedNotDropped) {
    auto tape = sample_tape();
    std::size_t x = find_char(tape, 'Y', 30) + 2;
    ASSERT_EQ(tape[x], *FrameCode::iso().frame_for('2'));
    ASSERT_NE(tape[x - 1], tape[x]);
    ASSERT_NE(tape[x + 1], tape[x]);
    auto r = lost_by_two_of_three(tape, x);
    EXPECT_EQ(r.frames, tape);
    const RestoreProblem* p = problem_at(r, x + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::contested) << p->reason;
    EXPECT_FALSE(r.complete());
}

// The X of "X+10." lost by two reads of three: "+10." with no letter is no word, so the program's rules
// write it, and say so; one read alone backs what it is, so it stays in doubt.
TEST(Restore, AFrameTwoReadsLostThatTheBlockNeedsIsWritten) {
    auto tape = sample_tape();
    std::size_t x = find_char(tape, 'X', 30);
    auto r = lost_by_two_of_three(tape, x);
    EXPECT_EQ(r.frames, tape);
    const RestoreProblem* p = problem_at(r, x + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::contested) << p->reason;
    EXPECT_NE(p->reason.find("the program's rules decide that it stands here (without it the block breaks"),
              std::string::npos)
        << p->reason;
}

// Reads that disagree on how many times a frame is punched: two have the letter X twice, the third
// once. Two reads doubling the same frame is far less likely than one losing it, but "XX" is no word:
// the program's grammar decides the run, and the summary counts it as voted on a run length.
TEST(Restore, ARunTheGrammarDecidesOutweighsTheOdds) {
    auto tape = sample_tape();
    std::size_t x = find_char(tape, 'X', 30);
    auto a = tape, b = tape, c = tape;
    a.insert(a.begin() + static_cast<std::ptrdiff_t>(x), tape[x]);
    b.insert(b.begin() + static_cast<std::ptrdiff_t>(x), tape[x]);
    auto r = restore_all({a, b, c});
    EXPECT_EQ(r.frames, tape);
    EXPECT_EQ(r.run_length_votes, 1U);
    EXPECT_TRUE(r.complete());
    ASSERT_EQ(r.problems.size(), 1U);
    EXPECT_TRUE(r.problems[0].run_length);
    EXPECT_NE(r.problems[0].reason.find("rules decide"), std::string::npos) << r.problems[0].reason;
}

// A hole in blank leader, in the one read there is: blank tape on both sides is the grammar that
// fits, not a character the block around it would also take.
TEST(Restore, AHoleInBlankLeaderIsRepairedToBlank) {
    auto tape = sample_tape();
    auto a = tape;
    a[10] = 0x02;
    auto r = restore_all({a});
    EXPECT_EQ(r.frames, tape);
    const RestoreProblem* p = problem_at(r, 11);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::inferred);
}

// Over random damage of every kind (tape::damage: flips, drops, doubles, stains), three reads of 1%
// each: the output is checked against the tape, and what is wrong must be in doubt in the report.
TEST(Restore, MixedDamageIsNeverSilentlyWrong) {
    auto tape = sample_tape();
    std::uint64_t silently_wrong = 0, exact = 0;
    constexpr std::uint64_t sets = 300;
    for (std::uint64_t seed = 0; seed < sets; ++seed) {
        std::vector<std::vector<Frame>> reads;
        for (std::uint64_t k = 0; k < 3; ++k) reads.push_back(damage(tape, mixed_damage(0.01, seed * 3 + k + 1)));
        auto check = check_restore(tape, restore_all(reads));
        silently_wrong += check.silently_wrong;
        exact += check.exact;
    }
    // 300 x 392 frames: none wrong unsaid but for one set whose reads were each damaged in the last
    // frames of the tape (a stain on one, a read twice on another), where every read ends differently.
    EXPECT_LE(silently_wrong, 2U);
    EXPECT_GE(exact, sets * 9 / 10);
}

// Two good readings tied, and a third failing parity one hole from one of them: contested, so the frame
// stays as read, failing parity (the image says it is in doubt); the reading the failing one leans to is
// the first candidate.
TEST(Restore, AParityErrorLeansATieBetweenGoodReadings) {
    auto tape = sample_tape();
    std::size_t x = find_char(tape, 'X', 30) + 2;
    auto a = tape, b = tape, c = tape;
    b[x] = *FrameCode::iso().frame_for('3');  // good parity, two holes from 1
    c[x] ^= 0x04;                             // 1 with a hole lost or gained
    auto r = restore_all({a, b, c});
    EXPECT_EQ(r.frames[x], c[x]);
    const RestoreProblem* p = problem_at(r, x + 1);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->status, FrameStatus::contested) << p->reason;
    ASSERT_FALSE(p->candidates.empty());
    EXPECT_EQ(p->candidates.front(), tape[x]);
}

// Two reads, one with a frame the other lacks: like its neighbour it may have been read twice, and "XX"
// is no word, so the grammar leaves it out; unlike them it could not be read twice, and "+10." without
// its X is no word, so the grammar writes it (in doubt: one read alone backs what it is).
TEST(Restore, OneOfTwoReadsWithAFrameMoreWritesItOnlyUnlikeItsNeighbours) {
    auto tape = sample_tape();
    std::size_t x = find_char(tape, 'X', 30);
    auto doubled = tape, dropped = tape;
    doubled.insert(doubled.begin() + static_cast<std::ptrdiff_t>(x), tape[x]);
    dropped.erase(dropped.begin() + static_cast<std::ptrdiff_t>(x));
    auto r = restore_all({doubled, tape});
    EXPECT_EQ(r.frames, tape);
    EXPECT_EQ(r.count(FrameStatus::contested), 0U);
    EXPECT_EQ(r.run_length_votes, 1U);
    auto s = restore_all({tape, dropped});
    EXPECT_EQ(s.frames, tape);
    EXPECT_EQ(s.count(FrameStatus::contested), 1U);
}

// Two reads: one read a frame twice, the other misread a hole three frames on. The extra frame is
// never written as clean, and the frames both reads have are not put in doubt.
TEST(Restore, ADoubleNearAFlipInTheOtherOfTwoReads) {
    auto tape = sample_tape();
    std::size_t x = find_char(tape, 'X', 30);
    auto a = tape, b = tape;
    a.insert(a.begin() + static_cast<std::ptrdiff_t>(x), tape[x]);
    b[x + 3] ^= 0x02;
    auto r = restore_all({a, b});
    EXPECT_EQ(r.frames, tape);
    for (const auto& p : r.problems) {
        if (p.frame && *p.frame != x + 4) {
            EXPECT_NE(p.status, FrameStatus::clean);
        }
    }
}

// Two reads, one stained over a long stretch: the stain fails parity in places, the other read's
// frames hold it everywhere, so the other read is heard there and its frames are written.
TEST(Restore, ALongStainInOneOfTwoReadsKeepsTheOther) {
    auto tape = sample_tape();
    auto stained = tape;
    std::mt19937 rng(3);
    for (std::size_t i = 60; i < 120; ++i) stained[i] = static_cast<Frame>(rng());
    auto r = restore_all({stained, tape});
    EXPECT_EQ(r.frames, tape);
}

// A stretch torn from one of two reads is written whole from the other, in doubt.
TEST(Restore, AStretchTornFromOneOfTwoReadsIsWrittenWhole) {
    auto tape = sample_tape();
    auto torn = tape;
    torn.erase(torn.begin() + 60, torn.begin() + 100);
    auto r = restore_all({torn, tape});
    EXPECT_EQ(r.frames, tape);
    EXPECT_EQ(r.count(FrameStatus::contested), 40U);
}

// Clean reads with leaders of different length: nothing is in doubt.
TEST(Restore, LeadersOfDifferentLengthAreNotInDoubt) {
    auto tape = sample_tape();
    auto longer = tape;
    longer.insert(longer.begin(), 150, blank_frame);
    longer[40] = 0x10;  // and a hole in it
    auto r = restore_all({longer, tape});
    EXPECT_TRUE(r.complete());
    EXPECT_EQ(r.count(FrameStatus::contested), 0U);
}
