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

// The streaming search, fed by the loader, finds what the searches over the whole tape find, from
// every frame of the tape.
TEST(Searcher, FindsWhatTheWholeTapeSearchesFindFromEveryFrame) {
    LoadedTape t = tape_of(two_programs);
    auto run = [&](SearchQuery q) {
        Searcher s(q);
        load_each(t.text, t.frame_of, s);
        std::vector<std::uint64_t> offsets;
        for (const auto& h : s.hits()) offsets.push_back(h.where.offset);
        return offsets;
    };
    std::uint64_t last_frame = t.frame_of.back() + 2;
    for (std::uint64_t frame = 0; frame <= last_frame; ++frame) {
        SCOPED_TRACE("from frame " + std::to_string(frame));
        std::uint64_t from = frame_offset(t, frame);
        for (std::optional<long long> number : {std::optional<long long>{}, std::optional<long long>{5}}) {
            std::vector<std::uint64_t> whole;
            for (auto r = find_main_block(t, from, number); r;
                 r = find_main_block(t, r->block->where.offset + 1, number))
                whole.push_back(r->block->where.offset);
            EXPECT_EQ(run(SearchQuery{
                          .kind = SearchQuery::Kind::main_block, .number = number, .from = frame, .from_tape = true}),
                      whole);
        }
        const Program* stop = find_rewind_stop(t, from);
        auto rewind = run(SearchQuery{.kind = SearchQuery::Kind::rewind_stop, .from = frame, .from_tape = true});
        EXPECT_EQ(rewind, stop ? std::vector<std::uint64_t>{stop->start.offset} : std::vector<std::uint64_t>{});
    }
    EXPECT_EQ(run(SearchQuery{.kind = SearchQuery::Kind::program, .program = "020"}),
              std::vector<std::uint64_t>{find_program(t, "20")->start.offset});
    std::vector<std::uint64_t> numbered;
    for (auto r : find_numbered_blocks(t, 1)) numbered.push_back(r.block->where.offset);
    EXPECT_EQ(run(SearchQuery{.kind = SearchQuery::Kind::numbered_block, .number = 1}), numbered);
}

// A Fanuc program found by number is shown by its O block, where it stands (the shape of
// cade_O58214.nc: '%', then "O58214" on its own line): not "%O58214" at the '%'.
TEST(Searcher, AFanucProgramIsShownByItsOBlock) {
    auto run = [](const std::string& text) {
        Searcher s(SearchQuery{.kind = SearchQuery::Kind::program, .program = "58214"});
        load_each(text, {}, s, LoadOptions{Dialect::automatic});
        return s.hits();
    };
    auto own_line = run("%\nO58214 \n(BORED PART)\nG18 G40 G80 G99\nM30\n%\n");
    ASSERT_EQ(own_line.size(), 1U);
    EXPECT_EQ(own_line[0].text, "O58214");
    EXPECT_EQ(own_line[0].where.line, 2U);
    auto after_comment = run("%\n(HEADER)\nO58214 (BORED PART)\nG18 G40 G80 G99\nM30\n%\n");
    ASSERT_EQ(after_comment.size(), 1U);
    EXPECT_EQ(after_comment[0].text, "O58214 (BORED PART)");
    EXPECT_EQ(after_comment[0].where.line, 3U);
    auto on_percent_line = run("%O58214(BORED PART)\nG18 G40 G80 G99\nM30\n%\n");
    ASSERT_EQ(on_percent_line.size(), 1U);
    EXPECT_EQ(on_percent_line[0].text, "O58214 (BORED PART)");
    EXPECT_EQ(on_percent_line[0].where.line, 1U);
}
