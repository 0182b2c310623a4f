// Leader labels: the font, the frames it punches (parity-valid, never a character a reader acts on),
// reading them back, and a program whose decoding does not change for a label in its leader.
#include "tape/label.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <set>

#include "codec/label_font.hpp"
#include "codec/utf8.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "tape/input.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

std::vector<Frame> with_blank_around(const std::vector<Frame>& label) {
    std::vector<Frame> t(label.size() + 2 * label_blank_around, blank_frame);
    std::copy(label.begin(), label.end(), t.begin() + label_blank_around);
    return t;
}

// Every way of punching a label: ISO with each parity rule, and EIA.
std::vector<FrameCode> label_codes() {
    std::vector<FrameCode> codes;
    for (Parity p : {Parity::even, Parity::odd, Parity::mark, Parity::space, Parity::none})
        codes.push_back(FrameCode::iso(p));
    codes.push_back(FrameCode::eia());
    return codes;
}

std::string decoded(const std::string& path) {
    Input in(path, InputOptions{});
    DecodeResult r;
    while (in.next_text(r)) {
    }
    EXPECT_TRUE(r.ok());
    return r.text;
}

}  // namespace

TEST(LabelFont, EveryGlyphIsFiveBySixAndDiffersFromTheOthersOfItsSet) {
    for (auto set : {label_font::plain(), label_font::cyrillic()}) {
        std::set<std::string> seen;
        for (const auto& g : set) {
            std::string all;
            for (const char* row : g.rows) {
                ASSERT_EQ(std::strlen(row), 5U);
                EXPECT_EQ(std::strspn(row, "#."), 5U);
                all += row;
            }
            EXPECT_TRUE(seen.insert(all).second) << "glyph U+" << std::hex << static_cast<unsigned>(g.ch) << " twice";
        }
    }
    EXPECT_EQ(label_glyph(U'Ж').size(), 6U);
    EXPECT_TRUE(label_glyph(U'ß').empty());
}

TEST(Label, EveryFrameOfTheWholeAlphabetIsParityValidAndNeverActedOn) {
    for (const FrameCode& code : label_codes()) {
        auto frames = label_frames(label_alphabet(), code);
        ASSERT_EQ(frames.size(), label_frame_count(26 + 10 + 4 + 33));
        for (Frame f : frames) {
            SCOPED_TRACE(holes_picture(f));
            EXPECT_NE(f, blank_frame);  // a label is one run of punched frames
            ASSERT_NE(code.kind(f), FrameKind::parity_error);
            if (code.code() == Code::eia) {
                EXPECT_NE(f, 0x80);                  // End of Block
                EXPECT_NE(f, *code.frame_for('%'));  // rewind stop
                EXPECT_NE(code.kind(f), FrameKind::blank);
            } else {
                ASSERT_EQ(code.kind(f), f == 0xFF || f == 0x7F ? FrameKind::rubout : FrameKind::character);
                if (code.kind(f) != FrameKind::character) continue;
                char c = code.character(f);
                EXPECT_GE(static_cast<unsigned char>(c), 0x40U);  // so none of % LF CR : DC1-DC4
                for (char bad : std::string("%\n\r:\x11\x12\x13\x14")) EXPECT_NE(c, bad);
            }
        }
    }
}

TEST(Label, TheWholeAlphabetReadsBackInEveryCode) {
    for (const FrameCode& code : label_codes()) {
        auto tape = with_blank_around(label_frames(label_alphabet(), code));
        auto found = find_label(tape);
        ASSERT_TRUE(found) << code_name(code.code());
        EXPECT_EQ(found->text, label_alphabet());
        EXPECT_EQ(found->first, label_blank_around);
        EXPECT_EQ(found->frames, label_frame_count(73));
        EXPECT_EQ(found->code, code.code());
    }
}

TEST(Label, EachCharacterAloneReadsBackAsItself) {
    // Homoglyphs (Latin A, Cyrillic А) are told apart by the marker before them.
    std::string alphabet = label_alphabet();
    for (std::size_t i = 0; i < alphabet.size();) {
        std::size_t n = utf8::length(alphabet, i);
        std::string ch = alphabet.substr(i, n);
        i += n;
        if (ch == " ") continue;  // a space alone is blank letters on the rail: read back too, below
        auto found = find_label(with_blank_around(label_frames(ch, FrameCode::iso())));
        ASSERT_TRUE(found) << ch;
        EXPECT_EQ(found->text, ch);
    }
    auto spaced = find_label(with_blank_around(label_frames("A B", FrameCode::eia())));
    ASSERT_TRUE(spaced);
    EXPECT_EQ(spaced->text, "A B");
}

TEST(Label, SmallLettersArePunchedAsCapitals) {
    auto found = find_label(with_blank_around(label_frames("detail ёж 17", FrameCode::iso())));
    ASSERT_TRUE(found);
    EXPECT_EQ(found->text, "DETAIL ЁЖ 17");
}

