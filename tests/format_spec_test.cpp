// ГОСТ 20999-83 §9 format notation, and rewriting words for a controller.
#include <gtest/gtest.h>

#include "tape/error.hpp"
#include "tape/format_spec.hpp"

using namespace tape;

namespace {
Word word(const std::string& text) { return load("%\nN1 " + text + "\nM02\n").programs.at(0).blocks.at(0).words.at(0); }
std::string fmt(const std::string& spec, const std::string& w, bool strip = false, const std::string& from = "") {
    FormatSpec s = parse_format_spec(spec);
    std::optional<FormatSpec> f;
    if (!from.empty()) f = parse_format_spec(from);
    return format_word(word(w), s, f ? &*f : nullptr, strip);
}
}  // namespace

TEST(FormatSpec, TheStandardsExample) {
    FormatSpec s = parse_format_spec("% : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*");
    EXPECT_TRUE(s.program_start && s.main_block && s.block_skip && s.explicit_point);
    ASSERT_EQ(s.words.size(), 9U);
    const WordFormat* x = s.find('X');
    EXPECT_TRUE(x->sign && x->dimension && x->omit_leading && !x->omit_trailing);
    EXPECT_EQ(x->before, 5);
    EXPECT_EQ(x->after, 3);
    const WordFormat* f = s.find('F');
    EXPECT_TRUE(f->dimension && f->omit_leading);
    EXPECT_EQ(f->before, 3);
    EXPECT_EQ(f->after, 1);
    const WordFormat* n = s.find(':');
    EXPECT_EQ(n->address, 'N');
    EXPECT_FALSE(n->dimension);
    EXPECT_EQ(n->before, 3);
    EXPECT_TRUE(n->omit_leading);
    EXPECT_EQ(s.find('S')->before, 4);
}

TEST(FormatSpec, SpacesAndTrailingZeroForms) {
    FormatSpec s = parse_format_spec("N03G02X+530 Y42 M2");
    EXPECT_TRUE(s.find('X')->omit_trailing);
    EXPECT_FALSE(s.find('Y')->sign);
    EXPECT_FALSE(s.find('M')->omit_leading);
}

TEST(FormatSpec, MalformedNotationIsAUsageError) {
    for (const char* bad : {"", "X+5", "N03 X+123", "N03 Q", "N03 N04", "N03 * G02", "N03 @"}) {
        try {
            parse_format_spec(bad);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::usage) << bad;
        }
    }
}

TEST(FormatWord, TheIssuesExample) {
    const std::string spec = "N03 G02 X+053 Y+053 F031 M02";
    EXPECT_EQ(fmt(spec, "X12.5"), "X+00012500");
    EXPECT_EQ(fmt(spec, "X12.5", true), "X+12500");
    EXPECT_EQ(fmt(spec, "Y-3."), "Y-00003000");
    EXPECT_EQ(fmt(spec, "G1"), "G01");
    EXPECT_EQ(fmt(spec, "F100."), "F1000");
    EXPECT_EQ(fmt(spec, "F100"), "F1000");  // whole number
}

TEST(FormatWord, ExplicitPointOutputWithDs) {
    const std::string spec = "DS N03 G02 X+053 F031";
    EXPECT_EQ(fmt(spec, "X12.50"), "X+12.5");
    EXPECT_EQ(fmt(spec, "X-0.030"), "X-0.03");
    EXPECT_EQ(fmt(spec, "X7"), "X+7.");
}

TEST(FormatWord, ImpliedPointInputWithFrom) {
    // 16К20Ф3С5 style input: X+0000000 is 5.2 (seven digits) on the source controller.
    EXPECT_EQ(fmt("DS X+053", "X-0040000", false, "X+052"), "X-400.");
    EXPECT_EQ(fmt("X+053", "X-0040000", false, "X+052"), "X-00400000");
    EXPECT_EQ(fmt("X+043", "X125", false, "X+053"), "X+0000125");   // leading zeros omitted in the source
    EXPECT_EQ(fmt("X+063", "X125", false, "X+530"), "X+012500000"); // trailing zeros omitted in the source
    EXPECT_EQ(fmt("X+530", "X12.5", true), "X+000125");              // trailing zeros left out
}

TEST(FormatWord, ValuesThatDoNotFitAreErrors) {
    for (auto [spec, w] : {std::pair{"X+053", "X123456."}, {"X+053", "X1.2345"}, {"X53", "X-1."}, {"G02", "G1.5"},
                          {"G02", "G123"}, {"N03", "X1"}}) {
        try {
            fmt(spec, w);
            ADD_FAILURE() << spec << " accepted " << w;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_text);
        }
    }
}
