// Decoding: blank tape and DEL skipped, bad frames reported with their numbers, never repaired.
#include "tape/decode.hpp"

#include <gtest/gtest.h>

#include <random>

#include "tape/encode.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {
// "%\nN1\n" in ISO with even parity, by hand from the spec table.
const std::vector<Frame> small_iso = {0x00, 0x00, 0xA5, 0x0A, 0x4E, 0xB1, 0x0A, 0x00};
}  // namespace

TEST(Decode, SkipsLeaderTrailerAndBlankTape) {
    auto r = decode(small_iso, {});
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.text, "%\nN1\n");
}

TEST(Decode, SkipsDelWhereverItStands) {
    std::vector<Frame> t = {0xFF, 0xA5, 0xFF, 0x0A, 0x4E, 0xFF, 0xFF, 0xB1, 0x0A, 0xFF};
    EXPECT_EQ(decode(t, {}).text, "%\nN1\n");
    DecodeOptions eia{.code = Code::eia};
    std::vector<Frame> e = {0x7F, 0x0B, 0x80, 0x45, 0x7F, 0x01, 0x80};
    EXPECT_EQ(decode(e, eia).text, "%\nN1\n");
}

TEST(Decode, StopsAtTheFirstParityErrorWithItsFrameNumber) {
    auto t = small_iso;
    t[5] ^= 0x80;  // '1' loses its parity hole
    t[6] ^= 0x01;
    auto r = decode(t, {});
    ASSERT_EQ(r.diagnostics.size(), 1U);
    EXPECT_FALSE(r.complete);
    EXPECT_EQ(r.diagnostics[0].code, Errc::parity);
    EXPECT_EQ(*r.diagnostics[0].where.frame, 6U);
    EXPECT_EQ(r.diagnostics[0].message, "parity error, holes |  oo .  o|");
}

TEST(Decode, KeepGoingReportsEveryBadFrameAndMarksIt) {
    auto t = small_iso;
    t[5] ^= 0x80;
    t[4] ^= 0x02;
    DecodeOptions o{.keep_going = true};
    auto r = decode(t, o);
    ASSERT_EQ(r.diagnostics.size(), 2U);
    EXPECT_EQ(*r.diagnostics[0].where.frame, 5U);
    EXPECT_EQ(*r.diagnostics[1].where.frame, 6U);
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.text, "%\n" + std::string(bad_frame_marker) + std::string(bad_frame_marker) + "\n");
}

TEST(Decode, PositionsGiveTheFrameOfEveryCharacter) {
    DecodeOptions o{.positions = true};
    auto r = decode(small_iso, o);
    EXPECT_EQ(r.frame_of, (std::vector<std::uint64_t>{2, 3, 4, 5, 6}));
}

TEST(Decode, FastPathAgreesWithTheTableOnRandomTapes) {
    std::mt19937 rng(2026);
    for (int round = 0; round < 200; ++round) {
        std::vector<Frame> t(1 + rng() % 300);
        // Mostly good frames, with a few random ones, blanks and DELs.
        FrameCode iso = FrameCode::iso();
        for (auto& f : t) {
            unsigned pick = rng() % 100;
            f = pick < 90   ? *iso.frame_for(static_cast<unsigned char>(0x20 + rng() % 0x5F))
                : pick < 94 ? 0x00
                : pick < 97 ? 0xFF
                            : static_cast<Frame>(rng());
        }
        for (bool keep : {false, true}) {
            DecodeOptions fast{.keep_going = keep}, table{.keep_going = keep, .positions = true};
            auto a = decode(t, fast), b = decode(t, table);
            ASSERT_EQ(a.text, b.text);
            ASSERT_EQ(a.complete, b.complete);
            ASSERT_EQ(a.diagnostics.size(), b.diagnostics.size());
            for (std::size_t i = 0; i < a.diagnostics.size(); ++i)
                ASSERT_EQ(a.diagnostics[i].where.frame, b.diagnostics[i].where.frame);
        }
    }
}

