// ГОСТ 20999-83 §9 format notation, and rewriting words for a controller.
#include "tape/format_spec.hpp"

#include <gtest/gtest.h>

#include <random>

#include "tape/error.hpp"
#include "tape/lint.hpp"

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

TEST(FormatSpec, EmptyNotationSaysSo) {
    for (const char* empty : {"", "   ", "\t"}) {
        try {
            parse_format_spec(empty);
            ADD_FAILURE() << "accepted '" << empty << "'";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::usage);
            EXPECT_STREQ(e.what(), "empty format specification");
        }
    }
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
    EXPECT_EQ(fmt("X+043", "X125", false, "X+053"), "X+0000125");    // leading zeros omitted in the source
    EXPECT_EQ(fmt("X+063", "X125", false, "X+530"), "X+012500000");  // trailing zeros omitted in the source
    EXPECT_EQ(fmt("X+530", "X12.5", true), "X+000125");              // trailing zeros left out
}

TEST(FormatWord, ValuesThatDoNotFitAreErrors) {
    for (auto [spec, w] : {std::pair{"X+053", "X123456."},
                           {"X+053", "X1.2345"},
                           {"X53", "X-1."},
                           {"G02", "G1.5"},
                           {"G02", "G123"},
                           {"N03", "X1"}}) {
        try {
            fmt(spec, w);
            ADD_FAILURE() << spec << " accepted " << w;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_text);
        }
    }
}

TEST(FormatWord, NoDigitsBeforeThePoint) {
    // X+05: no digit before the point and five after (§9.2: the first digit counts those before).
    const std::string spec = "DS N03 G02 X+05 M02";
    EXPECT_EQ(fmt(spec, "X.00012"), "X+.00012");
    EXPECT_EQ(fmt(spec, "X-0.5"), "X-.5");
    EXPECT_EQ(fmt(spec, "X0"), "X+.0");
    EXPECT_EQ(fmt("N03 X+05", "X.00012"), "X+00012");
    EXPECT_THROW(fmt(spec, "X12"), Error);  // twelve has no room, rather than becoming 0.00012
    EXPECT_THROW(fmt(spec, "X1.5"), Error);
}

TEST(FormatWord, NoDigitsAfterThePoint) {
    EXPECT_EQ(fmt("DS X+50", "X12"), "X+12.");
    EXPECT_EQ(fmt("X+50", "X12."), "X+00012");
    EXPECT_EQ(fmt("X+500", "X1200.", true), "X+012");
    EXPECT_THROW(fmt("DS X+50", "X12.5"), Error);
}

TEST(FormatWord, MainBlockNumberNeedsColonInTheFormat) {
    Word w = load("%\n:5 G1\nM02\n").programs.at(0).blocks.at(0).number.value();
    EXPECT_EQ(format_word(w, parse_format_spec(": N03 G02"), nullptr, false), ":005");
    EXPECT_THROW(format_word(w, parse_format_spec("N03 G02"), nullptr, false), Error);
}