TEST(Label, WhatTheFontCannotDrawIsAUsageError) {
    auto code = FrameCode::iso();
    for (const char* text : {"", "ß", "A_B", "%"}) {
        try {
            label_frames(text, code);
            ADD_FAILURE() << text;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::usage) << text;
        }
    }
    EXPECT_NO_THROW(label_frames(std::string(label_max_chars, 'A'), code));
    EXPECT_THROW(label_frames(std::string(label_max_chars + 1, 'A'), code), Error);
    EXPECT_THROW(label_frames("A", FrameCode::five_track(Code::ita2)), Error);
}

TEST(Label, NoSampleTapeAndNoProgramIsTakenForALabel) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(TAPE_SOURCE_DIR) + "/tapes")) {
        if (entry.path().extension() != ".ptp") continue;
        EXPECT_FALSE(find_label(read_frames(entry.path().string()))) << entry.path();
    }
    // Capitals on tape have track 7 like a label's frames, but do not make its letters.
    auto program = encode("HELLO WORLD\n", EncodeOptions{.leader = 10, .trailer = 10});
    EXPECT_FALSE(find_label(program));
    auto run = encode("@@@@@@@\n", EncodeOptions{.leader = 10, .trailer = 10});
    EXPECT_FALSE(find_label(run));
}

TEST(Label, EncodedIntoTheLeaderTheProgramAndItsDecodingAreUnchanged) {
    TempDir dir;
    std::string program = read_text(sample_path("gost-20999-format-example.txt"));
    for (Code c : {Code::iso, Code::eia}) {
        std::string text = c == Code::iso ? program : read_text(sample_path("gost-20999-format-example.eia.txt"));
        EncodeOptions plain{.code = c};
        EncodeOptions labelled = plain;
        labelled.label = "ДЕТАЛЬ 17";
        auto without = encode(text, plain), with = encode(text, labelled);
        ASSERT_EQ(without.size(), with.size());
        // The leader keeps its length: from the program's start on, every frame is the same.
        EXPECT_TRUE(std::equal(without.begin() + default_leader, without.end(), with.begin() + default_leader));
        auto found = find_label(with);
        ASSERT_TRUE(found);
        EXPECT_EQ(found->text, "ДЕТАЛЬ 17");
        EXPECT_EQ(found->first, label_blank_around);
        std::string a = dir.file("a.ptp"), b = dir.file("b.ptp");
        write_file_atomic(a, std::string(without.begin(), without.end()), true);
        write_file_atomic(b, std::string(with.begin(), with.end()), true);
        EXPECT_EQ(decoded(a), decoded(b)) << code_name(c);
        Input in(b, InputOptions{});
        auto label = in.label();
        ASSERT_TRUE(label);
        EXPECT_EQ(label->text, "ДЕТАЛЬ 17");
        // The frames themselves are given as punched: the label is holes on the tape.
        auto frames = in.next_frames();
        ASSERT_GE(frames.size(), label->first + label->frames);
        EXPECT_NE(frames[label->first], blank_frame);
    }
}

TEST(Label, AGivenCodeStillSkipsTheLabel) {
    TempDir dir;
    auto with = encode("%\nN1 G0 X1\nM2\n", EncodeOptions{.label = "A1"});
    std::string b = dir.file("b.ptp");
    write_file_atomic(b, std::string(with.begin(), with.end()), true);
    InputOptions o;
    o.detect_code = false;
    Input in(b, o);
    DecodeResult r;
    while (in.next_text(r)) {
    }
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.text, "%\nN1 G0 X1\nM2\n");
}

TEST(Label, ALeaderTooShortForTheLabelIsAUsageErrorSayingHowLong) {
    try {
        encode("%\n", EncodeOptions{.leader = 20, .label = "AB"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage);
        EXPECT_NE(std::string(e.what()).find("33 frames"), std::string::npos) << e.what();
    }
}

TEST(LeaderTitle, ATitleInAnotherFontIsFoundNotRead) {
    // "AL" drawn seven holes high, a column a frame, as on the Elliott 900 archive's tapes.
    std::vector<Frame> t(30, 0);
    for (Frame f :
         {0x7E, 0x09, 0x09, 0x09, 0x7E, 0x00, 0x7F, 0x40, 0x40, 0x40, 0x60, 0x00, 0x7F, 0x49, 0x49, 0x49, 0x41})
        t.push_back(f);
    t.insert(t.end(), 40, 0);
    auto program = encode("%\nN1\n", EncodeOptions{.leader = 0, .trailer = 10});
    t.insert(t.end(), program.begin(), program.end());
    auto label = find_label(t);
    ASSERT_TRUE(label);
    EXPECT_EQ(label->font, LabelFont::title);
    EXPECT_EQ(label->first, 30U);
    EXPECT_EQ(label->frames, 17U);
    EXPECT_TRUE(label->text.empty());
    // A program with short lines between blank frames is no title.
    std::vector<Frame> lines(30, 0);
    for (const char* line : {"%\n", "N1\n", "N2\n", "M2\n"}) {
        auto f = encode(line, EncodeOptions{.leader = 0, .trailer = 5});
        lines.insert(lines.end(), f.begin(), f.end());
    }
    lines.insert(lines.end(), 30, 0);
    EXPECT_FALSE(find_title(lines));
}
