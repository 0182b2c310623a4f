// What lint makes of a program with a machine profile beyond its word format: a span of an axis wider
// than the machine's travel (only where the program's zero and the tool cannot have moved in between),
// Fanuc's dotted codes (G54.1) under the profile's format, and the Russian names of a feed code table.
#include <gtest/gtest.h>

#include "tape/lint.hpp"
#include "tape/machine.hpp"
#include "tape/machine_checks.hpp"
#include "tape/program.hpp"

using namespace tape;

namespace {

// A Fanuc mill with travel: X 0 to 500 (500 mm), Y -400 to 0, Z -300 to 0; its words in millimetres.
const std::string mill_profile = R"(name = "vmc"
title = "test mill"
kind = "mill"
dialect = "fanuc"
source = "test"

[[axis]]
name = "X"
min_mm = 0
max_mm = 500

[[axis]]
name = "Y"
min_mm = -400
max_mm = 0

[[axis]]
name = "Z"
min_mm = -300
max_mm = 0
)";

std::vector<std::string> travel(const MachineProfile& m, const std::string& program) {
    std::vector<std::string> out;
    for (const auto& f : lint(load(program, {}, LoadOptions{m.dialect}), LintOptions{.machine = &m}))
        if (f.rule == "machine-travel")
            out.push_back("block " + std::to_string(f.where.block.value_or(0)) + ": " + f.message);
    return out;
}

}  // namespace

TEST(MachineTravel, TwoPointsFartherApartThanTheTravelAreFound) {
    MachineProfile m = parse_machine_profile(mill_profile, "vmc.toml");
    auto found = travel(m, "%\nO0001\nG90 G54 G00 X10. Y-10.\nG01 X300. F200.\nX620.\nY-20.\nM30\n%\n");
    ASSERT_EQ(found.size(), 1U);
    EXPECT_EQ(found[0],
              "block 4: X goes to 620.000 here and to 10.000 in block 2, 610.000 mm apart; test mill's X travels "
              "500.000 mm (0.000 to 500.000, test): one of them is outside it, wherever the work offset puts zero");
    // Incremental moves from a known point are known points too.
    EXPECT_EQ(travel(m, "%\nO0001\nG90 G00 Z0.\nG91 Z-200.\nZ-150.\nM30\n%\n").size(), 1U);
}

TEST(MachineTravel, WithinTheTravelOrAcrossAChangeOfZeroOrToolNothingIsSaid) {
    MachineProfile m = parse_machine_profile(mill_profile, "vmc.toml");
    EXPECT_TRUE(travel(m, "%\nO0001\nG90 G00 X0. Y0.\nX500. Y-400.\nM30\n%\n").empty());
    // Each of these may move the program's zero or the tool against the machine between X10 and X620.
    for (std::string between : {"G55", "G92 X0.", "G52 X100.", "G10 L2 P1 X-100.", "T2 M06", "G43 H2 Z0.",
                                "G41 D1 X20.", "M98 P1000", "G68 X0 Y0 R90.", "#5221=-100.", "/G00 X0."}) {
        SCOPED_TRACE(between);
        EXPECT_TRUE(travel(m, "%\nO0001\nG90 G00 X10. Y0.\n" + between + "\nG00 X620.\nM30\n%\n").empty());
    }
    // A program that moves before it sets an axis absolutely: where it stood is not known.
    EXPECT_TRUE(travel(m, "%\nO0001\nG91 G00 X600.\nG90 X0.\nM30\n%\n").empty());
    // No travel in the profile, or words in pulses: not checked.
    MachineProfile lathe = load_machine("16k20f3s5");
    EXPECT_TRUE(travel(lathe, "%\nN001 G27 X+00100 F10600\nN002 X+99999\nN003 M102\n").empty());
}

