// The Elliott 900 and 920 telecodes as table data: reading, punching, detecting a 920 tape.
#include "tape/telecode.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "tape/decode.hpp"
#include "tape/detect.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

std::string decoded(const std::vector<Frame>& frames, Code code) {
    DecodeOptions o;
    o.code = code;
    auto r = decode(frames, o);
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
    return r.text;
}

std::vector<Frame> punched(const std::string& text, Code code) {
    EncodeOptions o;
    o.code = code;
    o.leader = o.trailer = 10;
    return encode(text, o);
}

}  // namespace

TEST(Telecode, The920CodeHasItsParityOnTrack5) {
    const auto& t = TelecodeTable::builtin(Code::elliott920);
    EXPECT_EQ(t.name(), "Elliott 920 telecode");
    // 'C' is value 043: tracks 1, 2 and 6, odd, so track 5 is punched.
    EXPECT_EQ(t.frame_of(U'C'), Frame{0x53});
    EXPECT_EQ(t.frame_of_value(043), Frame{0x53});
    EXPECT_EQ(t.entry(0x53).text, "C");
    EXPECT_EQ(t.frame_of(U'\n'), Frame{0x12}) << "newline is 002";
    EXPECT_EQ(t.frame_of(U'£'), t.frame_of(U'#')) << "# is punched as £";
    for (int f = 0; f < 256; ++f) {
        if (t.entry(static_cast<Frame>(f)).kind != TelecodeTable::Kind::none) {
            EXPECT_EQ(hole_count(static_cast<Frame>(f)) % 2, 0);
        }
    }
}

TEST(Telecode, The900CodeIsAsciiButForItsOwnCharacters) {
    const auto& t = TelecodeTable::builtin(Code::elliott900);
    EXPECT_EQ(t.frame_of(U'C'), Frame{0xC3}) << "even parity on track 8, as ISO";
    EXPECT_EQ(t.frame_of(U'£'), Frame{0xA3}) << "£ where ASCII has #";
    EXPECT_EQ(t.entry(0x14).text, "⏹") << "the halt code, 024";
}

TEST(Telecode, RoundTripsWithItsOwnCharacters) {
    std::string text = "(CONVERSION FOR MANDY, 15/2/71)\n£MAN\t8\t;+3 º ↑ ⑩\n";
    EXPECT_EQ(decoded(punched(text, Code::elliott920), Code::elliott920), text);
    std::string nine = "£SIR: A+B; X=`1'\r\n";
    EXPECT_EQ(decoded(punched(nine, Code::elliott900), Code::elliott900), "£SIR: A+B; X=`1'\n");
}

TEST(Telecode, RefusesWhatTheCodeCannotCarry) {
    try {
        punched("A$B\n", Code::elliott920);
        FAIL() << "the 920 code has no $";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::bad_text);
        EXPECT_EQ(std::string(e.what()), "'$' cannot be punched in the Elliott 920 telecode");
        EXPECT_EQ(e.where().describe(), "line 1, column 2");
    }
    DecodeOptions o;
    o.code = Code::elliott920;
    o.charset = Charset::koi7;
    EXPECT_THROW(Decoder{o}, Error);
}

TEST(Telecode, BadFramesAreNamed) {
    auto frames = punched("AB\n", Code::elliott920);
    frames[11] ^= 0x40;  // a hole lost: odd
    DecodeOptions o;
    o.code = Code::elliott920;
    o.keep_going = true;
    auto r = decode(frames, o);
    ASSERT_EQ(r.diagnostics.size(), 1U);
    EXPECT_EQ(r.diagnostics[0].code, Errc::parity);
    EXPECT_EQ(r.diagnostics[0].where.frame, 12U);
}

TEST(Telecode, A920TapeIsDetectedNotReadAsIso) {
    std::string text;
    for (int i = 0; i < 20; ++i) text += "(ENTRY POINTS)\n\t8\tFR8TO5\t(900 OR 920 TO 803)\n";
    auto d = detect_code(punched(text, Code::elliott920));
    EXPECT_EQ(d.kind, TapeKind::telecode) << d.reason;
    ASSERT_TRUE(d.code);
    EXPECT_EQ(*d.code, Code::elliott920);
    EXPECT_EQ(d.hint.action, Hint::Action::none) << "auto decodes it so: no advice to give --code";
    EXPECT_EQ(d.evidence.fits[5].bad_frames, 0U);
    EXPECT_GT(d.evidence.fits[0].controls, 0U) << "as ISO it is full of controls";
}

TEST(Telecode, IsoTapesStayIso) {
    auto d = detect_code(read_frames(sample_path("16k20f3s5-turning.iso.ptp")));
    EXPECT_EQ(d.kind, TapeKind::iso) << d.reason;
}

TEST(Telecode, TooManyControlsIsNoIso) {
    // Good parity, but an ESC in every block: no NC tape holds that, and no other reading fits either.
    std::vector<Frame> t;
    for (int i = 0; i < 200; ++i) t.insert(t.end(), {0x47, 0x30, 0xB1, 0xA0, 0xD8, 0xB1, 0x30, 0x0A, 0x1B});
    auto d = detect_code(t);
    EXPECT_EQ(d.kind, TapeKind::unknown) << d.reason;
    EXPECT_FALSE(d.code);
    EXPECT_NE(d.reason.find("not ISO with even parity: too many control characters (200 of 1800 frames"),
              std::string::npos)
        << d.reason;
}

TEST(TelecodeTables, MalformedTablesNameTheLine) {
    auto fails_at = [](const std::string& text, std::uint64_t line, const std::string& words) {
        try {
            TelecodeTable::parse(text);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_table);
            EXPECT_EQ(e.where().line.value_or(0), line) << e.what();
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    std::string head = "name T\ntracks 1 2 3 4 5 6 7\nparity 8\n000 BLANK\n012 LF\n";
    EXPECT_NO_THROW(TelecodeTable::parse(head + "101 A\nalias a A\n"));
    fails_at(head + "101 A\n101 B\n", 7, "given twice");
    fails_at(head + "101 A\n102 A\n", 7, "two values");
    fails_at(head + "200 A\n", 6, "octal");
    fails_at(head + "101 AB\n", 6, "one character");
    fails_at("name T\ntracks 1 2 3 4 5 6 6\n", 2, "twice");
    fails_at("name T\ntracks 1 2 3 4 5 6 7\nparity 7\n000 BLANK\n012 LF\n", 0, "parity track");
    fails_at(head + "alias b B\n", 6, "not in the table");
}

TEST(Telecode, MandyReadsAsText) {
    std::string path = shared_data_dir() + "/outside2/tapes/elliott900/MANDYV1S.1";
    if (shared_data_dir().empty()) GTEST_SKIP() << "../shared/data is absent: the real tape is not in the project";
    auto frames = read_frames(path);
    auto d = detect_code(frames);
    ASSERT_EQ(d.code, Code::elliott920) << d.reason;
    std::string text = decoded(frames, Code::elliott920);
    EXPECT_EQ(text.rfind("\n((CONVERSION PROGRAM FOR MANDY, 15/2/71)\n", 0), 0U) << text.substr(0, 60);
    EXPECT_TRUE(text.ends_with("⏹")) << "the tape ends with the halt code";
}
