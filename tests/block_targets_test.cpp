// The blocks a Fanuc or Haas program names by number (issue 31, item 8): the P and Q of the lathe
// cycles G70-G73, Haas's M97 P, GOTO; a target missing, a target whose number stands twice; and what
// is not decidable left alone (M98 P names a program, M99 P the caller's block, the mill's G73).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "tape/lint.hpp"
#include "tape/rules.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

// rule and line of every finding of the text read as Fanuc.
std::vector<std::pair<std::string, std::uint64_t>> found(const std::string& text, Dialect d = Dialect::fanuc) {
    std::vector<std::pair<std::string, std::uint64_t>> out;
    for (const auto& f : lint(load(text, {}, LoadOptions{d}))) out.emplace_back(f.rule, f.where.line.value_or(0));
    return out;
}

using Found = std::vector<std::pair<std::string, std::uint64_t>>;

}  // namespace

TEST(BlockTargets, TheRulesAreListed) {
    for (std::string_view id : {"block-target", "duplicate-target", "goto-target"}) {
        const Rule* r = find_rule(id);
        ASSERT_NE(r, nullptr) << id;
        EXPECT_TRUE(rule_applies(*r, Dialect::fanuc)) << id;
        EXPECT_FALSE(rule_applies(*r, Dialect::linuxcnc)) << id;  // LinuxCNC's G70-G72 name o-word subroutines
    }
}

// The shape of cade_O58215.nc: G71 P45 Q58 with no N58, and N45 three times.
TEST(BlockTargets, ACycleToAMissingBlockAndARepeatedOne) {
    const std::string text =
        "%\nO58215\nG00 X2.\nG71 P45 Q58 U0.01 W0.005 D0.025 F0.01\nN45 G00 X0.0 Z0.0\nG01 X1.5 Z0.0\n"
        "G71 P45 Q55 U0.01 W0.005 D0.025 F0.01\nN45 G00 X0.0 Z0.0\nN45 G00 X0.0 Z0.0\nG01 X0.0 Z-2.0\n"
        "N55 G01 X1.8 Z-2.0\nG70 P45 Q55\nM30\n%\n";
    EXPECT_EQ(found(text), (Found{{"block-target", 4}, {"duplicate-target", 8}}));
    auto findings = lint(load(text, {}, LoadOptions{Dialect::fanuc}));
    ASSERT_EQ(findings.size(), 2U);
    EXPECT_EQ(findings[0].message,
              "G71 Q58 names block N58, which this program does not have: the cycle's profile runs from its P block "
              "to its Q block, and the control stops with an alarm");
    EXPECT_EQ(findings[1].message,
              "N45 stands 3 times in this program (lines 5, 8, 9) and G71 P45 (line 4) names it: the control goes to "
              "the one it finds first, which may not be the one meant");
}

TEST(BlockTargets, CyclesWhoseBlocksAreThereAreClean) {
    EXPECT_TRUE(found("%\nO1\nG71 U1. R0.5\nG71 P10 Q20 U0.2 W0.1 F0.3\nN10 G00 X20.\nN20 G01 Z-30.\n"
                      "G70 P10 Q20\nM30\n%\n")
                    .empty());
    // The mill's G73 is peck drilling: its Q is the peck, and it names no block.
    EXPECT_TRUE(found("%\nO2\nG90 G00 X0 Y0\nG73 X10. Y10. Z-5. R1. Q2. P3 F100.\nG80\nM30\n%\n").empty());
}

// Haas's M97 P calls a block of the same program, after its M30 as Haas programs put them.
TEST(BlockTargets, HaasLocalSubprogramCalls) {
    const std::string called = "%\nO10\nM97 P15\nM97 P15\nM30\nN15 G81 Z-1. R1. F50.\nG80\nM99\n%\n";
    EXPECT_TRUE(found(called).empty());
    EXPECT_EQ(found("%\nO10\nM97 P16\nM30\nN15 G81 Z-1. R1. F50.\nG80\nM99\n%\n"), (Found{{"block-target", 3}}));
}

// M98 P names a program (in another file, or in the control's memory), M99 P a block of the caller:
// neither is decidable from the program, so neither is said.
TEST(BlockTargets, ProgramCallsAndReturnsAreNotChecked) {
    EXPECT_TRUE(found("%\nO1\nM98 P5001 L3\nM98 P9004\nM30\n%\n").empty());
    EXPECT_TRUE(found("%\nO9001\nG91 G01 X1. F100.\nM99 P40\n%\n").empty());
}

TEST(BlockTargets, GotoToARepeatedBlock) {
    EXPECT_EQ(found("%\nO1\n#1=0\nN10 #1=#1+1\nIF [#1 LT 3] GOTO 10\nN10 G00 X0\nGOTO 99\nM30\n%\n"),
              (Found{{"duplicate-target", 6}, {"goto-target", 7}}));
}

// Each program has its own numbers: the same N in two programs is no repeat.
TEST(BlockTargets, NumbersArePerProgram) {
    EXPECT_TRUE(found("%\nO1\nG70 P10 Q20\nN10 G00 X1.\nN20 G01 Z-1. F.1\nM30\nO2\nG70 P10 Q20\nN10 G00 X1.\n"
                      "N20 G01 Z-1. F.1\nM30\n%\n")
                    .empty());
}

TEST(BlockTargets, RealSnowmanLathe) {
    SKIP_WITHOUT_SHARED_DATA("outside3/haas/cade_O58215.nc");
    auto t = load(read_text(shared_data("outside3/haas/cade_O58215.nc")), {}, LoadOptions{Dialect::automatic});
    EXPECT_EQ(t.dialect, Dialect::fanuc) << t.dialect_reason;
    Found f;
    for (const auto& x : lint(t)) f.emplace_back(x.rule, x.where.line.value_or(0));
    EXPECT_EQ(f, (Found{{"block-target", 15}, {"duplicate-target", 25}}));
}

// The other Haas lathe programs name their blocks rightly: no false alarm.
TEST(BlockTargets, RealLatheProgramsAreClean) {
    SKIP_WITHOUT_SHARED_DATA("outside3/haas/cade_O58214.nc");
    for (std::string path :
         {"outside3/haas/cade_O58214.nc", "outside3/haas/cade_lathe-l5.nc", "outside3/haas/cade_Lathe-L8-Ex1.nc",
          "outside3/haas/enier_weld_pin.nc", "outside3/haas/enier_lathe_hp_2.nc",
          "outside2/haas/boreyko_otverstie_O00010.nc", "outside2/haas/boreyko_graver_O00001.nc"}) {
        if (!std::filesystem::exists(shared_data(path))) continue;  // each judged where it is present
        auto t = load(read_text(shared_data(path)), {}, LoadOptions{Dialect::automatic});
        for (const auto& x : lint(t)) {
            EXPECT_NE(x.rule, "block-target") << path << ": " << x.message;
            EXPECT_NE(x.rule, "duplicate-target") << path << ": " << x.message;
        }
    }
}
