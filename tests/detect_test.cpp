// Telling ISO from EIA, and finding the parity convention of a tape.
#include "tape/detect.hpp"

#include <gtest/gtest.h>

#include "tape/encode.hpp"
#include "test_util.hpp"

using namespace tape;

TEST(DetectCode, SamplesOfBothCodes) {
    EXPECT_EQ(detect_code(read_frames(sample_path("gost-20999-format-example.iso.ptp"))).code, Code::iso);
    EXPECT_EQ(detect_code(read_frames(sample_path("16k20f3s5-turning.iso.ptp"))).code, Code::iso);
    EXPECT_EQ(detect_code(read_frames(sample_path("gost-20999-format-example.eia.ptp"))).code, Code::eia);
    EXPECT_EQ(detect_code(read_frames(sample_path("16k20f3s5-turning.eia.ptp"))).code, Code::eia);
}

TEST(DetectCode, LabelBeforeTheProgramDoesNotConfuseIt) {
    std::string text = "PART 7-114 REV B\n%\nN1 G1 X1\nN2 M2\n";
    EXPECT_EQ(detect_code(encode(text, {})).code, Code::iso);
    EXPECT_EQ(detect_code(encode(text, EncodeOptions{.code = Code::eia})).code, Code::eia);
}

TEST(DetectCode, BlankTapeIsReadAsIso) { EXPECT_EQ(detect_code(std::vector<Frame>(50, 0)).code, Code::iso); }

TEST(DetectCode, MarkParityTapeIsRecognisedAndExplained) {
    auto t = encode("HELLO WORLD\nSECOND LINE\n", EncodeOptions{.parity = Parity::mark});
    auto d = detect_code(t);
    EXPECT_FALSE(d.code);
    EXPECT_NE(d.reason.find("mark parity"), std::string::npos) << d.reason;
    EXPECT_EQ(d.reason.find("--"), std::string::npos) << "no command-line option in a library message: " << d.reason;
    EXPECT_EQ(d.hint.action, Hint::Action::use_iso_parity);
    EXPECT_EQ(d.hint.value, "mark");
}

TEST(DetectCode, NoiseFitsNeither) {
    std::vector<Frame> noise;
    for (int i = 0; i < 64; ++i) noise.push_back(static_cast<Frame>(i * 37 + 11));
    auto d = detect_code(noise);
    EXPECT_FALSE(d.code);
    EXPECT_NE(d.reason.find("neither ISO nor EIA"), std::string::npos);
    EXPECT_FALSE(d.hint) << "no advice that would not read the tape cleanly";
}

TEST(DetectCode, EveryVerdictGivesItsEvidence) {
    auto d = detect_code(read_frames(sample_path("gost-20999-format-example.iso.ptp")));
    EXPECT_EQ(d.kind, TapeKind::iso);
    EXPECT_TRUE(d.clean);
    EXPECT_EQ(d.evidence.frames, 392U);
    EXPECT_EQ(d.evidence.punched, 192U);
    EXPECT_EQ(d.evidence.iso_lf, 11U);
    EXPECT_EQ(d.evidence.fits[0].bad_frames, 0U);
    EXPECT_EQ(d.evidence.fits[0].end_of_blocks, 11U);
    EXPECT_EQ(d.evidence.fits[1].bad_frames, 192U) << "every ISO frame fails EIA's odd parity";
    EXPECT_NE(d.reason.find("192 of 192 punched frames"), std::string::npos) << d.reason;
}

TEST(DetectCode, DecidesFromTheWholeTapeNotTheFirstBlock) {
    // A label of EIA-looking frames before the first end of block, then a long ISO program: the whole
    // tape says ISO.
    std::vector<Frame> t = {0x0B, 0x13, 0x15};
    std::string program = "%\n";
    for (int i = 1; i < 50; ++i) program += "N" + std::to_string(i) + " G01 X" + std::to_string(i * 7) + "\n";
    auto iso = encode(program, EncodeOptions{.leader = 0});
    t.insert(t.end(), iso.begin(), iso.end());
    auto d = detect_code(t);
    EXPECT_EQ(d.code, Code::iso) << d.reason;
    EXPECT_EQ(d.evidence.fits[0].bad_frames, 3U);
}

