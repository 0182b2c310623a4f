// Choosing a dialect from a program's text: the right one above the margin, two close below it, none
// when another control's syntax or unreadable text outweighs every dialect's clues.
#include "tape/dialect.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.hpp"

using namespace tape;

namespace {

Dialect chosen(std::string_view text) { return guess_dialect(text).dialect; }

std::string shared_data() { return std::string(TAPE_SOURCE_DIR) + "/../shared/data"; }

}  // namespace

// The shape of lagun_HEMA-P049.ngc: o-word calls with bracketed arguments are LinuxCNC's, not Macro B.
TEST(DialectChoice, OWordCallsWithBracketsAreLinuxcnc) {
    EXPECT_EQ(chosen("#<_z_clearance> = 0.5\nG20  ; inch\nG10 L1 P1 Z0.0 R[1/4/2] ; set tool\n#1 = 4\n"
                     "o1 if [#1 EQ 1]\no<pocket_circ> call [.591] [-.433] [12/25.4] [0.1][-.1] [0][4]\n"
                     "o<pocket_circ> call [.591] [-.984] [12/25.4] [0.1][-.2] [0][4]\no1 endif\nM2\n"),
              Dialect::linuxcnc);
}

// The shape of gcw_TOKARKA.NC: an O number on the '%' line, R arcs, N99999 repeated: Fanuc, not ГОСТ.
TEST(DialectChoice, PercentWithAnONumberAndRArcsAreFanuc) {
    auto choice = guess_dialect(
        "%O1200(TOKARKA)\nN10 G21 G90 G40 G95\nN20 (EGYSZER{ M{VELET)\nN60 G92 S500\nN90 G0 X160.0 Z7.149\n"
        "N110 G1 Z5.286 F0.3\nN360 G2 X60. Z-30. R5.\nN99999 Z-48.5\nN99999 M30\n%\n");
    EXPECT_EQ(choice.dialect, Dialect::fanuc) << choice.reason;
    EXPECT_FALSE(choice.close);
}

TEST(DialectChoice, OkumaIsNone) {
    auto choice = guess_dialect(
        "$FLANGE.MIN%\nPRES=1 (CHUCK PRESSURE)\nFLAN=318\nG50 S800 M90\nIF[PRES EQ 1]NM59\n"
        "M58\nGOTO N1\nNM59 M59\nN10 G96 G0 X=FLAN+5 Z=SPFA+10 S300 M3\nM02\n");
    EXPECT_EQ(choice.dialect, Dialect::none);
    EXPECT_NE(choice.reason.find("no known dialect fits"), std::string::npos) << choice.reason;
    EXPECT_NE(choice.reason.find("assignment"), std::string::npos) << choice.reason;
}

TEST(DialectChoice, SinumerikIsNone) {
    EXPECT_EQ(chosen("%_N_PART_MPF\n;$PATH=/_N_MPF_DIR\nDEF REAL HIGH=143.35\nN40 R0=0 R1=0 R2=111.2\nN50 L54\n"
                     "N110 G17 G54 X57 Y92.07 Z=HIGH+60 S2750 F1500 M3\nN130 G1 X23\nN150 M30\n"),
              Dialect::none);
    EXPECT_EQ(chosen("%MPF  90\n( SINUMERIK 850 )\nR11=384.553 R12=213.086\nL100\nN1 @371 R52 K2 K0\n"
                     "N10 G0 G17 G40 G90 Z631.6 D0\nN50 G81 R2=8. R3=-38. R10=8.\nN60 M30\n"),
              Dialect::none);
}

TEST(DialectChoice, PhilipsIsNone) {
    EXPECT_EQ(chosen("%PM\n\nN9000 (PHILIPS 3000)\nN10 G54\nN20 G99 X105 Z1237\nN30 T1013 M4\nN8001 X50.2 Z1237.5\n"
                     "N110 G15 X57.2 R3\nN8011\nN180 G13 N1=8001 N2=8011\nN190 G0 X250 M9\nN200 M30\n"),
              Dialect::none);
}

TEST(DialectChoice, HecklerAndKochIsNone) {
    EXPECT_EQ(chosen("(OLD HECKLER&KOCH CONTROL)\nP000058\nN10T25M75M60\nN30G54G0Z+0035000F20000S3120M13P32.936P32\n"
                     "N40G89G81G2Z-0028000K+0000000R-0013000M13M8P120.0P121.0P122.178P123.22.5P125.-90P126.4\n"
                     "N50G92X-0280000\nN70G80G0Z+0040000\nN130T0M6M29M70\n"),
              Dialect::none);
}

// Clues of both, as many of each: the two are close, and the reason says so.
TEST(DialectChoice, BelowTheMarginTwoAreClose) {
    auto choice = guess_dialect("G21 G64 P0.02\nG0 X0 Y0\nM98 P100\nG1 X1 F100\nM30\n");
    ASSERT_TRUE(choice.close);
    EXPECT_NE(choice.dialect, *choice.close);
    EXPECT_NE(choice.reason.find("close to"), std::string::npos) << choice.reason;
}

// With no clue: ГОСТ when it starts with '%', LinuxCNC when no '%' comes before it.
TEST(DialectChoice, NoClueFallsBackByTheTapesStart) {
    EXPECT_EQ(chosen("%\nN1 G01 X1 F100\nN2 M02\n"), Dialect::gost);
    EXPECT_EQ(chosen("G0 X1\nG1 X2 F100\nM2\n"), Dialect::linuxcnc);
    EXPECT_EQ(chosen("G21\nG18 G8\nG0 X13.5 Z1.0\nM2\n%\n"), Dialect::linuxcnc);  // only a closing '%'
}

// A program with a few mistakes is still its dialect's: planted errors read wrong in every dialect.
TEST(DialectChoice, AFewMistakesDoNotMakeItNone) {
    EXPECT_EQ(chosen("%\nO0800\nN10 G21 G17\nN50 Z2.$\nN80 g01 Y35.\nN100 G01 X55.5.\nN180 G90\n%\n"), Dialect::fanuc);
    EXPECT_EQ(chosen("%12\n:001 G90 G17 X+0. Y+0.\nN002 G01 X+25. X+30. F100\nN003 G02 X+25. Y+0. R+25.\nN004 M02\n"),
              Dialect::gost);
}

// The files the issue names, where ../shared/data is at hand.
TEST(DialectChoice, TheIssuesFiles) {
    if (!std::filesystem::exists(shared_data() + "/outside2"))
        GTEST_SKIP() << shared_data() << " is absent: the programs from outside are not in a user's clone";
    EXPECT_EQ(chosen(read_text(shared_data() + "/outside2/lcnc/lagun_HEMA-P049.ngc")), Dialect::linuxcnc);
    EXPECT_EQ(chosen(read_text(shared_data() + "/outside2/other/gcw_TOKARKA.NC").substr(0, 64 << 10)), Dialect::fanuc);
    for (const char* f :
         {"okuma/gcw_FLANGE.nc", "okuma/gcw_OSP5020M.nc", "okuma/gcw_OSP7000L.nc", "sinumerik/gcw_SINUMERIK840D.nc",
          "sinumerik/gcw_SINUMERIK850.nc", "other/gcw_PHILIPS.nc", "other/gcw_HK.nc"})
        EXPECT_EQ(chosen(read_text(shared_data() + "/outside2/" + f)), Dialect::none) << f;
}
