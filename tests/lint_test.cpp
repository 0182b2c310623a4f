// One test per lint rule, each with a program that breaks it and one that does not.
#include "tape/lint.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "tape/code_tables.hpp"
#include "tape/decode.hpp"
#include "tape/encode.hpp"

using namespace tape;

namespace {
std::size_t count(std::string_view text, std::string_view rule, const FormatSpec* spec = nullptr,
                  Dialect dialect = Dialect::gost) {
    auto findings = lint(load(std::string(text), {}, LoadOptions{dialect}), LintOptions{spec});
    return static_cast<std::size_t>(
        std::count_if(findings.begin(), findings.end(), [&](const Finding& f) { return f.rule == rule; }));
}
std::size_t count_in(Dialect dialect, std::string_view text, std::string_view rule) {
    return count(text, rule, nullptr, dialect);
}
}  // namespace

TEST(Lint, NoProgram) {
    EXPECT_EQ(count("N1 G01 X1\n", "no-program"), 1U);
    EXPECT_EQ(count("%\nN1 M02\n", "no-program"), 0U);
}

TEST(Lint, ProgramStart) {
    EXPECT_EQ(count("%\n", "program-start"), 1U);             // no block after '%'
    EXPECT_EQ(count("%X-1\nN1 M02\n", "program-start"), 1U);  // not a number
    EXPECT_EQ(count("%1\nN1 M02\n", "program-start"), 0U);
}

TEST(Lint, ProgramEnd) {
    EXPECT_EQ(count("%\nN1 G01 X1\n", "program-end"), 1U);
    EXPECT_EQ(count("%\nN1 G01 X1\nN2 M30\n", "program-end"), 0U);
}

TEST(Lint, AfterEnd) {
    EXPECT_EQ(count("%\nN1 M30\nN2 X1\n", "after-end"), 1U);
    EXPECT_EQ(count("%\nN1 M30\n\n", "after-end"), 0U);
}

TEST(Lint, RepeatedDimension) {
    EXPECT_EQ(count("%\nN1 X1 Y2 X3\nM02\n", "repeated-dimension"), 1U);
    EXPECT_EQ(count("%\nN1 I1 J2 I3\nM02\n", "repeated-dimension"), 1U);
    EXPECT_EQ(count("%\nN1 X1 Y2 Z3 I1 J1\nM02\n", "repeated-dimension"), 0U);
    EXPECT_EQ(count("%\nN1 M03 M08\nM02\n", "repeated-dimension"), 0U);  // M words may repeat
}

TEST(Lint, GGroup) {
    EXPECT_EQ(count("%\nN1 G00 G01 X1\nM02\n", "g-group"), 1U);  // group a
    EXPECT_EQ(count("%\nN1 G17 G18\nM02\n", "g-group"), 1U);     // group c
    EXPECT_EQ(count("%\nN1 G90 G91\nM02\n", "g-group"), 1U);     // group j
    EXPECT_EQ(count("%\nN1 G01 G17 G90 G94\nM02\n", "g-group"), 0U);
}

TEST(Lint, WordOrder) {
    EXPECT_EQ(count("%\nN1 X1 G01\nM02\n", "word-order"), 1U);
    EXPECT_EQ(count("%\nN1 G01 Y1 X1\nM02\n", "word-order"), 1U);
    EXPECT_EQ(count("%\nN1 M03 S100\nM02\n", "word-order"), 1U);
    EXPECT_EQ(count("%\nN1 G01 X1 Y2 Z3 I1 F100 S200 T1 M03\nM02\n", "word-order"), 0U);
    EXPECT_EQ(count("%\nN1 G01 X1 F100 Z2\nM02\n", "word-order"), 0U);  // a feed for the X axis alone (§2.2)
}

TEST(Lint, SignNotAllowed) {
    EXPECT_EQ(count("%\nN1 G01 F-100\nM02\n", "sign-not-allowed"), 1U);
    EXPECT_EQ(count("%\nN1 G01 X-100 I+5\nM02\n", "sign-not-allowed"), 0U);
}