// Every single-bit flip of every frame of a sample ISO tape is detected at that frame.
TEST(Decode, EverySingleBitFlipOfTheSampleIsDetected) {
    auto tape = read_frames(sample_path("gost-20999-format-example.iso.ptp"));
    ASSERT_GT(tape.size(), 300U);
    std::size_t flips = 0, detected = 0;
    for (std::size_t i = 0; i < tape.size(); ++i) {
        for (int bit = 0; bit < 8; ++bit) {
            auto damaged = tape;
            damaged[i] ^= static_cast<Frame>(1U << bit);
            ++flips;
            for (bool positions : {false, true}) {
                auto r = decode(damaged, DecodeOptions{.positions = positions});
                bool found = !r.diagnostics.empty() && *r.diagnostics[0].where.frame == i + 1;
                if (!positions)
                    detected += found;
                else
                    EXPECT_TRUE(found) << "frame " << i + 1 << " bit " << bit;
            }
        }
    }
    EXPECT_EQ(detected, flips) << "flips detected: " << detected << " of " << flips;
}

TEST(Decode, EiaFrameOutsideTheTableIsReported) {
    std::vector<Frame> e = {0x0B, 0x80, 0x0D, 0x80};
    auto r = decode(e, DecodeOptions{.code = Code::eia});
    ASSERT_EQ(r.diagnostics.size(), 1U);
    EXPECT_EQ(r.diagnostics[0].code, Errc::not_in_code);
    EXPECT_EQ(*r.diagnostics[0].where.frame, 3U);
    auto p = decode(std::vector<Frame>{0x0B, 0x03}, DecodeOptions{.code = Code::eia});
    EXPECT_EQ(p.diagnostics.at(0).code, Errc::parity);
}

TEST(Decode, Koi7ShiftsBecomeCyrillic) {
    // SO, 'd' 'e' (Н1: Д Е), SI, 'X'
    FrameCode iso = FrameCode::iso();
    std::vector<Frame> t;
    for (char c : std::string("(\x0e"
                              "de\x0fX)"))
        t.push_back(*iso.frame_for(static_cast<unsigned char>(c)));
    EXPECT_EQ(decode(t, DecodeOptions{.charset = Charset::koi7}).text, "(ДЕX)");
    EXPECT_EQ(decode(t, DecodeOptions{}).text,
              "(\x0e"
              "de\x0fX)");
    auto with_pos = decode(t, DecodeOptions{.charset = Charset::koi7, .positions = true});
    EXPECT_EQ(with_pos.frame_of.size(), with_pos.text.size());
    EXPECT_EQ(with_pos.frame_of[1], 2U);  // both bytes of Д come from frame index 2
    EXPECT_EQ(with_pos.frame_of[2], 2U);
}

TEST(Decode, MarkParityTapeReadsWithTheRightRule) {
    EncodeOptions eo{.parity = Parity::mark, .leader = 3, .trailer = 3};
    auto t = encode("HELLO\n", eo);
    EXPECT_FALSE(decode(t, {}).ok());
    auto r = decode(t, DecodeOptions{.parity = Parity::mark});
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.text, "HELLO\n");
}

// A tape of noise must not fill memory with messages: past the limit bad frames are only counted.
TEST(Decode, DiagnosticsBeyondTheLimitAreCounted) {
    std::vector<Frame> noise;
    for (int i = 0; i < 1000; ++i) noise.push_back(0x01);  // SOH without its parity hole
    for (int i = 0; i < 10; ++i) noise.push_back(0x80);    // track 8 alone: parity error too
    DecodeOptions o;
    o.keep_going = true;
    o.max_diagnostics = 5;
    DecodeResult r = decode(noise, o);
    ASSERT_EQ(r.diagnostics.size(), 5u);
    EXPECT_EQ(r.diagnostics[4].where.frame, 5u);
    EXPECT_EQ(r.unlisted.at(Errc::parity), 1005u);
    EXPECT_FALSE(r.ok());
    o.positions = true;
    DecodeResult with_positions = decode(noise, o);
    EXPECT_EQ(with_positions.diagnostics.size(), 5u);
    EXPECT_EQ(with_positions.unlisted.at(Errc::parity), 1005u);
    o.max_diagnostics = 0;
    EXPECT_EQ(decode(noise, o).diagnostics.size(), 1010u);
}

