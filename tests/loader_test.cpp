// The loader: label, programs, blocks, words, comments, positions (ГОСТ 20999-83 §1-§3).
#include <gtest/gtest.h>

#include "tape/decode.hpp"
#include "tape/encode.hpp"
#include "tape/program.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {
std::vector<std::string_view> rules(const LoadedTape& t) {
    std::vector<std::string_view> r;
    for (const auto& f : t.findings) r.push_back(f.rule);
    return r;
}
}  // namespace

TEST(Loader, LabelProgramNumberAndBlocks) {
    auto t = load("PART 7-114 (SETUP: VISE)\n%41\nN1 G01 X+12.5 Y-3\n/N2 M00\n:3 G90\nN4 M02\n");
    EXPECT_EQ(t.label, "PART 7-114 (SETUP: VISE)\n");
    ASSERT_EQ(t.programs.size(), 1U);
    const Program& p = t.programs[0];
    EXPECT_EQ(p.number, "41");
    EXPECT_TRUE(p.ended);
    ASSERT_EQ(p.blocks.size(), 4U);
    EXPECT_EQ(p.blocks[0].number_text(), "N1");
    EXPECT_EQ(p.blocks[0].words.size(), 3U);
    EXPECT_TRUE(p.blocks[1].skip);
    EXPECT_TRUE(p.blocks[2].main);
    EXPECT_EQ(p.blocks[2].number_text(), ":3");
    EXPECT_TRUE(p.blocks[3].ends_program());
    EXPECT_TRUE(t.findings.empty());
}

TEST(Loader, WordsKeepSignDigitsAndPoint) {
    auto t = load("%\nN1 X.03 Y1030. Z-12.5 S 64 X + 0000000\nM30\n");
    const auto& w = t.programs.at(0).blocks.at(0).words;
    ASSERT_EQ(w.size(), 5U);
    EXPECT_EQ(w[0].text, "X.03");
    EXPECT_EQ(w[0].point, 0);
    EXPECT_EQ(w[0].digits(), "03");
    EXPECT_EQ(w[1].point, 4);
    EXPECT_EQ(w[2].sign, '-');
    EXPECT_EQ(w[2].digits(), "125");
    EXPECT_EQ(w[2].point, 2);
    EXPECT_EQ(w[3].text, "S64");
    EXPECT_EQ(w[3].integer(), 64);
    EXPECT_EQ(w[4].text, "X+0000000");
    EXPECT_FALSE(w[4].has_point());
}

TEST(Loader, TabsAndCarriageReturnsAreIgnored) {
    auto t = load("%\r\nN1\tG01\tX1\r\nM02\r\n");
    ASSERT_EQ(t.programs.at(0).blocks.size(), 2U);
    EXPECT_EQ(t.programs[0].blocks[0].text(), "N1 G01 X1");
    EXPECT_TRUE(t.findings.empty());
}

TEST(Loader, CommentsAttachToTheirBlock) {
    auto t = load("%\nN1 G00 (ТОЧКА 1) X1 (SECOND)\nM02\n");
    const Block& b = t.programs.at(0).blocks.at(0);
    ASSERT_EQ(b.comments.size(), 2U);
    EXPECT_EQ(b.comments[0].text, "ТОЧКА 1");
    EXPECT_EQ(b.words.size(), 2U);
    EXPECT_EQ(b.comments[1].where.column, 21U);  // counted in characters, not bytes
}

TEST(Loader, NothingAfterTheEndIsPartOfTheProgram) {
    auto t = load("%1\nN1 M30\nNOTES AFTER THE END\n%2\nN1 M02\n");
    ASSERT_EQ(t.programs.size(), 2U);
    EXPECT_EQ(t.programs[0].after_end, "NOTES AFTER THE END\n");
    EXPECT_EQ(t.programs[0].blocks.size(), 1U);
    EXPECT_EQ(t.programs[1].number, "2");
}

TEST(Loader, PhysicalStartMark) {
    auto t = load("%%001\nN1 M02\n");
    EXPECT_TRUE(t.physical_start);
    EXPECT_EQ(t.programs.at(0).number, "001");
    EXPECT_TRUE(load("% %\nN1 M02\n").physical_start);
}

