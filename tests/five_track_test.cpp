// 5-track codes (ITA2, МТК-2): the tables against the spec, shifts, round trips, findings.
#include "tape/five_track.hpp"

#include <gtest/gtest.h>

#include "tape/decode.hpp"
#include "tape/encode.hpp"
#include "tape/image.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

// Spec section 4b, copied row by row from the spec (not from data/*.tab). Figures: ITA2's, then МТК-2's;
// "" where ITA2 leaves the position to national use, the control pictures for WRU and the bell.
struct SpecRow {
    Frame frame;
    const char *latin, *russian, *ita2_figure, *mtk2_figure;
};
constexpr SpecRow spec_rows[] = {
    {0x03, "A", "А", "-", "-"}, {0x19, "B", "Б", "?", "?"}, {0x0E, "C", "Ц", ":", ":"}, {0x09, "D", "Д", "␅", "␅"},
    {0x01, "E", "Е", "3", "3"}, {0x0D, "F", "Ф", "", "Э"},  {0x1A, "G", "Г", "", "Ш"},  {0x14, "H", "Х", "", "Щ"},
    {0x06, "I", "И", "8", "8"}, {0x0B, "J", "Й", "␇", "Ю"}, {0x0F, "K", "К", "(", "("}, {0x12, "L", "Л", ")", ")"},
    {0x1C, "M", "М", ".", "."}, {0x0C, "N", "Н", ",", ","}, {0x18, "O", "О", "9", "9"}, {0x16, "P", "П", "0", "0"},
    {0x17, "Q", "Я", "1", "1"}, {0x0A, "R", "Р", "4", "4"}, {0x05, "S", "С", "'", "'"}, {0x10, "T", "Т", "5", "5"},
    {0x07, "U", "У", "7", "7"}, {0x1E, "V", "Ж", "=", "="}, {0x13, "W", "В", "2", "2"}, {0x1D, "X", "Ь", "/", "/"},
    {0x15, "Y", "Ы", "6", "6"}, {0x11, "Z", "З", "+", "+"},
};
constexpr Frame ltrs = 0x1F, figs = 0x1B, rus = 0x00, sp = 0x04, cr = 0x08, lf = 0x02;

DecodeResult read(const std::vector<Frame>& frames, Code code, bool keep_going = false) {
    return decode(frames, DecodeOptions{.code = code, .keep_going = keep_going, .positions = true});
}

std::vector<Frame> punch(std::string_view text, Code code) {
    return encode(text, EncodeOptions{.code = code, .leader = 0, .trailer = 0});
}

// Every character of the table on its own, in every register: a line of each register's characters.
std::string every_character(const FiveTrackTable& t) {
    std::string text;
    for (int r = 0; r < t.registers(); ++r) {
        for (Frame f = 0; f < five_track_frames; ++f) {
            const auto& m = t.meaning(r, f);
            if (m.kind == FiveTrackTable::Kind::character && m.text != "\r" && m.text != "\n") text += m.text;
        }
        text += '\n';
    }
    return text;
}

}  // namespace

TEST(FiveTrackTables, FollowTheSpec) {
    const auto& ita2 = FiveTrackTable::builtin_ita2();
    const auto& mtk2 = FiveTrackTable::builtin_mtk2();
    ASSERT_EQ(ita2.registers(), 2);
    ASSERT_EQ(mtk2.registers(), 3);
    for (const SpecRow& row : spec_rows) {
        SCOPED_TRACE(row.latin);
        EXPECT_EQ(read({ltrs, row.frame}, Code::ita2).text, row.latin);
        EXPECT_EQ(read({ltrs, row.frame}, Code::mtk2).text, row.latin);
        EXPECT_EQ(read({rus, row.frame}, Code::mtk2).text, row.russian);
        EXPECT_EQ(read({figs, row.frame}, Code::mtk2).text, row.mtk2_figure);
        auto fig = read({figs, row.frame}, Code::ita2);
        if (*row.ita2_figure) {
            EXPECT_EQ(fig.text, row.ita2_figure);
        } else {
            EXPECT_EQ(fig.diagnostics.size(), 1U) << "a national position is a finding";
        }
    }
    for (Code code : {Code::ita2, Code::mtk2}) {
        EXPECT_EQ(read({ltrs, sp, figs, sp, cr, lf, cr}, code).text, "  \n\r");
        EXPECT_EQ(punch("A", code), (std::vector<Frame>{ltrs, 0x03}));
        EXPECT_EQ(punch("1", code), (std::vector<Frame>{figs, 0x17}));
    }
    EXPECT_EQ(punch("Я", Code::mtk2), (std::vector<Frame>{rus, 0x17}));
    EXPECT_EQ(read({0x03, 0x00, 0x03}, Code::ita2).text, "AA") << "blank tape is skipped in ITA2";
}