TEST(DetectCode, MarkParityAdviceOnlyWhenItReadsCleanly) {
    std::string text;
    for (int i = 0; i < 40; ++i) text += "LINE " + std::to_string(i) + " OF AN ASR-33 TAPE\n";
    auto t = encode(text, EncodeOptions{.parity = Parity::mark});
    auto d = detect_code(t);
    EXPECT_EQ(d.kind, TapeKind::ascii);
    EXPECT_EQ(d.reading, (Reading{Code::iso, Parity::mark}));
    EXPECT_TRUE(d.clean);
    EXPECT_EQ(d.hint.action, Hint::Action::use_iso_parity);
    // Damage beyond one frame in a thousand: still an ASCII tape with mark parity, but no advice.
    for (std::size_t i = 120; i < 140; i += 2) t[i] &= 0x7F;
    d = detect_code(t);
    EXPECT_EQ(d.kind, TapeKind::ascii) << d.reason;
    EXPECT_FALSE(d.clean);
    EXPECT_FALSE(d.hint) << d.reason;
    EXPECT_NE(d.reason.find("frame(s) fail"), std::string::npos) << d.reason;
}

TEST(DetectCode, FiveTrackTape) {
    std::vector<Frame> t(20, 0);
    for (int i = 0; i < 200; ++i) t.push_back(static_cast<Frame>(1 + (i * 7) % 31));
    auto d = detect_code(t);
    EXPECT_EQ(d.kind, TapeKind::five_track) << d.reason;
    EXPECT_FALSE(d.code);
    EXPECT_EQ(d.hint.action, Hint::Action::use_five_track_code);
    EXPECT_NE(d.reason.find("5-track tape"), std::string::npos);
    EXPECT_EQ(d.reason.find("--"), std::string::npos) << d.reason;
    EXPECT_EQ(detect_code(read_frames(sample_path("bad/ita2-5-track.ptp"))).kind, TapeKind::five_track);
}

TEST(DetectCode, DecBinaryTape) {
    auto d = detect_code(read_frames(sample_path("bad/pdp8-bin-loader.bin")));
    EXPECT_EQ(d.kind, TapeKind::binary) << d.reason;
    EXPECT_FALSE(d.code);
    EXPECT_FALSE(d.hint);
    EXPECT_EQ(d.reason.rfind("binary tape, not a character code", 0), 0U) << d.reason;
    EXPECT_EQ(d.evidence.longest_0x80_run, 60U);
}

TEST(DetectCode, RandomFramesAreBinary) {
    std::vector<Frame> t;
    std::uint32_t x = 12345;
    for (int i = 0; i < 4000; ++i) {
        x = x * 1103515245 + 12345;
        t.push_back(static_cast<Frame>(x >> 16));
    }
    auto d = detect_code(t);
    EXPECT_EQ(d.kind, TapeKind::binary) << d.reason;
}

TEST(DetectCode, TextFileGivenAsAnImage) {
    std::string text = "%\nN1 G01 X10\nN2 M02\n";
    std::vector<Frame> t(text.begin(), text.end());
    auto d = detect_code(t);
    EXPECT_EQ(d.kind, TapeKind::text) << d.reason;
    EXPECT_EQ(d.hint.action, Hint::Action::encode_text);
    Detector holes(nullptr, false);  // frames from a holes picture are no file's bytes
    holes.feed(t);
    EXPECT_NE(holes.result().kind, TapeKind::text);
}

TEST(DetectCode, SameVerdictHoweverCut) {
    auto t = read_frames(sample_path("16k20f3s5-turning.eia.ptp"));
    Detector d;
    for (std::size_t i = 0; i < t.size(); i += 7)
        d.feed(std::span(t).subspan(i, std::min<std::size_t>(7, t.size() - i)));
    EXPECT_EQ(d.result().reason, detect_code(t).reason);
}

