// Searches a tape reader performs: main blocks forward, the rewind stop backward, programs, blocks.
#include "tape/search.hpp"

#include <gtest/gtest.h>

#include "tape/decode.hpp"
#include "tape/encode.hpp"

using namespace tape;

namespace {
LoadedTape tape_of(const std::string& text) {
    auto r = decode(encode(text, EncodeOptions{.leader = 10, .trailer = 10}), DecodeOptions{.positions = true});
    return load(r.text, r.frame_of);
}
const std::string two_programs = "%10\n:1 G90\nN2 X1\n:3 G91\nN4 M02\n%20\nN1 X1\n:5 X2\nN6 M30\n";
}  // namespace

TEST(Search, MainBlocksForwardFromAFrame) {
    LoadedTape t = tape_of(two_programs);
    auto first = find_main_block(t, 0);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->block->number_text(), ":1");
    EXPECT_EQ(first->block->where.frame, 15U);  // 10 leader, "%10" LF, then ':'
    auto next = find_main_block(t, first->block->where.offset + 1);
    EXPECT_EQ(next->block->number_text(), ":3");
    auto numbered = find_main_block(t, 0, 5);
    EXPECT_EQ(numbered->program->number, "20");
    EXPECT_FALSE(find_main_block(t, numbered->block->where.offset + 1));
    EXPECT_EQ(main_blocks(t).size(), 3U);
}

TEST(Search, FrameOffsetFindsTheFirstCharacterAtOrAfterAFrame) {
    LoadedTape t = tape_of(two_programs);
    EXPECT_EQ(frame_offset(t, 1), 0U);
    EXPECT_EQ(frame_offset(t, 15), 4U);  // ':' is the fifth character
    EXPECT_EQ(frame_offset(t, 100000), t.text.size());
}

TEST(Search, RewindStopsAtTheLastPercentBefore) {
    LoadedTape t = tape_of(two_programs);
    auto main5 = find_main_block(t, 0, 5);
    const Program* stop = find_rewind_stop(t, main5->block->where.offset);
    ASSERT_TRUE(stop);
    EXPECT_EQ(stop->number, "20");
    EXPECT_EQ(find_rewind_stop(t, t.programs[1].start.offset), &t.programs[0]);
    EXPECT_EQ(find_rewind_stop(t, 0), nullptr);
}

TEST(Search, ProgramsAndBlocksByNumber) {
    LoadedTape t = tape_of(two_programs);
    EXPECT_EQ(find_program(t, "20"), &t.programs[1]);
    EXPECT_EQ(find_program(t, "010"), &t.programs[0]);
    EXPECT_EQ(find_program(t, "30"), nullptr);
    EXPECT_EQ(find_numbered_blocks(t, 1).size(), 2U);  // :1 and N1
    EXPECT_EQ(find_numbered_blocks(t, 7).size(), 0U);
}

TEST(Search, TextInputCountsLines) {
    LoadedTape t = load(two_programs);
    EXPECT_EQ(frame_offset(t, 3), 11U);  // line 3 starts at "N2"
    EXPECT_EQ(find_main_block(t, frame_offset(t, 3))->block->number_text(), ":3");
}
