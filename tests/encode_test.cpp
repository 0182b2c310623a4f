// Encoding: leader and trailer, line endings, characters a code cannot carry, round trips.
#include "tape/encode.hpp"

#include <gtest/gtest.h>

#include "tape/decode.hpp"
#include "tape/error.hpp"
#include "tape/utf8_text.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {
Error encode_error(std::string_view text, EncodeOptions o = {}) {
    try {
        encode(text, o);
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no error for " << text;
    return Error(Errc::usage, "none");
}
}  // namespace

TEST(Encode, LeaderAndTrailerAreBlankFrames) {
    auto t = encode("%\n", {});
    ASSERT_EQ(t.size(), 202U);
    for (std::size_t i = 0; i < 100; ++i) EXPECT_EQ(t[i], 0x00);
    EXPECT_EQ(t[100], 0xA5);
    EXPECT_EQ(t[101], 0x0A);
    EXPECT_EQ(t[201], 0x00);
    EXPECT_EQ(encode("%\n", EncodeOptions{.leader = 0, .trailer = 0}), (std::vector<Frame>{0xA5, 0x0A}));
}

TEST(Encode, CrLfBecomesLfAndEiaEndOfBlock) {
    EncodeOptions bare{.leader = 0, .trailer = 0};
    EXPECT_EQ(encode("N1\r\nM2\r\n", bare), encode("N1\nM2\n", bare));
    EncodeOptions eia{.code = Code::eia, .leader = 0, .trailer = 0};
    EXPECT_EQ(encode("%\nN1\r\n", eia), (std::vector<Frame>{0x0B, 0x80, 0x45, 0x01, 0x80}));
}

TEST(Encode, FastPathMatchesTheTableForEveryPosition) {
    std::string all;
    for (int rep = 0; rep < 3; ++rep)
        for (int c = 1; c < 127; ++c) all += static_cast<char>(c);
    EncodeOptions bare{.leader = 0, .trailer = 0};
    auto frames = encode(all, bare);
    FrameCode iso = FrameCode::iso();
    ASSERT_EQ(frames.size(), all.size());
    for (std::size_t i = 0; i < all.size(); ++i)
        EXPECT_EQ(frames[i], *iso.frame_for(static_cast<unsigned char>(all[i])));
}

TEST(Encode, NonAsciiIsAnErrorNamingLineAndColumn) {
    Error e = encode_error("%\nN1 X1 (é)\n");
    EXPECT_EQ(e.code(), Errc::bad_text);
    EXPECT_EQ(*e.where().line, 2U);
    EXPECT_EQ(*e.where().column, 8U);
    EXPECT_STREQ(e.what(), "'é' cannot be punched in ISO code");
    Error far = encode_error(std::string(100, 'X') + "\xC3\xA9");  // past the eight-byte fast loop
    EXPECT_EQ(*far.where().column, 101U);
    Error cyr = encode_error("(Д)\n");
    EXPECT_STREQ(cyr.what(), "'Д' cannot be punched in ISO code; Cyrillic needs the КОИ-7 character set");
    EXPECT_EQ(cyr.hint().action, Hint::Action::use_charset);
    EXPECT_EQ(cyr.hint().value, "koi7");
}

TEST(Encode, EiaCannotCarryColonOrLowerCase) {
    Error e = encode_error("%\n:1\n", EncodeOptions{.code = Code::eia});
    EXPECT_EQ(*e.where().line, 2U);
    EXPECT_EQ(*e.where().column, 1U);
    EXPECT_STREQ(e.what(), "':' cannot be punched in EIA code");
    EXPECT_EQ(*encode_error("N1 x2\n", EncodeOptions{.code = Code::eia}).where().column, 4U);
}

TEST(Encode, Koi7ShiftsOutAndBackBeforeLatinLettersAndEndOfBlock) {
    EncodeOptions o{.charset = Charset::koi7, .leader = 0, .trailer = 0};
    auto t = encode("(ВАЛ 1)X\n(Д)\n", o);
    auto r = decode(t, {});
    EXPECT_EQ(r.text,
              "(\x0ewal 1)\x0fX\n(\x0e"
              "d)\x0f\n");
    EXPECT_EQ(decode(t, DecodeOptions{.charset = Charset::koi7}).text, "(ВАЛ 1)X\n(Д)\n");
    Error yo = encode_error("(ЁЖ)\n", o);
    EXPECT_STREQ(yo.what(), "'Ё' cannot be punched in ISO code (КОИ-7 has no Ё: write Е)");
    EXPECT_EQ(*yo.where().column, 2U);
}