TEST(Lint, BlockNumberOrder) {
    EXPECT_EQ(count("%\nN5 X1\nN3 X2\nN3 M02\n", "block-number-order"), 2U);
    EXPECT_EQ(count("%\nN1 X1\n:2 X2\nN10 M02\n", "block-number-order"), 0U);
}

TEST(Lint, SyntaxFindingsAreIncludedAndSorted) {
    auto findings = lint(load("%\nN1 X Y2\nM02\n"));
    ASSERT_EQ(findings.size(), 1U);
    EXPECT_EQ(findings[0].rule, "no-digits");
    auto two = lint(load("%\nN1 X1 X2 #\nM02\n"));
    ASSERT_EQ(two.size(), 2U);
    EXPECT_LT(*two[0].where.byte, *two[1].where.byte);
}

TEST(LintSpec, EveryWordAgainstTheFormat) {
    FormatSpec spec = parse_format_spec("% : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*");
    EXPECT_EQ(count("%\n:001 G90 X+12.5 F120.5 S1250 T0101 M03\nN2 M02\n", "spec-digits", &spec), 0U);
    EXPECT_EQ(count("%\nN1 X123456.5\nM02\n", "spec-digits", &spec), 1U);  // 6 digits before the point
    EXPECT_EQ(count("%\nN1 X1.2345\nM02\n", "spec-digits", &spec), 1U);    // 4 after
    EXPECT_EQ(count("%\nN1 S12345\nM02\n", "spec-digits", &spec), 1U);
    EXPECT_EQ(count("%\nN1 H12\nM02\n", "spec-address", &spec), 1U);
    EXPECT_EQ(count("%\nN1 S-12\nM02\n", "spec-sign", &spec), 1U);
    EXPECT_EQ(count("%\nN1 G1.5\nM02\n", "spec-point", &spec), 1U);
    FormatSpec plain = parse_format_spec("N03 G02 X+53 F031 M02");
    EXPECT_EQ(count("%\nN001 X+1.5\nN002 M02\n", "spec-point", &plain), 1U);
    EXPECT_EQ(count("%\nN001 X+12345\nN002 M02\n", "spec-digits", &plain), 1U);  // needs exactly 8
    EXPECT_EQ(count("%\nN001 X+00012500\nN002 M02\n", "spec-digits", &plain), 0U);
    EXPECT_EQ(count("%\n:001 X+00012500\nN002 M02\n", "spec-main", &plain), 1U);
    EXPECT_EQ(count("%\n/N001 X+00012500\nN002 M02\n", "spec-skip", &plain), 1U);
    EXPECT_EQ(count("%\nN1 M02\n", "spec-digits", &plain), 0U);  // N03: up to three digits, leading zeros omitted
    FormatSpec strict = parse_format_spec("N3 G2 X+53 M2");
    EXPECT_EQ(count("%\nN1 M02\n", "spec-digits", &strict), 1U);  // N3: exactly three digits
    EXPECT_EQ(count("%\nN001 M02\n", "spec-digits", &strict), 0U);
}

TEST(CodeTables, ValuesAreComparedWithoutLeadingZerosAndTrailingFractionZeros) {
    EXPECT_EQ(code_value("01"), "1");
    EXPECT_EQ(code_value("000"), "0");
    EXPECT_EQ(code_value("012.10"), "12.1");
    EXPECT_EQ(code_value("1.0"), "1");
    EXPECT_EQ(code_value("38.2"), "38.2");
    EXPECT_EQ(code_value("#1"), "");
    EXPECT_EQ(code_value("1.2.3"), "");
}

TEST(CodeTables, GostKnowsTwoDigitCodesAndTheAcknowledgedThreeDigitM) {
    EXPECT_TRUE(code_known(Dialect::gost, 'G', "1"));
    EXPECT_TRUE(code_known(Dialect::gost, 'G', "12"));  // undefined: the controller's to use (note 1)
    EXPECT_FALSE(code_known(Dialect::gost, 'G', "890"));
    EXPECT_FALSE(code_known(Dialect::gost, 'G', "12.1"));
    EXPECT_TRUE(code_known(Dialect::gost, 'M', "102"));  // M02 after the machine's acknowledgement
    EXPECT_FALSE(code_known(Dialect::gost, 'M', "930"));
    EXPECT_TRUE(code_known(Dialect::gost, 'X', "930"));  // only G and M have tables
}