TEST(MachineTravel, ALathesXIsHeldAsARadiusWhereTheProfileOnlyGuessesDiameters) {
    MachineProfile m = parse_machine_profile(R"(name = "lathe"
kind = "lathe"
diameter_programming = { value = false, source = "guess: not known" }
dialect = "fanuc"
source = "test"

[[axis]]
name = "X"
min_mm = -10
max_mm = 200
)",
                                             "lathe.toml");
    // X0 to X400: 400 as radii, 200 as diameters: within 210 either way the program is read as diameters.
    EXPECT_TRUE(travel(m, "%\nO0001\nG00 X0. Z5.\nX400.\nM30\n%\n").empty());
    auto found = travel(m, "%\nO0001\nG00 X0. Z5.\nX430.\nM30\n%\n");
    ASSERT_EQ(found.size(), 1U);
    EXPECT_NE(found[0].find("X goes to 215.000 (as a radius) here"), std::string::npos) << found[0];
}

TEST(MachineFanuc, ExtendedWorkOffsetsAreCodesNotPoints) {
    MachineProfile m = load_machine("fanuc-16");
    std::string program = "%\nO0001\nG90 G54.1 P1 G00 X0 Y0\nG54.1 P48\nG54.1 P300\nG5.1 Q1\nG54.7 P1\nM30\n%\n";
    auto findings = lint(load(program, {}, LoadOptions{Dialect::fanuc}), LintOptions{.machine = &m});
    std::vector<std::string> points;
    for (const auto& f : findings)
        if (f.rule == "spec-point") points.push_back(f.message);
    // G54.1 and G5.1 are in Fanuc's table; G54.7 is not, and its point is still said.
    EXPECT_EQ(points, std::vector<std::string>{"G54.7: G03 is a whole number"});
    FormatSpec spec = parse_format_spec("% / DS N04 G03 X+053 Y+053 P+080 Q+053 M03");
    findings = lint(load(program, {}, LoadOptions{Dialect::fanuc}), LintOptions{.spec = &spec});
    std::size_t with_spec = 0;
    for (const auto& f : findings) with_spec += f.rule == "spec-point";
    EXPECT_EQ(with_spec, 1U);
}

TEST(MachineExplain, FeedCodesInRussianAsTheCourseTextNamesThem) {
    MachineProfile p = load_machine("16k20f3s5");
    ASSERT_NE(p.find_feed_code(2), nullptr);
    EXPECT_EQ(p.find_feed_code(1)->meaning_ru, "разгон");
    EXPECT_EQ(p.find_feed_code(7)->meaning_ru, "быстрый ход");
    LoadedTape t = load("%\nN001 G27 F10600\nN002 F20600\nN003 F70000\nN004 M102\n");
    ASSERT_EQ(t.programs.size(), 1U);
    const auto& blocks = t.programs[0].blocks;
    EXPECT_EQ(explain_machine_codes(blocks[0], p, true),
              "G27 работа в абсолютной системе координат, F10600 разгон: 600 мм/мин");
    EXPECT_EQ(explain_machine_codes(blocks[1], p, true),
              "F20600 торможение (меньше величины, указанной в программе, в 20 раз): 30 мм/мин");
    EXPECT_EQ(explain_machine_codes(blocks[2], p, false), "F70000 rapid traverse: X 2400 mm/min, Z 4800 mm/min");
    EXPECT_EQ(explain_machine_codes(blocks[2], p, true), "F70000 быстрый ход: X 2400 мм/мин, Z 4800 мм/мин");
    // A row's Russian name is optional, and read strictly like the rest.
    std::string base =
        "name = \"m\"\nkind = \"mill\"\nsource = \"test\"\n[feed]\n[[feed.code]]\nfirst_digit = 1\n"
        "meaning = \"a\"\n";
    EXPECT_TRUE(parse_machine_profile(base, "m.toml").feed_codes[0].meaning_ru.empty());
    EXPECT_THROW(parse_machine_profile(base + "meaning_ru = 5\n", "m.toml"), Error);
}
