// The library's one entry point for inputs (tape::Input), the streaming loader and survey, and the
// frames sent for an input: the same results however the input is cut, bounded by chunks.
#include "tape/input.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "tape/encode.hpp"
#include "tape/feed.hpp"
#include "tape/survey.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

// Gives the bytes in pieces of a fixed size, as a pipe or a slow reader would.
class PieceSource : public ByteSource {
public:
    PieceSource(std::string bytes, std::size_t piece) : bytes_(std::move(bytes)), piece_(piece) {}
    std::size_t read(std::span<std::uint8_t> buffer) override {
        std::size_t n = std::min({buffer.size(), piece_, bytes_.size() - at_});
        std::memcpy(buffer.data(), bytes_.data() + at_, n);
        at_ += n;
        return n;
    }

private:
    std::string bytes_;
    std::size_t piece_, at_ = 0;
};

Input open_bytes(const std::string& bytes, const std::string& name, InputOptions o = {}, std::size_t piece = 1 << 20) {
    return Input(std::make_unique<PieceSource>(bytes, piece), name, o);
}

std::string text_of(Input& in) {
    DecodeResult r;
    while (in.next_text(r)) {
    }
    return r.text;
}

struct Recorder : ProgramVisitor {
    std::vector<std::string> events;
    void label(std::string_view text) override { events.push_back("label " + std::string(text)); }
    void program_start(const Program& p) override {
        events.push_back("program " + p.number.value_or("") + " @" + std::to_string(p.start.offset));
    }
    void block(const Block& b) override {
        events.push_back("block " + b.text() + " @" + std::to_string(b.where.offset) + " line " +
                         std::to_string(b.where.line) + " col " + std::to_string(b.where.column) + " frame " +
                         (b.where.frame ? std::to_string(*b.where.frame) : "-"));
    }
    void after_end(std::string_view text, const Location& where) override {
        events.push_back("after " + std::string(text) + " @" + std::to_string(where.offset));
    }
    void physical_start() override { events.push_back("%%"); }
    void finding(const Finding& f) override {
        events.push_back("finding " + std::string(f.id()) + " @" + std::to_string(f.where.byte.value_or(0)) + " " +
                         f.message);
    }
};

const std::string program =
    "LABEL\n%%7\nN1 G01 X+12.5 Y-3 (КОММЕНТ)\nN2 X1 X2 #\nN3 M02\nAFTER\n%8\n/N4 :5 Q\nN5 X1.2.3 M30\n%9\nN6 G00";

}  // namespace

TEST(ProgramLoader, EverySplitPointGivesTheSameEvents) {
    Recorder whole;
    load_each(program, {}, whole);
    ASSERT_GT(whole.events.size(), 10U);
    for (std::size_t cut = 0; cut <= program.size(); ++cut) {
        for (std::size_t cut2 = cut; cut2 <= program.size(); cut2 += 7) {
            Recorder pieces;
            ProgramLoader loader(pieces);
            std::string_view all(program);
            loader.feed(all.substr(0, cut));
            loader.feed(all.substr(cut, cut2 - cut));
            loader.feed(all.substr(cut2));
            loader.finish();
            ASSERT_EQ(pieces.events, whole.events) << "cut at " << cut << " and " << cut2;
        }
    }
}

// A Fanuc program whose '%' holds comment lines back until its first block: they are loaded at their
// own places in the text when it comes, and the line then goes on with what the loader knows of it (its
// ';' ends of block, its stray ')'), wherever the text was cut.
TEST(ProgramLoader, HeldCommentLinesAndEveryCutKeepTheLinesOwnMarks) {
    const std::string fanuc = "%\n(HEADER)\n\n(" + std::string(100, 'A') + ")\nG0 X1;G1 X2 F1)\nM30\n%\n";
    Recorder whole;
    load_each(fanuc, {}, whole, LoadOptions{Dialect::fanuc});
    auto has = [&](std::string_view start) {
        return std::any_of(whole.events.begin(), whole.events.end(),
                           [&](const std::string& e) { return e.starts_with(start); });
    };
    EXPECT_TRUE(has("block G0 X1 @"));  // the ';' ends the block
    EXPECT_TRUE(has("block G1 X2 F1) @"));
    EXPECT_TRUE(has("finding unexpected-character @121 'G1 X2 F1)' is taken as a comment"));
    for (std::size_t cut = 0; cut <= fanuc.size(); ++cut) {
        Recorder pieces;
        ProgramLoader loader(pieces, LoadOptions{Dialect::fanuc});
        loader.feed(std::string_view(fanuc).substr(0, cut));
        loader.feed(std::string_view(fanuc).substr(cut));
        loader.finish();
        ASSERT_EQ(pieces.events, whole.events) << "cut at " << cut;
    }
}