TEST(CodeTables, FanucKnowsLatheMillAndDecimalCodes) {
    for (const char* g : {"12.1", "13.1", "5.1", "50", "71", "76", "84.2", "112", "154"})
        EXPECT_TRUE(code_known(Dialect::fanuc, 'G', g)) << "G" << g;
    for (const char* g : {"38.2", "33.1", "890", "64.1"}) EXPECT_FALSE(code_known(Dialect::fanuc, 'G', g)) << "G" << g;
    EXPECT_TRUE(code_known(Dialect::fanuc, 'M', "930"));  // the machine builder's
    EXPECT_FALSE(code_known(Dialect::fanuc, 'M', "1234"));
    EXPECT_EQ(code_meanings(Dialect::fanuc, 'G', "90").size(), 2U);  // a lathe cycle, a mill's absolute mode
}

TEST(CodeTables, LinuxcncKnowsItsReferenceAndTheUsersMCodes) {
    for (const char* g : {"38.2", "33.1", "64", "5.2", "7", "90.1", "92.3", "59.3"})
        EXPECT_TRUE(code_known(Dialect::linuxcnc, 'G', g)) << "G" << g;
    EXPECT_FALSE(code_known(Dialect::linuxcnc, 'G', "12.1"));
    for (const char* m : {"62", "68", "100", "199"}) EXPECT_TRUE(code_known(Dialect::linuxcnc, 'M', m)) << "M" << m;
    EXPECT_FALSE(code_known(Dialect::linuxcnc, 'M', "200"));
    EXPECT_FALSE(code_known(Dialect::linuxcnc, 'M', "13"));
}

TEST(Lint, UnknownCode) {
    EXPECT_EQ(count("%\nN1 G890 X1\nN2 M930\nN3 M02\n", "unknown-code"), 2U);
    EXPECT_EQ(count("%\nN1 G01 X1 F100\nN2 M102\n", "unknown-code"), 0U);
    EXPECT_EQ(count("%\nN1 G01 X1 F100\nN2 M102\n", "program-end"), 0U);  // M102 is M02, acknowledged
    EXPECT_EQ(count_in(Dialect::fanuc, "O1\nG12.1\nG38.2 Z-5\nM30\n", "unknown-code"), 1U);
    EXPECT_EQ(count_in(Dialect::linuxcnc, "G38.2 Z-5 F10\nG12.1\nM2\n", "unknown-code"), 1U);
    // The letters of a macro call are its arguments: M0.070 is #13, not an M code.
    EXPECT_EQ(count_in(Dialect::fanuc, "O1\nG65 P9010 X1. M0.070\nM30\n", "unknown-code"), 0U);
    EXPECT_EQ(count_in(Dialect::fanuc, "O1\nG#1 M#2\nM30\n", "unknown-code"), 0U);  // macro values
}

// A code's verdict is kept by its value (G1 as G01, G890 as G0890; M930 apart from G930), and past 999
// by the text as written: each use reported, none carried to another code.
TEST(Lint, UnknownCodeAskedOnceAndEachUseReported) {
    EXPECT_EQ(count("%\nN1 G890 X1\nN2 G0890 X2\nN3 G01 X3 F100\nN4 G1 X4\nN5 M02\n", "unknown-code"), 2U);
    EXPECT_EQ(count("%\nN1 G04 X1\nN2 M04\nN3 M930\nN4 G930\nN5 M02\n", "unknown-code"), 2U);
    EXPECT_EQ(count("%\nN1 G1234 X1\nN2 G1234 X2\nN3 G01234 X3\nN4 M02\n", "unknown-code"), 3U);
    // The verdicts are of the dialect read: a Fanuc code is known to Fanuc, not to ГОСТ.
    EXPECT_EQ(count_in(Dialect::fanuc, "O1\nG54.1 P1\nG10 L2 P1 X0\nM30\n", "unknown-code"), 0U);
    EXPECT_EQ(count("%\nN1 G10 X0\nN2 M02\n", "unknown-code"), count("%\nN1 G010 X0\nN2 M02\n", "unknown-code"));
}