// However the tape is cut, the text, the positions and the messages are the same.
TEST(Decode, EverySplitPointGivesTheSameResult) {
    struct Case {
        std::string image;
        DecodeOptions options;
    };
    DecodeOptions iso_positions;
    iso_positions.positions = true;
    DecodeOptions koi7;
    koi7.charset = Charset::koi7;
    koi7.positions = true;
    DecodeOptions eia;
    eia.code = Code::eia;
    eia.positions = true;
    std::vector<Case> cases = {
        {"16k20f3s5-turning.iso.ptp", {}},
        {"16k20f3s5-turning.iso.ptp", iso_positions},
        {"koi7-comment.iso.ptp", koi7},
        {"16k20f3s5-turning.eia.ptp", eia},
    };
    // A damaged copy: every 37th frame with a hole punched or lost.
    std::vector<Frame> damaged = read_frames(sample_path("gost-20999-format-example.iso.ptp"));
    for (std::size_t i = 120; i < damaged.size(); i += 37) damaged[i] ^= 0x04;
    for (bool keep_going : {false, true})
        for (bool positions : {false, true}) {
            DecodeOptions o;
            o.keep_going = keep_going;
            o.positions = positions;
            o.max_diagnostics = 3;
            DecodeResult whole = decode(damaged, o);
            for (std::size_t k = 0; k <= damaged.size(); ++k) {
                Decoder d(o);
                DecodeResult r;
                d.feed(std::span(damaged).first(k), r);
                d.feed(std::span(damaged).subspan(k), r);
                ASSERT_EQ(r.text, whole.text) << "cut at frame " << k;
                ASSERT_EQ(r.frame_of, whole.frame_of) << "cut at frame " << k;
                ASSERT_EQ(r.diagnostics.size(), whole.diagnostics.size()) << "cut at frame " << k;
                for (std::size_t i = 0; i < r.diagnostics.size(); ++i) {
                    ASSERT_EQ(r.diagnostics[i].where.frame, whole.diagnostics[i].where.frame);
                    ASSERT_EQ(r.diagnostics[i].message, whole.diagnostics[i].message);
                }
                ASSERT_EQ(d.unlisted(), whole.unlisted);
                ASSERT_EQ(r.complete, whole.complete);
            }
        }
    for (const auto& c : cases) {
        std::vector<Frame> frames = read_frames(sample_path(c.image));
        DecodeResult whole = decode(frames, c.options);
        ASSERT_TRUE(whole.ok()) << c.image;
        for (std::size_t k = 0; k <= frames.size(); ++k) {
            Decoder d(c.options);
            DecodeResult r;
            d.feed(std::span(frames).first(k), r);
            d.feed(std::span(frames).subspan(k), r);
            ASSERT_EQ(r.text, whole.text) << c.image << " cut at frame " << k;
            ASSERT_EQ(r.frame_of, whole.frame_of) << c.image << " cut at frame " << k;
        }
    }
}

TEST(Decode, BadFrameNamesItsLine) {
    auto t = encode("%\nN1 G01\nN2 X10\n", EncodeOptions{.leader = 3});
    t[3 + 2 + 8 + 1] ^= 0x80;  // the X of line 3
    for (bool positions : {false, true}) {
        auto r = decode(t, DecodeOptions{.positions = positions});
        ASSERT_EQ(r.diagnostics.size(), 1U);
        EXPECT_EQ(r.diagnostics[0].where.frame, 15U);
        EXPECT_EQ(r.diagnostics[0].where.line, 3U);
        EXPECT_FALSE(r.diagnostics[0].where.block);  // which lines are blocks, only the loader knows
    }
    // Counted across chunks, and past the point where the vector loops take whole blocks.
    std::string long_text;
    for (int i = 0; i < 500; ++i) long_text += "N" + std::to_string(i) + " G01 X1\n";
    auto l = encode(long_text, EncodeOptions{.leader = 0, .trailer = 0});
    l[l.size() - 3] ^= 0x80;  // in the last line
    Decoder decoder(DecodeOptions{.keep_going = true});
    DecodeResult out;
    for (std::size_t i = 0; i < l.size(); i += 1000)
        decoder.feed(std::span(l).subspan(i, std::min<std::size_t>(1000, l.size() - i)), out);
    ASSERT_EQ(out.diagnostics.size(), 1U);
    EXPECT_EQ(out.diagnostics[0].where.line, 500U);
}