TEST(FiveTrack, EveryCharacterRoundTrips) {
    for (Code code : {Code::ita2, Code::mtk2}) {
        const auto& table = code == Code::ita2 ? FiveTrackTable::builtin_ita2() : FiveTrackTable::builtin_mtk2();
        std::string text = every_character(table);
        SCOPED_TRACE(text);
        auto r = read(punch(text, code), code);
        EXPECT_TRUE(r.ok());
        EXPECT_EQ(r.text, text);
        // Each character alone too, so that no shift is taken for granted.
        for (Frame f = 0; f < five_track_frames; ++f)
            for (int reg = 0; reg < table.registers(); ++reg) {
                const auto& m = table.meaning(reg, f);
                if (m.kind != FiveTrackTable::Kind::character) continue;
                EXPECT_EQ(read(punch(m.text, code), code).text, m.text);
            }
    }
}

TEST(FiveTrack, ShiftsOnlyWhereTheRegisterChanges) {
    // ЧАС: Ч is the figure 4 (spec), so it reads back as 4.
    auto frames = punch("AB 12 ЯЧАС", Code::mtk2);
    EXPECT_EQ(frames,
              (std::vector<Frame>{ltrs, 0x03, 0x19, sp, figs, 0x17, 0x13, sp, rus, 0x17, figs, 0x0A, rus, 0x03, 0x05}));
    EXPECT_EQ(read(frames, Code::mtk2).text, "AB 12 Я4АС");
    EXPECT_EQ(punch("A\nB", Code::ita2), (std::vector<Frame>{ltrs, 0x03, cr, lf, 0x19})) << "CR LF: no shift again";
}

TEST(FiveTrack, FramesReadTheSameHoweverTheTapeIsCut) {
    const std::string text = "ПРИВЕТ, MIR 1963\nЧАС 15-30\n\n";
    const auto frames = encode(text, EncodeOptions{.code = Code::mtk2});
    const auto whole = read(frames, Code::mtk2);
    for (std::size_t piece : {std::size_t{1}, std::size_t{2}, std::size_t{7}}) {
        Decoder d(DecodeOptions{.code = Code::mtk2, .positions = true});
        DecodeResult r;
        for (std::size_t i = 0; i < frames.size(); i += piece)
            d.feed(std::span(frames).subspan(i, std::min(piece, frames.size() - i)), r);
        d.finish(r);
        EXPECT_EQ(r.text, whole.text);
        EXPECT_EQ(r.frame_of, whole.frame_of);
        Encoder e(EncodeOptions{.code = Code::mtk2});
        std::vector<Frame> out;
        for (std::size_t i = 0; i < text.size(); i += piece) e.feed(std::string_view(text).substr(i, piece), out);
        e.finish(out);
        EXPECT_EQ(out, frames);
    }
}

