// Both code tables against the spec, entry by entry, in both directions.
#include <gtest/gtest.h>

#include "spec_tables.hpp"
#include "tape/code.hpp"
#include "tape/error.hpp"

using namespace tape;

namespace {
template <std::size_t N>
void expect_each_row_encodes_to_its_frame(const FrameCode& code, const SpecRow (&rows)[N]) {
    for (const auto& row : rows) {
        auto f = code.frame_for(static_cast<unsigned char>(row.character));
        ASSERT_TRUE(f) << row.name;
        EXPECT_EQ(*f, row.frame) << row.name;
        EXPECT_EQ(holes_picture(*f), row.holes) << row.name;
    }
}
}  // namespace

TEST(IsoTable, EverySpecRowEncodesToItsFrame) { expect_each_row_encodes_to_its_frame(FrameCode::iso(), spec_iso_rows); }

TEST(IsoTable, EverySpecFrameDecodesToItsCharacter) {
    FrameCode iso = FrameCode::iso();
    for (const auto& row : spec_iso_rows) {
        if (row.frame == 0x00) {
            EXPECT_EQ(iso.kind(row.frame), FrameKind::blank);
        } else if (row.frame == 0xFF) {
            EXPECT_EQ(iso.kind(row.frame), FrameKind::rubout);
        } else {
            ASSERT_EQ(iso.kind(row.frame), FrameKind::character) << row.name;
            EXPECT_EQ(iso.character(row.frame), row.character) << row.name;
        }
    }
}

TEST(IsoTable, EveryOddFrameIsAParityError) {
    FrameCode iso = FrameCode::iso();
    for (int f = 0; f < 256; ++f)
        EXPECT_EQ(iso.kind(static_cast<Frame>(f)) == FrameKind::parity_error,
                  hole_count(static_cast<Frame>(f)) % 2 == 1)
            << f;
}

TEST(IsoTable, AllSevenBitPositionsRoundTrip) {
    FrameCode iso = FrameCode::iso();
    for (int c = 1; c < 127; ++c) {
        Frame f = *iso.frame_for(static_cast<unsigned char>(c));
        EXPECT_EQ(hole_count(f) % 2, 0);
        EXPECT_EQ(f & 0x7F, c);
        EXPECT_EQ(iso.character(f), c);
    }
}

TEST(IsoTable, OtherParityRules) {
    EXPECT_EQ(*FrameCode::iso(Parity::mark).frame_for('A'), 0xC1);
    EXPECT_EQ(*FrameCode::iso(Parity::space).frame_for('C'), 0x43);
    EXPECT_EQ(*FrameCode::iso(Parity::odd).frame_for('A'), 0xC1);
    EXPECT_EQ(FrameCode::iso(Parity::mark).kind(0x41), FrameKind::parity_error);
    EXPECT_EQ(FrameCode::iso(Parity::mark).kind(0x80), FrameKind::blank);
    EXPECT_EQ(FrameCode::iso(Parity::none).kind(0x41), FrameKind::character);
    EXPECT_EQ(FrameCode::iso(Parity::none).kind(0xC1), FrameKind::character);
}

TEST(EiaTable, EverySpecRowEncodesToItsFrame) {
    expect_each_row_encodes_to_its_frame(FrameCode::eia(), spec_eia_rows);
    EXPECT_EQ(*FrameCode::eia().frame_for('\0'), 0x00);
}

TEST(EiaTable, EverySpecFrameDecodesToItsCharacter) {
    FrameCode eia = FrameCode::eia();
    for (const auto& row : spec_eia_rows) {
        if (row.character == '\x7f') {
            EXPECT_EQ(eia.kind(row.frame), FrameKind::rubout);
            continue;
        }
        ASSERT_EQ(eia.kind(row.frame), FrameKind::character) << row.name;
        EXPECT_EQ(eia.character(row.frame), row.character) << row.name;
        EXPECT_EQ(hole_count(row.frame) % 2, 1) << row.name << ": EIA frames have odd parity";
    }
    EXPECT_EQ(eia.kind(0x00), FrameKind::blank);
}

TEST(EiaTable, TrackEightIsOnlyEndOfBlock) {
    FrameCode eia = FrameCode::eia();
    for (int f = 0x81; f < 256; ++f) EXPECT_NE(eia.kind(static_cast<Frame>(f)), FrameKind::character) << f;
    EXPECT_EQ(eia.kind(0x0A), FrameKind::parity_error);
    EXPECT_EQ(eia.kind(0x0D), FrameKind::not_in_code);
    EXPECT_FALSE(eia.frame_for(':'));
    EXPECT_FALSE(eia.frame_for('a'));
}

TEST(EiaTable, CorrectedTableReplacesAnEntryWithoutCode) {
    CodeTable t = CodeTable::parse("LF 8\n%  1,3,4  a corrected rewind stop\nA 1,6,7\n");
    FrameCode eia = FrameCode::eia(t);
    EXPECT_EQ(*eia.frame_for('%'), 0x0D);
    EXPECT_EQ(eia.character(0x0D), '%');
    EXPECT_EQ(eia.kind(0x0B), FrameKind::not_in_code);
}

TEST(EiaTable, MalformedTablesNameTheLine) {
    auto line_of = [](const char* text) {
        try {
            CodeTable::parse(text);
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_table);
            return *e.where().line;
        }
        return std::uint64_t{0};
    };
    EXPECT_EQ(line_of("LF 8\nA 1,6\n"), 2U);             // even number of holes
    EXPECT_EQ(line_of("LF 8\nA 1,6,7\nB 1,6,7\n"), 3U);  // frame given twice
    EXPECT_EQ(line_of("# c\nLF 8\nA 9\n"), 3U);          // no track 9
    EXPECT_EQ(line_of("LF 8\nAB 1\n"), 2U);              // not a character name
    EXPECT_EQ(line_of("LF\n"), 1U);                      // no tracks
    EXPECT_EQ(line_of("A 1,6,7\n"), 1U);                 // no end of block
}

TEST(Frame, HolesPictureFollowsTheSpecLayout) {
    EXPECT_EQ(holes_picture(0xA5), "|o o  .o o|");
    EXPECT_EQ(holes_picture(0x00), "|     .   |");
    EXPECT_EQ(holes_picture(0xFF), "|ooooo.ooo|");
    EXPECT_EQ(holes_picture(0x01), "|     .  o|");
    EXPECT_EQ(holes_picture(0x08), "|    o.   |");
}