TEST(DecodeEnding, ATapeCutInsideABlockOrWithoutTrailerIsSaid) {
    auto ending_of = [](const std::vector<Frame>& t) {
        Decoder d(DecodeOptions{});
        DecodeResult r;
        d.feed(t, r);
        d.finish(r);
        return d.ending();
    };
    EXPECT_TRUE(ending_of(encode("%\nN1 G01\nM02\n%\n", EncodeOptions{})).empty());
    EXPECT_TRUE(ending_of(encode("%\nN1 G01\nM02\n%", EncodeOptions{})).empty()) << "a closing % ends it";
    auto cut = encode("%\nN1 G01\nN2 X1", EncodeOptions{.leader = 10, .trailer = 0});
    auto findings = ending_of(cut);
    ASSERT_EQ(findings.size(), 1U);
    EXPECT_EQ(findings[0].severity, Severity::warning);
    EXPECT_EQ(findings[0].where.frame, cut.size());
    EXPECT_NE(findings[0].message.find("ends inside a block, at a punched frame without a blank trailer"),
              std::string::npos);
    auto mid = encode("%\nN1\nN2 X1", EncodeOptions{.leader = 10, .trailer = 5});
    ASSERT_EQ(ending_of(mid).size(), 1U);
    EXPECT_NE(ending_of(mid)[0].message.find("ends inside a block:"), std::string::npos);
    auto no_trailer = encode("%\nN1\n", EncodeOptions{.leader = 10, .trailer = 0});
    ASSERT_EQ(ending_of(no_trailer).size(), 1U);
    EXPECT_NE(ending_of(no_trailer)[0].message.find("without a blank trailer"), std::string::npos);
    EXPECT_TRUE(ending_of(std::vector<Frame>(20, 0)).empty()) << "blank tape ends well";
}

TEST(FiveTrackUnshiftOnSpace, ASpaceReturnsToLettersWhenAsked) {
    // "1 W": FIGS 1 SP W, as a teleprinter with unshift-on-space punches it (no LTRS after the space).
    std::vector<Frame> t = {0x1B, 0x17, 0x04, 0x13};
    DecodeOptions o;
    o.code = Code::ita2;
    EXPECT_EQ(decode(t, o).text, "1 2") << "without it the figures register holds";
    o.unshift_on_space = true;
    EXPECT_EQ(decode(t, o).text, "1 W");
    o.code = Code::mtk2;
    EXPECT_THROW(Decoder{o}, Error);
    // Punched so that both kinds of teleprinter read it right: FIGS again after the space.
    EncodeOptions e{.code = Code::ita2, .leader = 0, .trailer = 0};
    auto frames = encode("1 2", e);
    EXPECT_EQ(frames, (std::vector<Frame>{0x1B, 0x17, 0x04, 0x1B, 0x13}));
    DecodeOptions usos{.code = Code::ita2, .unshift_on_space = true};
    EXPECT_EQ(decode(frames, usos).text, "1 2");
}

// Line ends counted a piece at a time, as decode takes the text: the same as a look at every character,
// wherever the pieces are cut (a CR at the end of one and its LF at the start of the next).
TEST(LineEnds, CountsLinesAndCrLfPairsAcrossPieces) {
    std::mt19937 random(30);
    const std::string alphabet = "N1 \r\n\n\rX";
    for (int t = 0; t < 300; ++t) {
        std::string text;
        for (int k = random() % 200; k > 0; --k) text += alphabet[random() % alphabet.size()];
        std::uint64_t lines = 0, crlf = 0;
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') ++lines, crlf += i > 0 && text[i - 1] == '\r';
        LineEnds ends;
        for (std::size_t at = 0; at < text.size();) {
            std::size_t n = std::min<std::size_t>(1 + random() % 40, text.size() - at);
            ends.take(std::string_view(text).substr(at, n));
            at += n;
        }
        ASSERT_EQ(ends.lines, lines) << text;
        ASSERT_EQ(ends.crlf, crlf) << text;
    }
}