TEST(Input, ATapeReadInAnyPiecesLoadsAsTheWholeTape) {
    auto frames =
        encode(program.substr(program.find('%')), EncodeOptions{.charset = Charset::koi7, .leader = 30, .trailer = 30});
    std::string bytes(frames.begin(), frames.end());
    InputOptions o;
    o.decode.positions = true;
    o.decode.charset = Charset::koi7;
    Recorder whole;
    {
        auto in = open_bytes(bytes, "t.ptp", o);
        ASSERT_TRUE(in.is_image());
        EXPECT_TRUE(load_each(in, whole));
    }
    for (std::size_t piece : {1, 2, 5, 64, 1000}) {
        Recorder pieces;
        auto in = open_bytes(bytes, "t.ptp", o, piece);
        EXPECT_TRUE(load_each(in, pieces));
        EXPECT_EQ(pieces.events, whole.events) << "pieces of " << piece;
    }
    ASSERT_GT(whole.events.size(), 2U);
    EXPECT_EQ(whole.events[2].find("frame -"), std::string::npos) << whole.events[2] << ": blocks carry their frames";
}

TEST(Input, TextOrImageIsDecidedByFormatThenExtensionThenContent) {
    const std::string text = "%\nN1 G01 X1\nN2 M02\n";
    EXPECT_FALSE(open_bytes(text, "part.txt").is_image());
    EXPECT_FALSE(open_bytes(text, "-").is_image());
    EXPECT_TRUE(open_bytes(text, "part.ptp").is_image()) << "an image's own extension decides";
    InputOptions as_raw;
    as_raw.format = find_image_format("raw");
    auto in = open_bytes(text, "part.txt", as_raw);
    ASSERT_TRUE(in.is_image());
    EXPECT_EQ(in.format()->id, "raw");
    auto frames = encode("%\n", EncodeOptions{.leader = 5});
    EXPECT_TRUE(open_bytes(std::string(frames.begin(), frames.end()), "-").is_image()) << "blank leader is no text";
    const std::string picture = find_image_format("holes")->write(
        encode("%\n", EncodeOptions{.leader = 0, .trailer = 0}), ImageWriteOptions{.header = false});
    auto holes = open_bytes(picture, "part.txt");
    ASSERT_TRUE(holes.is_image());
    EXPECT_EQ(holes.format()->id, "holes");
}

// A bordered picture another tool printed is not a holes picture: named .holes or given --format
// holes, it is refused at its first line, never silently read as raw bytes.
TEST(Input, ContentNeverOverridesTheGivenFormat) {
    const std::string bordered = "+----------+\n|ooo.o  o  |\n";
    for (bool by_option : {false, true}) {
        InputOptions o;
        if (by_option) o.format = find_image_format("holes");
        auto in = open_bytes(bordered, by_option ? "-" : "scan.holes", o);
        ASSERT_TRUE(in.is_image());
        EXPECT_EQ(in.format()->id, "holes");
        try {
            while (!in.next_frames().empty()) {
            }
            ADD_FAILURE() << "a bordered picture read as frames";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_image);
            EXPECT_EQ(e.where().line, 1U);
        }
    }
}

TEST(Input, AFaultInATextProgramIsFoundWhereverThePiecesEnd) {
    const std::string text = "%\nN1 G01 (ПРОХОД)\nN2 X1\x01 M02\n";
    for (std::size_t piece : {1, 2, 3, 7, 100}) {
        InputOptions o;
        o.kind = InputKind::text;
        auto in = open_bytes(text, "-", o, piece);
        try {
            text_of(in);
            ADD_FAILURE() << "a control character taken as text";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_text);
            EXPECT_EQ(e.where().line, 3U) << "pieces of " << piece;
            EXPECT_EQ(e.where().column, 6U) << "pieces of " << piece;
            EXPECT_EQ(e.hint().action, Hint::Action::read_as_image);
        }
    }
    InputOptions o;
    o.kind = InputKind::text;
    auto cyrillic = open_bytes("%\n(ЖЁЛТЫЙ)\n", "-", o, 1);
    EXPECT_EQ(text_of(cyrillic), "%\n(ЖЁЛТЫЙ)\n") << "a character cut by a piece's end is no fault";
}

