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