// Property: whatever format_word writes for a spec is a word lint accepts under that spec, with the
// same value; everything else is an Error(bad_text). Specs and words are random, from a fixed seed.
namespace {

std::string random_spec_text(std::mt19937& rng) {
    auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    std::string s;
    if (pick(2)) s += "% ";
    if (pick(2)) s += ": ";
    if (pick(2)) s += "/ ";
    if (pick(2)) s += "DS ";
    if (pick(4) == 0) s += ". ";
    static constexpr std::string_view addresses = "NGXYZUVWPQRABCIJKFESTMDH";
    for (char a : addresses) {
        if (pick(3) == 0) continue;
        // Random digits until the word alone is valid notation: a whole spec of random words would
        // almost never be.
        for (;;) {
            std::string w(1, a);
            if (pick(3) == 0) w += '+';
            int digits = 1 + pick(3);
            for (int i = 0; i < digits; ++i) w += static_cast<char>('0' + (pick(3) == 0 ? 0 : pick(10)));
            try {
                parse_format_spec(w);
            } catch (const Error&) {
                continue;
            }
            s += w + ' ';
            break;
        }
    }
    if (pick(2)) s += '*';
    return s;
}

FormatSpec random_spec(std::mt19937& rng) {
    for (;;) {
        try {
            return parse_format_spec(random_spec_text(rng));
        } catch (const Error& e) {
            if (e.code() != Errc::usage) throw;  // only "no words" is expected here
        }
    }
}

std::string random_word_text(std::mt19937& rng, const FormatSpec& spec) {
    auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    std::string s;
    int kind = pick(10);
    if (kind == 0)
        s += ':';
    else if (kind == 1)
        s += static_cast<char>('A' + pick(26));
    else
        s += spec.words[static_cast<std::size_t>(pick(static_cast<int>(spec.words.size())))].address;
    if (int sign = pick(3); sign) s += sign == 1 ? '+' : '-';
    int digits = pick(11);
    int point = pick(2) ? pick(digits + 1) : -1;
    for (int i = 0; i < digits; ++i) {
        if (i == point) s += '.';
        s += static_cast<char>('0' + (pick(3) == 0 ? 0 : pick(10)));
    }
    if (point == digits) s += '.';
    if (s.size() == 1) s += '0';  // a bare address is a no-digits finding, not a word to format
    return s;
}

// The one word of a one-block program: its number (N, ':') or its first word.
std::optional<Word> only_word(const LoadedTape& t) {
    if (t.programs.size() != 1 || t.programs[0].blocks.size() != 1) return std::nullopt;
    const Block& b = t.programs[0].blocks[0];
    if (b.number) return b.number;
    if (b.words.size() == 1) return b.words[0];
    return std::nullopt;
}

// The loader's findings but program-end: the one-block programs here have no M02 on purpose, so that
// their only word is the one under test.
std::vector<Finding> syntax_findings(const LoadedTape& t) {
    std::vector<Finding> out;
    for (const Finding& f : t.findings)
        if (f.rule != "program-end") out.push_back(f);
    return out;
}

bool same_value(const DecimalValue& a, const DecimalValue& b) {
    return a.negative == b.negative && a.whole == b.whole && a.fraction == b.fraction;
}

}  // namespace

TEST(FormatWord, WhatFormatWritesLintAcceptsWithTheSameValue) {
    std::mt19937 rng(20999);
    int formatted = 0, refused = 0;
    for (int i = 0; i < 20000; ++i) {
        std::optional<FormatSpec> spec = random_spec(rng);
        std::optional<FormatSpec> from;
        if (rng() % 3 == 0) from = random_spec(rng);
        bool strip = rng() % 2;
        std::string input = random_word_text(rng, *spec);
        LoadedTape in = load("%\n" + input + "\n");
        std::optional<Word> w = only_word(in);
        if (!w || !syntax_findings(in).empty()) continue;
        std::string context = "spec '" + spec->text + "', from '" + (from ? from->text : "") + "', word " + input +
                              (strip ? ", strip zeros" : "");
        std::string out;
        try {
            out = format_word(*w, *spec, from ? &*from : nullptr, strip);
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::bad_text) << context;
            ++refused;
            continue;
        }
        ++formatted;
        LoadedTape t = load("%\n" + out + "\n");
        std::vector<Finding> syntax = syntax_findings(t);
        EXPECT_TRUE(syntax.empty()) << context << " wrote " << out
                                    << ", which has a syntax finding: " << (syntax.empty() ? "" : syntax[0].message);
        for (const Finding& f : lint(t, LintOptions{&*spec}))
            EXPECT_NE(f.rule.substr(0, 5), "spec-")
                << context << " wrote " << out << ": " << f.rule << ": " << f.message;
        std::optional<Word> back = only_word(t);
        ASSERT_TRUE(back) << context << " wrote " << out;
        const WordFormat* target = spec->find(w->address);
        DecimalValue before = word_value(*w, from ? from->find(w->address) : nullptr);
        DecimalValue after = word_value(*back, target);
        EXPECT_TRUE(same_value(before, after))
            << context << " wrote " << out << ": value changed from " << (before.negative ? "-" : "") << before.whole
            << "." << before.fraction << " to " << (after.negative ? "-" : "") << after.whole << "." << after.fraction;
    }
    // Both outcomes must be common, or the property says little.
    EXPECT_GT(formatted, 4000);
    EXPECT_GT(refused, 2000);
}