TEST(Input, DetectionReadsAheadAndGivesTheFramesAgain) {
    auto frames = encode("%\nN1 X1\n", EncodeOptions{.code = Code::eia, .leader = 2000});
    std::string bytes(frames.begin(), frames.end());
    auto in = open_bytes(bytes, "t.ptp", {}, 16);
    EXPECT_EQ(in.decode_options().code, Code::eia);
    ASSERT_TRUE(in.detection());
    std::vector<Frame> back;
    for (auto f = in.next_frames(); !f.empty(); f = in.next_frames()) back.insert(back.end(), f.begin(), f.end());
    EXPECT_EQ(back, frames);
}

TEST(Surveyor, TheSameCountsHoweverTheTapeIsCut) {
    auto frames = encode("%\nN1 X1\n\nN2 M02\n", EncodeOptions{.leader = 7, .trailer = 9});
    frames.insert(frames.begin() + 20, 3, blank_frame);
    frames[12] ^= 0x01;  // a parity error
    FrameCode code = FrameCode::iso();
    TapeSurvey whole = survey(frames, code);
    EXPECT_EQ(whole.leader, 7U);
    EXPECT_EQ(whole.trailer, 9U);
    EXPECT_EQ(whole.blank_inside, 3U);
    EXPECT_EQ(whole.parity_errors, 1U);
    for (std::size_t cut = 0; cut <= frames.size(); ++cut) {
        Surveyor s(code);
        s.feed(std::span(frames).first(cut));
        s.feed(std::span(frames).subspan(cut));
        TapeSurvey r = s.result();
        ASSERT_EQ(r.leader, whole.leader) << cut;
        ASSERT_EQ(r.trailer, whole.trailer) << cut;
        ASSERT_EQ(r.blank_inside, whole.blank_inside) << cut;
        ASSERT_EQ(r.data, whole.data) << cut;
        ASSERT_EQ(r.parity_errors, whole.parity_errors) << cut;
        ASSERT_EQ(r.program_starts, whole.program_starts) << cut;
        ASSERT_EQ(r.end_of_blocks, whole.end_of_blocks) << cut;
    }
}

TEST(FramesToSend, AnImageGoesAsItIsUnlessNewBlankEndsAreAsked) {
    auto frames = encode("%\nN1 M30\n", EncodeOptions{.leader = 4, .trailer = 6});
    std::string bytes(frames.begin(), frames.end());
    auto in = open_bytes(bytes, "t.ptp");
    EXPECT_EQ(frames_to_send(in, FeedOptions{}), frames);
    auto again = open_bytes(bytes, "t.ptp");
    FeedOptions o;
    o.replace_leader = true;
    o.encode.leader = 1;
    auto sent = frames_to_send(again, o);
    EXPECT_EQ(sent.size(), frames.size() - 3);
    EXPECT_EQ(sent[0], blank_frame);
    EXPECT_NE(sent[1], blank_frame);
}

TEST(FramesToSend, ATextProgramIsSentAsWrittenUnlessAskedToWrapIt) {
    FeedOptions o;
    o.encode.leader = o.encode.trailer = 0;
    auto sent = [&](const std::string& text) {
        auto in = open_bytes(text, "-", {}, 2);
        return frames_to_send(in, o);
    };
    // As encode punches it (issue 31: one file, one tape): no LF added after a last line without one.
    EXPECT_EQ(sent("N1 M30"), encode("N1 M30", o.encode));
    EXPECT_EQ(sent("%\nN1 M30\n%"), encode("%\nN1 M30\n%", o.encode));
    EXPECT_EQ(sent("%\nN1 M30\n%\n"), encode("%\nN1 M30\n%\n", o.encode));
    o.percent = true;
    EXPECT_EQ(sent("N1 M30"), encode("%\nN1 M30\n%", o.encode));
    EXPECT_EQ(sent("%\nN1 M30\n"), encode("%\nN1 M30\n%", o.encode));
    // Never doubled: a program that ends with its '%' already is sent as it is.
    EXPECT_EQ(sent("%\nN1 M30\n%\n"), encode("%\nN1 M30\n%\n", o.encode));
    EXPECT_EQ(sent("%\n"), encode("%\n%", o.encode));
}

TEST(FramesToSend, FanucSemicolonsBecomeEndsOfBlock) {
    FeedOptions o;
    o.encode.leader = o.encode.trailer = 0;
    o.dialect = Dialect::fanuc;
    auto in = open_bytes("%\nO1000;\nG00 X1 ;\nG01 X2 F100; G01 X3\n(NOTE; KEPT)\nM30;\n%\n", "-", {}, 3);
    DialectChoice chosen;
    EXPECT_EQ(frames_to_send(in, o, &chosen),
              encode("%\nO1000\nG00 X1\nG01 X2 F100\nG01 X3\n(NOTE; KEPT)\nM30\n%\n", o.encode));
    EXPECT_EQ(chosen.dialect, Dialect::fanuc);
    EXPECT_EQ(semicolons_to_line_ends("G1 X1;"), "G1 X1\n");
}

