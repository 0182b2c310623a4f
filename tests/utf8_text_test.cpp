// Text programs versus tape images, and input bytes made safe to show in messages.
#include "tape/utf8_text.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace tape;

namespace {
std::span<const std::uint8_t> bytes_of(const std::string& s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}
}  // namespace

TEST(TextFault, NamesLineColumnAndWhat) {
    std::string nul = std::string("%\nN1 G01\nN2 X", 13) + '\0' + "2\n";
    auto f = find_text_fault(bytes_of(nul));
    ASSERT_TRUE(f);
    EXPECT_EQ(f->where.describe(), "line 3, column 5");
    EXPECT_EQ(f->offset, 13u);
    EXPECT_EQ(f->what, "a NUL byte");

    auto stray = find_text_fault(bytes_of("%\n(Д \xD0)\n"));  // a Cyrillic letter counts as one column
    ASSERT_TRUE(stray);
    EXPECT_EQ(stray->where.describe(), "line 2, column 4");
    EXPECT_EQ(stray->what, "byte 0xD0, which is not UTF-8");

    auto bell = find_text_fault(bytes_of("%\nG01\a\n"));
    ASSERT_TRUE(bell);
    EXPECT_EQ(bell->what, "the control character \\x07");

    EXPECT_FALSE(find_text_fault(bytes_of("%\r\n(ДЕТАЛЬ 17)\tG01\x0E\x0F\n")));
}

TEST(TextFault, DamagedTextIsNotATapeImage) {
    EXPECT_TRUE(looks_like_damaged_text(bytes_of(std::string("%\nN1 G01\nN2 X", 13) + '\0' + "2\nM02\n")));
    EXPECT_TRUE(looks_like_damaged_text(bytes_of("%\nN1 (\xD0)\nM02\n")));
    // Raw ISO tapes: blank leader first, or track 8 punched in half the frames.
    EXPECT_FALSE(looks_like_damaged_text(bytes_of(std::string(10, '\0') + "\xA5\x0A")));
    EXPECT_FALSE(looks_like_damaged_text(bytes_of("\xA5\x0A")));
    EXPECT_FALSE(looks_like_damaged_text(bytes_of("\xA5\x0A\xCE\xB1\xB0\x0A\xCD\xB0\x32\x0A")));
    EXPECT_FALSE(looks_like_damaged_text(bytes_of("no line ends at all \x01")));
}

TEST(Visible, SpellsOutWhatATerminalWouldHideOrActOn) {
    EXPECT_EQ(visible(std::string("a\0b", 3)), "a\\x00b");
    EXPECT_EQ(visible("\x1B[2J"), "\\x1B[2J");
    EXPECT_EQ(visible("\xD0 and \xFF"), "\\xD0 and \\xFF");
    EXPECT_EQ(visible("\xEF\xBB\xBF%"), "U+FEFF%");
    EXPECT_EQ(visible("\xE2\x80\x8B"), "U+200B");
    EXPECT_EQ(visible("ДЕТАЛЬ | o oo. |"), "ДЕТАЛЬ | o oo. |");
}

TEST(TextFault, DosEndOfFileMarksEndATextAndAreNoFault) {
    EXPECT_EQ(dos_end_of_file_at(bytes_of("%\nM30\n%\n\x1A\x1A")), 8U);
    EXPECT_EQ(dos_end_of_file_at(bytes_of("%\n")), 2U);
    EXPECT_TRUE(is_program_text(bytes_of("%\r\nM30\r\n%\r\n\x1A")));
    auto inside = find_text_fault(bytes_of("%\n\x1A\nM30\n"));
    ASSERT_TRUE(inside);
    EXPECT_EQ(inside->what, "the control character \\x1A");
    // In pieces: a mark at a piece's end waits for what follows.
    TextChecker ends;
    EXPECT_FALSE(ends.check(bytes_of("%\nM30\n\x1A")));
    EXPECT_FALSE(ends.check(bytes_of("\x1A")));
    EXPECT_FALSE(ends.finish());
    ASSERT_TRUE(ends.end_of_file_mark());
    EXPECT_EQ(ends.end_of_file_mark()->offset, 6U);
    EXPECT_EQ(ends.end_of_file_mark()->where.line, 3U);
    TextChecker goes_on;
    EXPECT_FALSE(goes_on.check(bytes_of("%\nM30\x1A")));
    auto fault = goes_on.check(bytes_of("\n"));
    ASSERT_TRUE(fault);
    EXPECT_EQ(fault->where.describe(), "line 2, column 4");
    EXPECT_EQ(fault->offset, 5U);
}
