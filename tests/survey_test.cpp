// The counts behind `tape info`.
#include "tape/survey.hpp"

#include <gtest/gtest.h>

#include "tape/encode.hpp"

using namespace tape;

TEST(Survey, CountsEveryKindOfFrame) {
    auto t = encode("%%\nN1\n%\nN2\n", EncodeOptions{.leader = 5, .trailer = 7});
    t.insert(t.begin() + 8, 0xFF);   // DEL inside
    t.insert(t.begin() + 9, 0x00);   // blank inside
    t.insert(t.begin() + 10, 0x01);  // parity error
    auto s = survey(t, FrameCode::iso());
    EXPECT_EQ(s.frames, t.size());
    EXPECT_EQ(s.leader, 5U);
    EXPECT_EQ(s.trailer, 7U);
    EXPECT_EQ(s.rubouts, 1U);
    EXPECT_EQ(s.blank_inside, 1U);
    EXPECT_EQ(s.parity_errors, 1U);
    EXPECT_EQ(s.data, 11U);
    EXPECT_EQ(s.program_starts, 2U);  // "%%" is the physical start plus one program
    EXPECT_EQ(s.end_of_blocks, 4U);
    EXPECT_EQ(s.leader + s.data + s.rubouts + s.blank_inside + s.parity_errors + s.trailer, s.frames);
}

TEST(Survey, EiaFramesOutsideTheTableAreCountedApart) {
    std::vector<Frame> t = {0, 0x0B, 0x80, 0x0D, 0x02, 0x80, 0};
    auto s = survey(t, FrameCode::eia());
    EXPECT_EQ(s.not_in_code, 1U);
    EXPECT_EQ(s.parity_errors, 0U);
    EXPECT_EQ(s.program_starts, 1U);
    EXPECT_EQ(s.data, 4U);
}

TEST(Survey, TheClosingPercentStartsNoProgram) {
    auto one = survey(encode("%\nO1\nG01 X1\nM30\n%\n", EncodeOptions{}), FrameCode::iso());
    EXPECT_EQ(one.program_starts, 1U);
    auto two = survey(encode("%\nO1\nM30\n%\n%\nO2\nM30\n%", EncodeOptions{}), FrameCode::iso());
    EXPECT_EQ(two.program_starts, 2U);
}