TEST(Input, AByteOrderMarkIsSkippedWithANote) {
    std::string program = "%\nN1 G01 X10\n";
    for (InputKind kind : {InputKind::automatic, InputKind::text}) {
        for (std::size_t piece : {1, 2, 1 << 20}) {
            auto in = open_bytes(std::string(utf8_bom) + program, "p.txt", InputOptions{.kind = kind}, piece);
            ASSERT_FALSE(in.is_image());
            EXPECT_EQ(text_of(in), program);
            ASSERT_EQ(in.notes().size(), 1U);
            EXPECT_EQ(in.notes()[0].where.line, 1U);
            EXPECT_NE(in.notes()[0].message.find("U+FEFF"), std::string::npos);
        }
    }
    auto plain = open_bytes(program, "p.txt");
    EXPECT_TRUE(plain.notes().empty());
}

TEST(Input, ATextFileGivenAsARawImageIsRefusedAsText) {
    auto in = open_bytes("%\nN1 G01 X10\nN2 M02\n", "p.ptp");
    ASSERT_TRUE(in.is_image());
    try {
        in.decode_options();
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::unknown_code);
        EXPECT_NE(std::string(e.what()).find("text program"), std::string::npos) << e.what();
        EXPECT_EQ(e.hint().action, Hint::Action::encode_text);
    }
}

TEST(Input, DetectionReadsAheadABoundedAmount) {
    // Longer than the read-ahead: the verdict says it saw the start only, and every frame comes back.
    std::string text;
    for (int i = 0; i < 40000; ++i) text += "N" + std::to_string(i) + " G01 X1\n";
    auto frames = encode(text, {});
    std::string bytes(frames.begin(), frames.end());
    auto in = open_bytes(bytes, "t.ptp", {}, 4096);
    EXPECT_EQ(in.decode_options().code, Code::iso);
    EXPECT_FALSE(in.detection()->evidence.whole_tape);
    EXPECT_LE(in.detection()->evidence.frames, 300000U);
    std::size_t back = 0;
    for (auto f = in.next_frames(); !f.empty(); f = in.next_frames()) back += f.size();
    EXPECT_EQ(back, frames.size());
}

TEST(Input, ADosEndOfFileMarkEndsTheTextWithANote) {
    std::string program = "%\r\nN1 G01 X10\r\nM30\r\n%\r\n";
    for (std::string marks : {"\x1A", "\x1A\x1A\x1A"}) {
        for (std::size_t piece : {1, 3, 1 << 20}) {
            auto in = open_bytes(program + marks, "p.nc", InputOptions{}, piece);
            ASSERT_FALSE(in.is_image()) << "a text program, not an ASCII tape with space parity";
            EXPECT_EQ(text_of(in), program);
            ASSERT_EQ(in.notes().size(), 1U);
            EXPECT_EQ(in.notes()[0].where.line, 5U);
            EXPECT_EQ(in.notes()[0].where.byte, program.size());
            EXPECT_NE(in.notes()[0].message.find("Ctrl-Z"), std::string::npos);
        }
    }
    // Text after the mark: the mark is a control character in a text program, as any other.
    auto in = open_bytes(
        "%\nN1\n\x1A"
        "N2\n",
        "p.nc", InputOptions{.kind = InputKind::text}, 2);
    try {
        text_of(in);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::bad_text);
        EXPECT_EQ(e.where().describe(), "line 3, column 1");
    }
}

TEST(Input, TheCodeAHeaderNamesIsTaken) {
    std::string hex5 = "# tape hex5 image: one 5-track frame a line, two hex digits (bit 0 = track 1)\n# code: mtk2\n";
    for (int f : {0x00, 0x00, 0x1F, 0x03, 0x13, 0x08, 0x02})
        hex5 += (f < 16 ? "0" : "") + [&] {
            char b[4];
            std::snprintf(b, sizeof b, "%X", f);
            return std::string(b);
        }() + "\n";
    auto in = open_bytes(hex5, "t.hex5");
    ASSERT_TRUE(in.is_image());
    EXPECT_EQ(in.declared_code(), Code::mtk2);
    EXPECT_EQ(in.decode_options().code, Code::mtk2);
    EXPECT_EQ(text_of(in), "AW\n");
}