TEST(RoundTrip, SamplesThroughBothCodes) {
    for (const char* name :
         {"gost-20999-format-example.txt", "gost-20999-format-example.eia.txt", "16k20f3s5-turning.txt"}) {
        std::string text = read_text(sample_path(name));
        for (Code code : {Code::iso, Code::eia}) {
            if (code == Code::eia && text.find(':') != std::string::npos) continue;  // EIA has no ':'
            auto frames = encode(text, EncodeOptions{.code = code});
            auto r = decode(frames, DecodeOptions{.code = code});
            EXPECT_TRUE(r.ok()) << name;
            EXPECT_EQ(r.text, text) << name << " " << code_name(code);
        }
    }
}

TEST(RoundTrip, CommittedImagesMatchTheirSources) {
    struct Pair {
        const char *image, *source;
        Code code;
    } pairs[] = {
        {"gost-20999-format-example.iso.ptp", "gost-20999-format-example.txt", Code::iso},
        {"gost-20999-format-example.eia.ptp", "gost-20999-format-example.eia.txt", Code::eia},
        {"16k20f3s5-turning.iso.ptp", "16k20f3s5-turning.txt", Code::iso},
        {"16k20f3s5-turning.eia.ptp", "16k20f3s5-turning.txt", Code::eia},
    };
    for (const auto& p : pairs) {
        auto frames = read_frames(sample_path(p.image));
        EXPECT_EQ(frames, encode(read_text(sample_path(p.source)), EncodeOptions{.code = p.code})) << p.image;
        EXPECT_EQ(decode(frames, DecodeOptions{.code = p.code}).text, read_text(sample_path(p.source))) << p.image;
    }
}

// NUL and DEL would encode, but read back as blank tape and a rubout: refused with their position.
TEST(Encode, NulAndDelAreRefusedWithTheirPosition) {
    for (char bad : {'\0', '\x7F'}) {
        std::string text = std::string("%\nN1 G01 X") + bad + "2\n";
        try {
            encode(text, {});
            FAIL() << "encoded a " << int(bad);
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_text);
            EXPECT_EQ(e.where().describe(), "line 2, column 9");
        }
    }
}

TEST(Encode, LeaderBeyondTheLimitIsAUsageError) {
    EncodeOptions o;
    o.leader = max_blank_frames + 1;
    try {
        encode("%\n", o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage);
    }
    o.leader = 0;
    o.trailer = static_cast<std::size_t>(-1);  // what "--trailer -1" became before the CLI checked it
    EXPECT_THROW(encode("%\n", o), Error);
}

namespace {
// Encodes text cut at cut (and, when second is given, again at second) through the incremental Encoder.
std::vector<Frame> encode_in_pieces(std::string_view text, const EncodeOptions& o, std::vector<std::size_t> cuts) {
    Encoder e(o);
    std::vector<Frame> out;
    std::size_t at = 0;
    for (std::size_t cut : cuts) {
        e.feed(text.substr(at, cut - at), out);
        at = cut;
    }
    e.feed(text.substr(at), out);
    e.finish(out);
    return out;
}
}  // namespace

// However the text is cut, the frames are the same: КОИ-7 shifts, CR LF and UTF-8 cut in two included.
TEST(Encode, EverySplitPointGivesTheSameFrames) {
    struct Case {
        std::string text;
        EncodeOptions options;
    };
    EncodeOptions koi7;
    koi7.charset = Charset::koi7;
    EncodeOptions crlf;
    crlf.crlf = true;
    EncodeOptions eia;
    eia.code = Code::eia;
    std::vector<Case> cases = {
        {read_text(sample_path("16k20f3s5-turning.txt")), {}},
        {read_text(sample_path("koi7-comment.txt")), koi7},
        {read_text(sample_path("gost-20999-format-example.txt")), crlf},
        {read_text(sample_path("gost-20999-format-example.eia.txt")), eia},
        {"%\r\nN1 (ДЕТАЛЬ)\r\nN2 G01\r\r\nM02\r", koi7},
    };
    for (const auto& c : cases) {
        std::vector<Frame> whole = encode(c.text, c.options);
        for (std::size_t k = 0; k <= c.text.size(); ++k)
            ASSERT_EQ(encode_in_pieces(c.text, c.options, {k}), whole) << "cut at byte " << k;
        for (std::size_t k = 0; k + 2 <= c.text.size(); k += 7)
            ASSERT_EQ(encode_in_pieces(c.text, c.options, {k, k + 1, k + 2}), whole) << "cut at " << k;
    }
}