TEST(OtherReading, ForcedWrongCodeIsToldTheCleanOne) {
    auto d = detect_code(read_frames(sample_path("16k20f3s5-turning.iso.ptp")));
    auto note = other_reading(d, Reading{Code::eia, Parity::odd});
    ASSERT_TRUE(note);
    EXPECT_NE(note->message.find("reads cleanly as ISO"), std::string::npos) << note->message;
    EXPECT_EQ(note->hint.action, Hint::Action::use_code);
    EXPECT_EQ(note->hint.value, "iso");
    note = other_reading(d, Reading{Code::iso, Parity::mark});
    ASSERT_TRUE(note);
    EXPECT_EQ(note->hint.action, Hint::Action::use_iso_parity);
    EXPECT_FALSE(other_reading(d, Reading{Code::iso, Parity::even}));
}

TEST(ParityCounts, FindsEachConvention) {
    std::string text = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789\n";
    for (Parity p : {Parity::even, Parity::odd, Parity::mark, Parity::space}) {
        auto c = count_parity(encode(text, EncodeOptions{.parity = p}));
        EXPECT_EQ(c.dominant(), p) << parity_name(p);
        EXPECT_EQ(c.misfits(p), 0U);
    }
}

TEST(ParityCounts, MixedWhenNoRuleFitsNineInTen) {
    std::vector<Frame> t = {0x41, 0xC1, 0x42, 0xC2, 0x43, 0x44};  // half even, half odd, track 8 on two
    EXPECT_FALSE(count_parity(t).dominant());
    EXPECT_FALSE(count_parity(std::vector<Frame>(3, 0)).dominant());
}

TEST(DetectCode, AnEiaTapeStartingWithEndsOfBlockIsEia) {
    auto t = read_frames(sample_path("16k20f3s5-turning.eia.ptp"));
    std::vector<Frame> eob_first(25, 0x80);
    eob_first.insert(eob_first.end(), t.begin(), t.end());
    auto d = detect_code(eob_first);
    EXPECT_EQ(d.kind, TapeKind::eia) << d.reason;
}

TEST(DetectCode, Koi7LettersAreSeen) {
    auto d = detect_code(read_frames(sample_path("koi7-comment.iso.ptp")));
    EXPECT_EQ(d.kind, TapeKind::iso);
    EXPECT_TRUE(looks_like_koi7(d.evidence)) << d.evidence.koi7_letters;
    EXPECT_FALSE(looks_like_koi7(detect_code(read_frames(sample_path("16k20f3s5-turning.iso.ptp"))).evidence));
}

namespace {

std::vector<tape::Frame> random_frames(int n) {
    std::vector<tape::Frame> t;
    std::uint32_t x = 12345;
    for (int i = 0; i < n; ++i) {
        x = x * 1103515245 + 12345;
        t.push_back(static_cast<tape::Frame>(x >> 16));
    }
    return t;
}

// Two reads of an ISO tape and a longer read of noise: the two decide, and the verdict is drawn from the
// longer of them. EIA reads outnumbering ISO ones win; no read in a code gives the longest read's verdict.
TEST(DetectCodeOfReads, MostReadsDecideNotTheLongest) {
    using namespace tape;
    std::string text = "%\nN1 G01 X10 Y20 F100\nN2 M02\n%\n";
    auto iso = encode(text, {});
    auto iso_long = encode(text, EncodeOptions{.leader = 2 * default_leader});
    auto eia = encode(text, EncodeOptions{.code = Code::eia});
    auto noise = random_frames(4000);
    std::vector<std::span<const Frame>> reads{iso, noise, iso_long};
    auto v = detect_code_of_reads(reads);
    EXPECT_EQ(v.detection.code, Code::iso);
    EXPECT_EQ(v.from, 2u);
    EXPECT_EQ(v.agreeing, 2u);
    std::vector<std::span<const Frame>> mixed{iso_long, eia, eia};
    EXPECT_EQ(detect_code_of_reads(mixed).detection.code, Code::eia);
    auto short_noise = random_frames(100);
    std::vector<std::span<const Frame>> none{noise, short_noise};
    auto n = detect_code_of_reads(none);
    EXPECT_EQ(n.from, 0u);
    EXPECT_EQ(n.agreeing, 0u);
    EXPECT_EQ(n.detection.kind, TapeKind::binary);
}

}  // namespace