TEST(Loader, SyntaxFindings) {
    EXPECT_EQ(rules(load("%\nN1 X Y2\nM02\n")), std::vector<std::string_view>{"no-digits"});
    EXPECT_EQ(rules(load("%\nN1 X1.2.3\nM02\n")), std::vector<std::string_view>{"two-points"});
    EXPECT_EQ(rules(load("%\nN1 G01 /X1\nM02\n")), std::vector<std::string_view>{"skip-position"});
    EXPECT_EQ(rules(load("%\nN1 G01 :2\nM02\n")), std::vector<std::string_view>{"main-position"});
    EXPECT_EQ(rules(load("%\nN1 x1\nM02\n")), std::vector<std::string_view>{"unknown-word"});
    EXPECT_EQ(rules(load("%\nN1 G01 x\nM02\n")), std::vector<std::string_view>{"unknown-word"});
    EXPECT_EQ(rules(load("%\nN1 X1 #\nM02\n")), std::vector<std::string_view>{"unknown-word"});
    EXPECT_EQ(rules(load("%\nN1 X1 $&\nM02\n")), std::vector<std::string_view>{"unexpected-character"});
    EXPECT_EQ(rules(load("%\nN1 (A:B%)\nM02\n")),
              (std::vector<std::string_view>{"comment-forbidden-char", "comment-forbidden-char"}));
    EXPECT_EQ(rules(load("%\nN1 (OPEN\nM02\n")), std::vector<std::string_view>{"unclosed-comment"});
    EXPECT_EQ(rules(load("%\nN1 G01\n")), std::vector<std::string_view>{"program-end"});
    EXPECT_EQ(rules(load("%PART-1\nN1 M02\n")), std::vector<std::string_view>{"program-start"});
    EXPECT_EQ(rules(load("%\nN1 G01 %\nM02\n")), std::vector<std::string_view>{"percent-in-block"});
}

TEST(Loader, ANewPercentEndsAnUnterminatedProgram) {
    auto t = load("%1\nN1 G01\n%2\nN1 M02\n");
    ASSERT_EQ(t.programs.size(), 2U);
    EXPECT_EQ(rules(t), std::vector<std::string_view>{"program-end"});
    EXPECT_EQ(t.findings[0].where.block, 1U);
}

TEST(Loader, TapePositionsAreFrames) {
    std::string text = read_text(sample_path("gost-20999-format-example.txt"));
    auto frames = encode(text, {});
    auto r = decode(frames, DecodeOptions{.positions = true});
    auto t = load(r.text, r.frame_of);
    ASSERT_EQ(t.programs.size(), 1U);
    EXPECT_EQ(t.programs[0].start.frame, 101U);  // after 100 frames of leader
    const Block& first = t.programs[0].blocks.at(0);
    EXPECT_EQ(first.where.frame, 103U);  // '%', LF, then ':'
    EXPECT_EQ(first.where.line, 2U);
    EXPECT_EQ(frames[*first.where.frame - 1], 0x3A);
}

TEST(Loader, SeedPrograms) {
    auto turning = load(read_text(sample_path("16k20f3s5-turning.txt")));
    ASSERT_EQ(turning.programs.size(), 1U);
    const auto& blocks = turning.programs[0].blocks;
    ASSERT_EQ(blocks.size(), 11U);
    EXPECT_EQ(blocks[0].text(), "N001 G27 F2000 S64 T102 M104");
    EXPECT_EQ(blocks[9].text(), "N010 X+002000 Z-001000 F10000");
    auto circles = load(read_text(sample_path("circle-examples.txt")));
    EXPECT_EQ(circles.programs.at(0).blocks.at(6).text(), "N21 G03 G90 X250.0 Z140.0 I-100.0 J-50.0 F100");
    EXPECT_TRUE(circles.programs[0].ended);
}

TEST(Loader, LocateAgreesWithTheLoader) {
    auto t = load("ЯРЛЫК\n%\nN1 X1\nM02\n");
    const Word& x = t.programs.at(0).blocks.at(0).words.at(0);
    Location l = t.locate(x.where.offset);
    EXPECT_EQ(l.line, x.where.line);
    EXPECT_EQ(l.column, x.where.column);
    EXPECT_EQ(l.line, 3U);
    EXPECT_EQ(l.column, 4U);
}