TEST(FiveTrack, LineEndsAndHeldCarriageReturns) {
    EXPECT_EQ(read({ltrs, 0x03, cr, cr, lf, 0x03}, Code::ita2).text, "A\nA");
    EXPECT_EQ(read({ltrs, 0x03, cr, figs, lf}, Code::ita2).text, "A\n") << "a shift between CR and LF";
    EXPECT_EQ(read({ltrs, 0x03, cr, 0x03, cr}, Code::ita2).text, "A\rA\r") << "a lone CR, at the end too";
    EXPECT_EQ(read({ltrs, 0x03, lf, cr}, Code::ita2).text, "A\n\r");
    auto r = read({ltrs, 0x03, cr, lf}, Code::ita2);
    EXPECT_EQ(r.frame_of, (std::vector<std::uint64_t>{1, 3})) << "LF stands where the LF frame is";
    EXPECT_EQ(punch("A\r\nB\rC", Code::ita2), (std::vector<Frame>{ltrs, 0x03, cr, lf, 0x19, cr, 0x0E}));
}

TEST(FiveTrack, LowerCaseIsPunchedAsCapitals) {
    EXPECT_EQ(read(punch("telegram", Code::ita2), Code::ita2).text, "TELEGRAM");
    EXPECT_EQ(read(punch("привет", Code::mtk2), Code::mtk2).text, "ПРИВЕТ");
}

TEST(FiveTrack, RefusesWhatTheCodeCannotCarry) {
    struct Case {
        Code code;
        std::string text, why;
        std::uint64_t line, column;
        Hint::Action hint;
    };
    for (const Case& c : {
             Case{Code::ita2, "OK\nAB%", "'%' cannot be punched in ITA2 code", 2, 3, Hint::Action::none},
             Case{Code::ita2, "ПРИВЕТ", "'П' cannot be punched in ITA2 code; Russian needs МТК-2", 1, 1,
                  Hint::Action::use_code},
             Case{Code::mtk2, "ЁЛКА", "'Ё' cannot be punched in МТК-2 code (МТК-2 has no Ё: write Е)", 1, 1,
                  Hint::Action::none},
             Case{Code::mtk2, "ОБЪЕМ", "'Ъ' cannot be punched in МТК-2 code (МТК-2 has no Ъ: write Ь)", 1, 3,
                  Hint::Action::none},
             Case{Code::ita2, "A\tB", "HT cannot be punched in ITA2 code", 1, 2, Hint::Action::none},
             Case{Code::mtk2, "A\xC3", "'\\xC3' cannot be punched in МТК-2 code", 1, 2, Hint::Action::none},
         }) {
        SCOPED_TRACE(c.text);
        try {
            punch(c.text, c.code);
            ADD_FAILURE() << "punched";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_text);
            EXPECT_EQ(e.what(), c.why);
            EXPECT_EQ(e.where().line, c.line);
            EXPECT_EQ(e.where().column, c.column);
            EXPECT_EQ(e.hint().action, c.hint);
        }
    }
    EXPECT_THROW(encode("A", EncodeOptions{.code = Code::ita2, .parity = Parity::odd}), Error);
    EXPECT_THROW(encode("A", EncodeOptions{.code = Code::mtk2, .charset = Charset::koi7}), Error);
}

TEST(FiveTrack, FramesWithHigherTracksAndNationalPositionsAreFindings) {
    // Frames 3 (0x41, track 7) and 6 (FIGS F: national in ITA2).
    std::vector<Frame> t = {ltrs, 0x03, 0x41, 0x03, figs, 0x0D, 0x17};
    auto stop = read(t, Code::ita2);
    EXPECT_FALSE(stop.complete);
    EXPECT_EQ(stop.text, "A");
    ASSERT_EQ(stop.diagnostics.size(), 1U);
    EXPECT_EQ(stop.diagnostics[0].where.frame, 3U);
    EXPECT_EQ(stop.diagnostics[0].code, Errc::not_in_code);
    EXPECT_NE(stop.diagnostics[0].message.find("not a 5-track frame"), std::string::npos);
    auto all = read(t, Code::ita2, true);
    EXPECT_EQ(all.text, "A" + std::string(bad_frame_marker) + "A" + std::string(bad_frame_marker) + "1");
    ASSERT_EQ(all.diagnostics.size(), 2U);
    EXPECT_EQ(all.diagnostics[1].where.frame, 6U);
    EXPECT_NE(all.diagnostics[1].message.find("FIGS F has no agreed character in ITA2"), std::string::npos)
        << all.diagnostics[1].message;
    EXPECT_EQ(read(t, Code::mtk2, true).text, "A" + std::string(bad_frame_marker) + "AЭ1");
    EXPECT_THROW(Decoder(DecodeOptions{.code = Code::ita2, .parity = Parity::mark}), Error);
}