namespace {
std::vector<Finding> lint_as(Dialect dialect, std::string_view text, LintOptions options = {}) {
    return lint(load(std::string(text), {}, LoadOptions{dialect}), options);
}
}  // namespace

// Of each rule the first findings by position are listed, however late a finding came: an unclosed
// DO is found at the program's end, after the END that closes no DO further down.
TEST(Lint, MaxPerRuleKeepsTheFirstByPosition) {
    std::string text = "O1\nWHILE [#1 LT 2] DO1\nG0 X1\nEND2\nM30\n";
    LintVisitor v(LintOptions{nullptr, 1});
    load_each(text, {}, v, LoadOptions{Dialect::fanuc});
    auto findings = v.findings();
    ASSERT_EQ(findings.size(), 1U);
    EXPECT_EQ(findings[0].where.line, 2U);  // the DO, not the END 2 that arrived first
    EXPECT_EQ(v.unlisted().at("control-flow"), 1U);
    EXPECT_EQ(v.count(Severity::error), 2U);
}

TEST(Lint, GrblConsoleLineIsOneWarning) {
    auto findings = lint_as(Dialect::linuxcnc, "$I  ; View build info\n?\nG0 X1\nM2\n");
    ASSERT_EQ(findings.size(), 2U);
    for (const auto& f : findings) {
        EXPECT_EQ(f.rule, "console-command");
        EXPECT_EQ(f.severity, Severity::warning);
    }
}

TEST(Lint, LinuxcncPolarWords) {
    EXPECT_TRUE(lint_as(Dialect::linuxcnc, "G0 @1.5 ^0 Z0\nG91 G81 R.1 Z-.5 ^60 L6 F10\nM2\n").empty());
}

// A subroutine file (o<name> sub ... endsub, called by name) needs no M2, and moves at its caller's feed.
TEST(Lint, LinuxcncSubroutineFile) {
    auto findings = lint_as(Dialect::linuxcnc, "o<pocket> sub\n  G1 X1 Y1\n  G3 X2 Y2 R1\no<pocket> endsub\n");
    EXPECT_TRUE(findings.empty()) << findings.front().rule << ": " << findings.front().message;
    EXPECT_EQ(count_in(Dialect::linuxcnc, "G1 X1 Y1\n", "program-end"), 1U);
}

// A subprogram (it ends with M99) moves at its caller's feed; a main program does not.
TEST(Lint, FanucSubprogramRunsAtTheCallersFeed) {
    EXPECT_EQ(count_in(Dialect::fanuc, "O100\nG1 X10\nM99\n", "no-feed"), 0U);
    EXPECT_EQ(count_in(Dialect::fanuc, "O100\nG1 X10\nM30\n", "no-feed"), 1U);
}

TEST(Lint, FanucAlarmInTheLastBlockEndsTheProgram) {
    EXPECT_EQ(
        count_in(Dialect::fanuc, "%\nO9000\nIF[#890 NE 1] GOTO2\nM30\nN2\n#3000=15 (CYCLE START)\n%\n", "program-end"),
        0U);
    EXPECT_EQ(count_in(Dialect::fanuc, "%\nO9000\n#3000=15 (ALARM)\nG0 X1\n%\n", "program-end"), 1U);
}

// Haas: M97 P15 calls the block N15 after M30, up to its M99; those blocks are linted, not after-end.
TEST(Lint, HaasLocalSubprogramsAfterM30) {
    std::string text = "%\nO10\nG0 X0 Y0\nM97 P15\nM30\nN15 G1 Z-1 F100\nG2 X1 Y1\nM99\n%\n";
    EXPECT_EQ(count_in(Dialect::fanuc, text, "arc-center"), 1U);
    EXPECT_EQ(count_in(Dialect::fanuc, text, "after-end"), 0U);
    EXPECT_EQ(count_in(Dialect::fanuc, "%\nO10\nG0 X0\nM30\nN15 G2 X1 Y1\nM99\n%\n", "after-end"), 1U);
}