// An error is reported at the same line and column whichever chunk it falls in.
TEST(Encode, ErrorPositionsAreTheSameInPieces) {
    std::string text = "%\nN1 G01\nN2 (ДЕТАЛЬ)\nM02\n";
    for (std::size_t k = 0; k <= text.size(); ++k) {
        try {
            encode_in_pieces(text, {}, {k});
            FAIL() << "Cyrillic encoded without koi7";
        } catch (const Error& e) {
            ASSERT_EQ(e.where().describe(), "line 3, column 5") << "cut at byte " << k;
        }
    }
}

TEST(Encode, SkipsAByteOrderMarkAtTheStart) {
    EncodeOptions o{.leader = 0, .trailer = 0};
    std::string text = "%\nN1 G01\n";
    for (std::size_t cut = 0; cut <= 4; ++cut) {
        std::string with_bom = std::string(utf8_bom) + text;
        Encoder e(o);
        std::vector<Frame> frames;
        e.feed(std::string_view(with_bom).substr(0, cut), frames);
        e.feed(std::string_view(with_bom).substr(cut), frames);
        e.finish(frames);
        EXPECT_EQ(frames, encode(text, o)) << "cut at " << cut;
        EXPECT_TRUE(e.skipped_byte_order_mark());
    }
    // Anywhere else it is a character ISO cannot carry, named visibly.
    try {
        encode("%\n" + std::string(utf8_bom) + "N1\n", o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("U+FEFF"), std::string::npos) << e.what();
    }
}

TEST(Encode, DosEndOfFileMarksAreNotPunched) {
    EncodeOptions o{.leader = 0, .trailer = 0};
    std::string text = "%\r\nN1 G01\r\nM30\r\n%\r\n";
    for (std::string marks : {"\x1A", "\x1A\x1A"}) {
        std::string with_marks = text + marks;
        for (std::size_t cut = 0; cut <= with_marks.size(); ++cut) {
            Encoder e(o);
            std::vector<Frame> frames;
            e.feed(std::string_view(with_marks).substr(0, cut), frames);
            e.feed(std::string_view(with_marks).substr(cut), frames);
            e.finish(frames);
            ASSERT_EQ(frames, encode(text, o)) << "cut at " << cut;
            ASSERT_TRUE(e.skipped_end_of_file_mark());
            EXPECT_EQ(e.skipped_end_of_file_mark()->describe(), "line 5, column 1");
        }
    }
    // With text after it, a mark is the character SUB, punched where it stands.
    auto sub = encode(
        "N1\x1A"
        "N2\n",
        o);
    ASSERT_EQ(sub.size(), 6U);
    EXPECT_EQ(sub[2], Frame{0x9A});
    Encoder plain(o);
    std::vector<Frame> frames;
    plain.feed(text, frames);
    plain.finish(frames);
    EXPECT_FALSE(plain.skipped_end_of_file_mark());
}

TEST(Encode, CrLfGivesACrLfTapeBack) {
    EncodeOptions lf{.leader = 0, .trailer = 0};
    EncodeOptions crlf = lf;
    crlf.crlf = true;
    auto tape = encode("%\nN1\n%\n", crlf);
    EXPECT_EQ(tape.size(), 10U);
    DecodeOptions d;
    auto text = decode(tape, d).text;
    EXPECT_EQ(text, "%\r\nN1\r\n%\r\n");
    EXPECT_EQ(encode(text, crlf), tape) << "decode then encode --crlf: the same tape";
    EXPECT_NE(encode(text, lf), tape) << "without it every CR is dropped";
}