// Columns count characters on a line that is not ASCII, whichever order the loader asks for them in:
// a word after the Cyrillic, a finding back at the start of a run, words far along a long line.
TEST(Loader, ColumnsOnANonAsciiLineCountCharacters) {
    std::string line = "N1 (ДЕТАЛЬ) X1 Ж2 Y3";
    for (int i = 0; i < 2000; ++i) line += " Z4";
    auto t = load("%\n" + line + "\nM02\n");
    const Block& b = t.programs.at(0).blocks.at(0);
    ASSERT_GE(b.words.size(), 2003U);
    EXPECT_EQ(b.words[0].where.column, 13U);  // X1: after "N1 (ДЕТАЛЬ) ", 12 characters
    EXPECT_EQ(b.words[1].where.column, 16U);  // the flagged Ж2
    EXPECT_EQ(b.words[2].where.column, 19U);  // Y3
    EXPECT_EQ(b.words.back().where.column, 19U + 3U * 2000U);
    ASSERT_EQ(t.findings.size(), 1U);
    EXPECT_EQ(t.findings[0].where.column, 16U);
}

// The loader looks for a line's ';' and ')' once, sixteen bytes at a time and then byte by byte: a
// ';' or a stray ')' in either part is found, on lines short and long, ASCII or not.
TEST(Loader, SemicolonsAndStrayBracketsAnywhereOnTheLine) {
    auto fanuc =
        load("O1\nG0;X1\nG01 X1.23456 Y2.34567;G00 X0 Y0 Z0 (A;B) M05\nG01 (ДЕТАЛЬ) X1.25 Y2.5 Z0.1;M09\nM30\n", {},
             LoadOptions{Dialect::fanuc});
    ASSERT_EQ(fanuc.programs.size(), 1U);
    std::vector<std::string> blocks;
    for (const auto& b : fanuc.programs[0].blocks) blocks.push_back(b.text());
    EXPECT_EQ(blocks, (std::vector<std::string>{"O1", "G0", "X1", "G01 X1.23456 Y2.34567", "G00 X0 Y0 Z0 M05 (A;B)",
                                                "G01 X1.25 Y2.5 Z0.1 (ДЕТАЛЬ)", "M09", "M30"}));
    for (std::string_view line :
         {"N1 X1)\n", "N1 G01 X1.23456 Y2.34567 Z1 F100 LOST)\n", "N1 (Ж) G01 X1 Y2 Z3 F4 S5)\n"}) {
        auto t = load("%\n" + std::string(line) + "N2 M02\n");
        EXPECT_EQ(rules(t), std::vector<std::string_view>{"unexpected-character"}) << line;
    }
}

// The block's number is kept from block to block for its string's sake: a block without one has none.
TEST(Loader, ANumberIsNotCarriedToTheNextBlock) {
    auto t = load("%\nN10 G01 X1\nG00 X2\nN30 M02\n");
    const auto& b = t.programs.at(0).blocks;
    ASSERT_EQ(b.size(), 3U);
    EXPECT_EQ(b[0].number_text(), "N10");
    EXPECT_FALSE(b[1].number.has_value());
    EXPECT_EQ(b[2].number->integer(), 30);
    EXPECT_EQ(b[2].number->where.line, 4U);
}

// Past 18 digits a word has no integer value (the loader's count wraps there, and says so).
TEST(Loader, LongDigitRunsHaveNoIntegerValue) {
    auto t = load("%\nN1 S123456789012345678 T1234567890123456789 M02\n");
    const auto& w = t.programs.at(0).blocks.at(0).words;
    ASSERT_EQ(w.size(), 3U);
    EXPECT_EQ(w[0].integer(), 123456789012345678LL);
    EXPECT_FALSE(w[1].integer().has_value());
    Word by_hand;  // made by hand: its digits are read from the text
    by_hand.address = 'S';
    by_hand.text = "S123456789012345678";
    EXPECT_EQ(by_hand.integer(), w[0].integer());
}