TEST(FiveTrack, ShowLabelsFollowTheShifts) {
    FiveTrackLabeler l(FiveTrackTable::builtin_mtk2());
    std::vector<std::string> labels;
    for (Frame f : {rus, Frame{0x17}, figs, Frame{0x17}, ltrs, Frame{0x17}, sp, cr, lf, Frame{0x41}})
        labels.push_back(l.next(f));
    EXPECT_EQ(labels,
              (std::vector<std::string>{"RUS", "Я", "FIGS", "1", "LTRS", "Q", "SP", "CR", "LF", "not 5-track"}));
    EXPECT_EQ(FrameCode::five_track(Code::mtk2).label(0x17), "Q/Я/1");
}

TEST(FiveTrackTables, MalformedTablesNameTheLine) {
    struct Case {
        std::string text;
        std::uint64_t line;
    };
    std::string frames;
    for (int f = 1; f < 32; ++f) {
        std::string holes;
        for (int t = 0; t < 5; ++t) holes += (f >> t) & 1 ? '1' : '0';
        frames += holes + (f == 0x1F ? "  LTRS\n" : f == 0x02 ? "  LF\n" : "  NONE\n");
    }
    EXPECT_NO_THROW(FiveTrackTable::parse("registers LTRS\n00000 BLANK\n" + frames));
    std::string twice_a = "registers LTRS\n00000 BLANK\n" + frames;  // A on lines 3 (10000) and 5 (11000)
    twice_a.replace(twice_a.find("10000  NONE"), 11, "10000  A");
    twice_a.replace(twice_a.find("11000  NONE"), 11, "11000  A");
    for (const Case& c :
         {Case{"registers LTRS\n00000 BLANK\n00000 BLANK\n", 3}, Case{"00000 BLANK\n", 1},
          Case{"registers LTRS CYR\n", 1}, Case{"registers LTRS\n0000 A\n", 2},
          Case{"registers LTRS FIGS\n00000 A B C\n", 2}, Case{"registers LTRS\n00000 AB\n", 2}, Case{twice_a, 5}}) {
        SCOPED_TRACE(c.text);
        try {
            FiveTrackTable::parse(c.text);
            ADD_FAILURE() << "parsed";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_table);
            EXPECT_EQ(e.where().line, c.line);
        }
    }
    EXPECT_THROW(FiveTrackTable::parse("registers LTRS\n00000 BLANK\n"), Error) << "frames left out";
}

// The sample telegrams were punched from the spec table, not by tape encode (tapes/README.md): they read
// as their texts.
TEST(FiveTrack, SampleTelegramsReadAsTheirTexts) {
    struct Sample {
        const char *image, *text;
        Code code;
    };
    for (const Sample& s : {Sample{"telegram.mtk2.hex5", "telegram.mtk2.txt", Code::mtk2},
                            Sample{"telegram.ita2.hex8", "telegram.ita2.txt", Code::ita2}}) {
        SCOPED_TRACE(s.image);
        std::string file = read_text(sample_path(s.image));
        const ImageFormat* format = image_format_for_path(s.image);
        ASSERT_NE(format, nullptr);
        auto frames = format->read({reinterpret_cast<const std::uint8_t*>(file.data()), file.size()});
        auto r = read(frames, s.code);
        EXPECT_TRUE(r.ok());
        EXPECT_EQ(r.text, read_text(sample_path(s.text)));
    }
}