TEST(Lint, FanucProgramNumberOnThePercentLine) {
    auto t = load("%O1200(TOKARKA)\nN10 G0 X1\nN20 G2 X2 Z1 R5 F.2\nN30 M30\n%\n", {}, LoadOptions{Dialect::fanuc});
    ASSERT_EQ(t.programs.size(), 1U);
    EXPECT_EQ(t.programs[0].number, "O1200");
    EXPECT_TRUE(lint(t).empty());
}

// A program of a control no dialect here reads: only what holds for every control is checked.
TEST(Lint, NoDialectChecksOnlyWhatHoldsForEveryControl) {
    std::string okuma = "$PART.MIN%\nPRES=1 (CHUCK)\nIF[PRES EQ 1]NM59\nNM59 M59\nG0 X=FLAN+5 Z=SPFA+10\nM02\n";
    EXPECT_TRUE(lint_as(Dialect::none, okuma).empty());
    auto bad = lint_as(Dialect::none, "G1 Х10 (CYRILLIC X) (OPEN\n" + okuma);
    ASSERT_EQ(bad.size(), 2U);
    EXPECT_EQ(bad[0].rule, "unexpected-character");
    EXPECT_EQ(bad[1].rule, "unclosed-comment");
}

// Two dialects close: the text is read in the first, and only what both readings find is reported.
// The sample (64 KiB) decides; what only one reading refuses comes after it here.
TEST(Lint, CloseDialectsReportWhatBothFind) {
    std::string text = "G21 G64 P0.02\nG0 X0 Y0\nM98 P100\n";
    for (int n = 0; text.size() < (80 << 10); ++n) text += "G1 X" + std::to_string(n % 100) + " F100\n";
    text += "G12.1\nG38.2 Z-5 F10\no100 sub\no100 endsub\nG1 X1 X2 F100\nM30\n";
    LintVisitor v;
    ProgramLoader loader(v, LoadOptions{Dialect::automatic});
    loader.feed(text);
    loader.finish();
    ASSERT_TRUE(v.close());
    EXPECT_NE(*v.close(), v.dialect());
    std::vector<std::string_view> rules;
    for (const auto& f : v.findings()) rules.push_back(f.rule);
    // G12.1 is Fanuc's, G38.2 LinuxCNC's, the o-words LinuxCNC's: none is reported; X twice is.
    EXPECT_EQ(rules, std::vector<std::string_view>{"repeated-dimension"});
}

// Blank tape inside a block: a warning at its frame, an error with strict; blank tape between blocks
// is silent.
TEST(Lint, BlankFrameInsideABlock) {
    auto frames = encode("%\nN1 G01 Z-1 F100\nN2 M02\n", {});
    std::size_t minus = 0;
    for (std::size_t i = 0; i < frames.size(); ++i)
        if (frames[i] == 0x2D) minus = i;
    ASSERT_NE(minus, 0U);
    frames[minus] = 0x00;  // the '-' lost its holes: Z-1 reads Z1
    frames.insert(frames.begin() + static_cast<std::ptrdiff_t>(minus) + 8, 0x00);  // blank after N1's LF: silent
    auto r = decode(frames, DecodeOptions{.positions = true});
    ASSERT_EQ(r.diagnostics.size(), 1U);
    EXPECT_EQ(r.diagnostics[0].code, Errc::blank_frame);
    EXPECT_EQ(r.diagnostics[0].where.frame, minus + 1);
    LoadedTape t = load(r.text, r.frame_of);
    t.findings.insert(t.findings.begin(), r.diagnostics.begin(), r.diagnostics.end());
    auto warned = lint(t);
    ASSERT_EQ(warned.size(), 1U);
    EXPECT_EQ(warned[0].severity, Severity::warning);
    auto strict = lint(t, LintOptions{.strict = true});
    ASSERT_EQ(strict.size(), 1U);
    EXPECT_EQ(strict[0].severity, Severity::error);
}
