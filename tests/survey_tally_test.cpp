// The surveys and the code detector's evidence, counted from one tally of the frames' values, against
// the plain reading of their rules a frame at a time (as they were counted before): the same figures on
// the project's sample tapes, every tape of ../shared/data and made-up tapes, however they are cut.
#include <gtest/gtest.h>

#include <random>

#include "every_tape.hpp"
#include "tape/code.hpp"
#include "tape/detect.hpp"
#include "tape/survey.hpp"
#include "test_util.hpp"

namespace {

using namespace tape;

TapeSurvey plain_survey(std::span<const Frame> frames, const FrameCode& code) {
    TapeSurvey s;
    s.frames = frames.size();
    for (Frame f : frames) {  // the parity counts too, a frame at a time
        if (f == blank_frame) continue;
        ++s.parity.frames;
        s.parity.even += hole_count(f) % 2 == 0;
        s.parity.mark += (f & 0x80) != 0;
    }
    std::uint64_t run = 0;
    bool punched = false, percent = false;
    for (Frame f : frames) {
        if (f == blank_frame) {
            ++run;
            continue;
        }
        (punched ? s.blank_inside : s.leader) += run;
        run = 0;
        punched = true;
        FrameKind k = code.kind(f);
        if (k == FrameKind::blank) ++s.blank_inside;
        if (k == FrameKind::rubout) ++s.rubouts;
        if (k == FrameKind::parity_error) ++s.parity_errors;
        if (k == FrameKind::not_in_code) ++s.not_in_code;
        if (k != FrameKind::character) continue;
        ++s.data;
        char c = code.character(f);
        if (c == '%') {
            percent = true;
        } else if (c != ' ' && c != '\n' && c != '\r') {
            s.program_starts += percent;
            percent = false;
        }
        if (c == '\n') ++s.end_of_blocks;
    }
    (punched ? s.trailer : s.leader) += run;
    return s;
}

void expect_same_survey(const TapeSurvey& a, const TapeSurvey& b, const std::string& what) {
    EXPECT_EQ(a.frames, b.frames) << what;
    EXPECT_EQ(a.leader, b.leader) << what;
    EXPECT_EQ(a.trailer, b.trailer) << what;
    EXPECT_EQ(a.data, b.data) << what;
    EXPECT_EQ(a.rubouts, b.rubouts) << what;
    EXPECT_EQ(a.blank_inside, b.blank_inside) << what;
    EXPECT_EQ(a.parity_errors, b.parity_errors) << what;
    EXPECT_EQ(a.not_in_code, b.not_in_code) << what;
    EXPECT_EQ(a.program_starts, b.program_starts) << what;
    EXPECT_EQ(a.end_of_blocks, b.end_of_blocks) << what;
    EXPECT_EQ(a.parity.even, b.parity.even) << what;
    EXPECT_EQ(a.parity.mark, b.parity.mark) << what;
    EXPECT_EQ(a.parity.frames, b.parity.frames) << what;
}

// The detector's own counts, a frame at a time.
struct PlainEvidence {
    std::uint64_t punched = 0, significant = 0, five_track = 0, longest_0x80_run = 0, iso_lf = 0, eia_eob = 0,
                  koi7_letters = 0;
};

PlainEvidence plain_evidence(std::span<const Frame> frames) {
    PlainEvidence e;
    FrameCode iso = FrameCode::make(Code::iso, Parity::even);
    std::uint64_t run = 0;
    bool shifted = false;
    for (Frame f : frames) {
        run = f == 0x80 ? run + 1 : 0;
        e.longest_0x80_run = std::max(e.longest_0x80_run, run);
        if (f == blank_frame) continue;
        ++e.punched;
        e.significant += f != 0xFF && f != 0x7F;
        e.five_track += f < 0x20;
        e.iso_lf += f == 0x0A;
        e.eia_eob += f == 0x80;
        if (iso.kind(f) != FrameKind::character) continue;
        char c = static_cast<char>(f & 0x7F);
        if (c == 0x0E || c == 0x0F || c == '\n') shifted = c == 0x0E;
        e.koi7_letters += shifted && c >= 0x40 && c <= 0x7E;
    }
    return e;
}

void expect_same_counts(std::span<const Frame> frames, const std::string& name) {
    const Reading readings[] = {{Code::iso, Parity::even},  {Code::eia, Parity::odd}, {Code::iso, Parity::mark},
                                {Code::iso, Parity::space}, {Code::iso, Parity::odd}, {Code::elliott920, Parity::even}};
    for (std::size_t chunk : {std::size_t{1} << 20, std::size_t{1}, std::size_t{37}, std::size_t{4096}}) {
        Detector d;
        for (std::size_t at = 0; at < frames.size(); at += chunk)
            d.feed(frames.subspan(at, std::min(chunk, frames.size() - at)));
        d.finish();
        std::string what = name + " in pieces of " + std::to_string(chunk);
        for (const Reading& r : readings)
            expect_same_survey(d.survey(r), plain_survey(frames, FrameCode::make(r.code, r.parity)),
                               what + ", " + reading_name(r));
        TapeEvidence e = d.result().evidence;
        PlainEvidence p = plain_evidence(frames);
        EXPECT_EQ(e.punched, p.punched) << what;
        EXPECT_EQ(e.significant, p.significant) << what;
        EXPECT_EQ(e.five_track, p.five_track) << what;
        EXPECT_EQ(e.longest_0x80_run, p.longest_0x80_run) << what;
        EXPECT_EQ(e.iso_lf, p.iso_lf) << what;
        EXPECT_EQ(e.eia_eob, p.eia_eob) << what;
        EXPECT_EQ(e.koi7_letters, p.koi7_letters) << what;
        if (frames.size() > 200000) break;  // a long tape in small pieces says nothing more
    }
}

TEST(SurveyTally, SameCountsAsAFrameAtATimeOnEveryTape) {
    auto tapes = every_tape();
    for (const auto& t : tapes) {
        expect_same_counts(t.frames, t.path);
        if (HasFailure()) break;
    }
    EXPECT_GE(tapes.size(), every_tape_minimum());
}

// Frames of every value, runs of 0x80 and blank tape, '%' before programs and at the end, SO/SI shifts.
TEST(SurveyTally, SameCountsAsAFrameAtATimeOnMadeUpTapes) {
    std::mt19937 random(31);
    const std::vector<Frame> pieces[] = {{0, 0, 0},
                                         {0x80, 0x80, 0x80, 0x80},
                                         {0xA5, 0x0A},
                                         {0xA5, 0xA5, 0x20, 0xCE},
                                         {0x8E, 0x41, 0xC2, 0x0F},
                                         {0xFF, 0x7F},
                                         {0x25, 0x4E},
                                         {0x0B, 0x2A, 0x80}};
    for (int t = 0; t < 300; ++t) {
        std::vector<Frame> frames;
        for (int k = static_cast<int>(random() % 400); k > 0; --k) {
            if (random() % 3 == 0)
                frames.push_back(static_cast<Frame>(random()));
            else
                for (Frame f : pieces[random() % std::size(pieces)]) frames.push_back(f);
        }
        expect_same_counts(frames, "made-up tape " + std::to_string(t));
        if (HasFailure()) break;
    }
}

}  // namespace
