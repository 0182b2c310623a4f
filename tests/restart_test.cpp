// Restart after a tool break: the modal state rebuilt at a block, and the refusals where it cannot be.
#include "tape/restart.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "tape/error.hpp"
#include "test_util.hpp"

namespace {

std::string refusal(const std::string& text, const std::string& block) {
    try {
        tape::plan_restart(text, block);
    } catch (const tape::Error& e) {
        EXPECT_EQ(e.code(), tape::Errc::usage);
        return e.what();
    }
    return "";
}

TEST(Restart, ModalStateRebuiltAsBlocks) {
    const std::string text =
        "%\nO1000 (POCKET)\nN10 G20 G18 G91 G95 G55\nN20 G21 G17 G90 G94 G54\nN30 T3 M06\nN40 G97 S2500 M04\n"
        "N45 M07 M08\nN50 G43 H3 G00 X-10. Y0 Z5.\nN60 G41 D13 G01 X0 F300.\nN70 G02 X10. Y10. R10.\nN75 G40 G01 X12.\n"
        "N80 X20. M09\nN90 M30\n%\n";
    tape::RestartPlan p = tape::plan_restart(text, "N80");
    EXPECT_EQ(p.start, "%\nO1000 (POCKET)\n");
    EXPECT_EQ(p.marker, "(RESTART AT N80)");
    EXPECT_EQ(p.modal, (std::vector<std::string>{"G21 G17 G90 G94 G54", "T3 M06", "G97 S2500 M04", "M07 M08", "G43 H3",
                                                 "G40", "G01 F300."}));
    // Then the tool to where N80 starts (it never went below the height N50 took it to) and G01 again.
    EXPECT_EQ(p.approach, (std::vector<std::string>{"G90 G00 Z5.", "G00 X12. Y10.", "G01 F300."}));
    EXPECT_EQ(p.rest, "N80 X20. M09\nN90 M30\n%\n");
    EXPECT_EQ(p.line, 12u);
    EXPECT_EQ(p.text(), p.header() + p.rest);
}

TEST(Restart, GostProgramWithItsOwnGroups) {
    const std::string text =
        "%\nN001 G71 G17 G90\nN002 T01 S800 M13\nN003 G00 X10. Y10. Z5.\nN004 G01 X20 F150\nN005 M02\n";
    tape::RestartPlan p = tape::plan_restart(text, "N004", tape::Dialect::gost);
    EXPECT_EQ(p.modal, (std::vector<std::string>{"G71 G17 G90", "T01", "S800 M03", "M08", "G00"}));
    EXPECT_EQ(p.approach, (std::vector<std::string>{"G90 G00 Z5.", "G00 X10. Y10.", "G00"}));
    EXPECT_EQ(p.block, "N004");
}

TEST(Restart, MacroAssignmentsCarriedInOrder) {
    const std::string text = "%\nO1\n#1=5.\n#2=[#1*2]\nN10 G90 G00 X0 Y0 Z5.\nN20 G01 Y#2 F100.\nN30 M30\n%\n";
    tape::RestartPlan p = tape::plan_restart(text, "N20");
    ASSERT_GE(p.modal.size(), 2u);
    EXPECT_EQ(p.modal[0], "#1=5.");
    EXPECT_EQ(p.modal[1], "#2=[#1*2]");
}

TEST(Restart, RefusedInsideAMacroLoop) {
    std::string why = refusal("%\nO1\n#1=0\nWHILE [#1 LT 5] DO1\nN50 G01 X#1 F100.\n#1=#1+1\nEND1\nM30\n%\n", "N50");
    EXPECT_NE(why.find("inside a macro loop"), std::string::npos) << why;
    EXPECT_NE(why.find("line 5"), std::string::npos) << why;
}

TEST(Restart, RefusedAfterASubprogramCall) {
    std::string why = refusal("%\nO1\nN10 G90 G54\nN20 M98 P2000\nN50 G01 X1 F100.\nM30\n%\n", "N50");
    EXPECT_NE(why.find("subprogram call (M98)"), std::string::npos) << why;
    why = refusal("%\nO1\nN10 G65 P9010 A1.\nN50 G01 X1 F100.\nM30\n%\n", "N50");
    EXPECT_NE(why.find("macro call (G65)"), std::string::npos) << why;
}

TEST(Restart, RefusedWhereTheBlockOccursTwice) {
    std::string why = refusal("%\nO1\nN50 G00 X1\nN60 X2\nN50 X3\nM30\n%\n", "N50");
    EXPECT_NE(why.find("N50 occurs twice (line 3 and line 5)"), std::string::npos) << why;
}

TEST(Restart, RefusedWithReasons) {
    EXPECT_NE(refusal("%\nO1\nN10 G00 X1\nM30\n%\n", "N50").find("no block N50"), std::string::npos);
    EXPECT_NE(refusal("%\nO1\nN10 G00 X1\nM30\n%\n", "N5x").find("no block number"), std::string::npos);
    EXPECT_NE(refusal("%\nO1\nN10 G81 Z-5. R1. F50.\nN50 X10.\nN60 G80\nM30\n%\n", "N50").find("canned cycle (G81)"),
              std::string::npos);
    EXPECT_NE(refusal("%\nO1\nN10 IF [#1 EQ 1] GOTO 60\nN50 X10.\nN60 M30\n%\n", "N50").find("a jump"),
              std::string::npos);
    EXPECT_NE(refusal("%\nO1\nN10 G92 X0 Y0\nN50 X10.\nM30\n%\n", "N50").find("G92 sets coordinates"),
              std::string::npos);
    EXPECT_NE(refusal("%\nO1\nN10 F#5\nN50 X10.\nM30\n%\n", "N50").find("macro expression (F#5)"), std::string::npos);
    EXPECT_NE(refusal("%\nO1\n/N10 G91\nN50 X10.\nM30\n%\n", "N50").find("optional block"), std::string::npos);
}

// A real Haas program from outside (../shared/data): restarted at its second tool.
TEST(Restart, RealHaasProgram) {
    std::string path = std::string(TAPE_SOURCE_DIR) + "/../shared/data/outside2/haas/gcw_HAAS.nc";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path << " (the shared data is not beside the tree)";
    tape::RestartPlan p = tape::plan_restart(read_text(path), "N110");
    // The file's lines end CR LF, and the blocks made up for the restart end as its own do.
    EXPECT_EQ(p.start, "%\r\nO00094 ( HAAS )\r\n");
    EXPECT_EQ(p.line_end, "\r\n");
    std::string header = p.header();
    for (std::size_t i = header.find('\n'); i != std::string::npos; i = header.find('\n', i + 1))
        EXPECT_TRUE(i > 0 && header[i - 1] == '\r') << "a bare LF at " << i << " of " << header;
    ASSERT_FALSE(p.modal.empty());
    EXPECT_EQ(p.modal.front(), "IF [ #5405 GE 6000 ] THEN #3000= 15");
    EXPECT_EQ(p.rest.rfind("N110 T3 M06", 0), 0u);
    bool spindle = false;
    for (const auto& b : p.modal) spindle = spindle || b == "S1500 M03";
    EXPECT_TRUE(spindle) << p.header();
}

}  // namespace
