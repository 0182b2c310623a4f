// Subprograms followed by the interpreter (tape/motion.hpp): Fanuc/Haas M98 P with L and P####LLLL
// repeats, Haas M97 local subroutines, M99 P, LinuxCNC o-call; what cannot be followed (a program not in
// the text, nesting past the control's levels, recursion) named at its block. Moves worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "tape/error.hpp"
#include "tape/motion.hpp"
#include "tape/restart.hpp"
#include "test_util.hpp"

namespace {

using tape::Dialect;
using tape::Move;
using tape::MoveKind;

struct Collect : tape::MotionVisitor {
    std::vector<Move> moves;
    std::vector<std::uint64_t> sub_blocks;  // lines of the subprogram blocks given before their moves
    void move(const Move& m) override { moves.push_back(m); }
    void subprogram_block(const tape::Block& b) override { sub_blocks.push_back(b.where.line); }
    std::vector<Move> of(MoveKind k) const {
        std::vector<Move> out;
        std::copy_if(moves.begin(), moves.end(), std::back_inserter(out), [k](const Move& m) { return m.kind == k; });
        return out;
    }
    std::vector<Move> paths() const {
        std::vector<Move> out;
        for (const auto& m : moves)
            if (m.kind == MoveKind::rapid || m.kind == MoveKind::linear || m.kind == MoveKind::arc) out.push_back(m);
        return out;
    }
};

Collect run(const std::string& text, Dialect d) {
    Collect c;
    tape::interpret_each(text, {}, c, tape::motion_options(d));
    return c;
}

// (x, y) end of each path move, and its line.
struct End {
    double x, y;
    std::uint64_t line;
};

// with_lines false: the lines are not compared (a restarted text has lines of its own).
void expect_ends(const std::vector<Move>& moves, const std::vector<End>& want, bool with_lines = true) {
    ASSERT_EQ(moves.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_NEAR(moves[i].end.x, want[i].x, 1e-9) << "move " << i;
        EXPECT_NEAR(moves[i].end.y, want[i].y, 1e-9) << "move " << i;
        if (with_lines) {
            EXPECT_EQ(moves[i].where.line, want[i].line) << "move " << i;
        }
    }
}

// Main O0001 calls O1000 twice with L2 and twice again as Fanuc's P####LLLL (P21000: 2 times O1000).
// O1000 moves X by +10 in G91: X 10, 20; back to 0; 10, 20. O1000 itself, after the main program,
// does not run on its own.
const std::string fanuc_main =
    "%\n"
    "O0001\n"
    "N10 G90 G54 G17 G00 X0 Y0 Z50.\n"  // line 3
    "N20 M98 P1000 L2\n"
    "N30 G90 G00 X0 Y0\n"  // line 5
    "N40 M98 P21000\n"
    "N50 M30\n"
    "O1000\n"
    "N1 G91 G01 X10. F100.\n"  // line 9
    "N2 M99\n"
    "%\n";

TEST(MotionSubprograms, FanucM98WithRepeatsFollowed) {
    auto c = run(fanuc_main, Dialect::fanuc);
    EXPECT_TRUE(c.of(MoveKind::not_simulated).empty()) << c.of(MoveKind::not_simulated)[0].note;
    expect_ends(c.paths(), {{0, 0, 3}, {10, 0, 9}, {20, 0, 9}, {0, 0, 5}, {10, 0, 9}, {20, 0, 9}});
    auto lines = c.of(MoveKind::linear);
    ASSERT_EQ(lines.size(), 4u);
    for (const auto& m : lines) {
        EXPECT_EQ(m.depth, 1);
        EXPECT_EQ(m.block, 8u);  // O0001 is the tape's block 1, N1 of O1000 its 8th
        EXPECT_TRUE(m.state.incremental);
    }
    EXPECT_EQ(c.sub_blocks, (std::vector<std::uint64_t>{9, 10, 9, 10, 9, 10, 9, 10}));
    EXPECT_EQ(c.of(MoveKind::program_end).size(), 1u);  // M30; the M99s return
}

// Fanuc's ISO form of a program number, ":1000", is the program M98 P1000 calls (as search finds it).
TEST(MotionSubprograms, ColonProgramNumberIsCalled) {
    auto c =
        run("%\n:0001\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P1000\nN30 M30\n:1000\nN1 G00 X4.\nN2 M99\n%\n", Dialect::fanuc);
    EXPECT_TRUE(c.of(MoveKind::not_simulated).empty()) << c.of(MoveKind::not_simulated)[0].note;
    expect_ends(c.paths(), {{0, 0, 3}, {4, 0, 7}});
}

// Haas M97 P100: block N100 of the same program, after M30, run as a subroutine up to its M99.
TEST(MotionSubprograms, HaasM97LocalSubroutine) {
    auto c =
        run("%\nO00010\nN10 G90 G00 X0 Y0 Z5.\nN20 M97 P100\nN30 G00 X50.\nN40 M30\n"
            "N100 G01 X5. Y5. F200.\nN110 G00 X0 Y0\nN120 M99\n%\n",
            Dialect::fanuc);
    EXPECT_TRUE(c.of(MoveKind::not_simulated).empty());
    expect_ends(c.paths(), {{0, 0, 3}, {5, 5, 7}, {0, 0, 8}, {50, 0, 5}});
}

// M99 P40 returns to the caller's N40: N30 does not run.
TEST(MotionSubprograms, M99PReturnsToTheCallersBlock) {
    auto c =
        run("%\nO0001\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P2000\nN30 G00 X99.\nN40 G00 X7.\nN50 M30\n"
            "O2000\nN1 G00 Y3.\nN2 M99 P40\n%\n",
            Dialect::fanuc);
    EXPECT_TRUE(c.of(MoveKind::not_simulated).empty());
    expect_ends(c.paths(), {{0, 0, 3}, {0, 3, 9}, {7, 3, 6}});
}

// A jump back (M99 P10, before the call) is a loop: named, not followed.
TEST(MotionSubprograms, M99PBackIsNamed) {
    auto c = run("%\nO0001\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P2000\nN30 M30\nO2000\nN1 G00 Y3.\nN2 M99 P10\n%\n",
                 Dialect::fanuc);
    auto named = c.of(MoveKind::not_simulated);
    ASSERT_EQ(named.size(), 1u);
    EXPECT_NE(named[0].note.find("before the call: a loop"), std::string::npos) << named[0].note;
    EXPECT_EQ(named[0].where.line, 8u);
}

// LinuxCNC: a square drawn by o<square> call twice, the second from X20.
TEST(MotionSubprograms, LinuxcncOCall) {
    auto c =
        run("o<square> sub\n  G91 G1 X10 F100\n  Y10\n  X-10\n  Y-10\n  G90\no<square> endsub\n"
            "G90 G0 X0 Y0 Z1\no<square> call\nG0 X20\no<square> call\nM2\n",
            Dialect::linuxcnc);
    EXPECT_TRUE(c.of(MoveKind::not_simulated).empty());
    expect_ends(c.paths(), {{0, 0, 8},
                            {10, 0, 2},
                            {10, 10, 3},
                            {0, 10, 4},
                            {0, 0, 5},
                            {20, 0, 10},
                            {30, 0, 2},
                            {30, 10, 3},
                            {20, 10, 4},
                            {20, 0, 5}});
}

// An o-sub that moves by its arguments (#1): what it does is known only when it runs; named at the
// body's block, and the call's block does not hide it.
TEST(MotionSubprograms, OCallArgumentsNamedInTheBody) {
    auto c = run("o<hole> sub\nG0 X#1\no<hole> endsub\nG0 X0 Y0 Z0\no<hole> call [5]\nM2\n", Dialect::linuxcnc);
    auto named = c.of(MoveKind::not_simulated);
    ASSERT_EQ(named.size(), 1u);
    EXPECT_EQ(named[0].where.line, 2u);
    EXPECT_NE(named[0].note.find("macro"), std::string::npos) << named[0].note;
}

// O1 → O2 → O3 → O4 → O5 is four levels; O5's call of O6 would be the fifth: named at O5's block.
TEST(MotionSubprograms, NestingPastFourLevelsNamed) {
    std::string text = "%\nO0001\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P2\nN30 M30\n";
    for (int p = 2; p <= 5; ++p)
        text += "O" + std::to_string(p) + "\nG91 G00 X1.\nM98 P" + std::to_string(p + 1) + "\nM99\n";
    text += "O6\nG91 G00 Y1.\nM99\n%\n";
    auto c = run(text, Dialect::fanuc);
    auto named = c.of(MoveKind::not_simulated);
    ASSERT_EQ(named.size(), 1u);
    EXPECT_NE(named[0].note.find("deeper than the 4 levels"), std::string::npos) << named[0].note;
    EXPECT_EQ(named[0].where.line, 20u);          // O5's M98 P6
    EXPECT_EQ(c.of(MoveKind::rapid).size(), 5u);  // N10 and X1 in O2..O5; O6's Y1 never runs
    EXPECT_NE(named[0].note.find("Fanuc control allows: the control stops"), std::string::npos);
    // A ГОСТ control's own depth is not on tape: Fanuc's bound is followed, and said to be Fanuc's.
    // (ГОСТ ends the program at M30: the bodies stand before it, and N30 calls the M30 after them.)
    std::string local = "%\nN10 G90 G00 X0 Y0 Z5.\nN20 M97 P100\nN30 M97 P900\n";
    for (int p = 1; p <= 5; ++p)
        local += "N" + std::to_string(p * 100) + " G91 G00 X1.\nN" + std::to_string(p * 100 + 1) + " M97 P" +
                 std::to_string(p * 100 + 100) + "\nN" + std::to_string(p * 100 + 2) + " M99\n";
    auto gost = run(local + "N600 G91 G00 Y1.\nN601 M99\nN900 M30\n%\n", Dialect::gost).of(MoveKind::not_simulated);
    ASSERT_FALSE(gost.empty());
    EXPECT_NE(gost[0].note.find("this control's own limit is not known here"), std::string::npos) << gost[0].note;
}

TEST(MotionSubprograms, RecursionNamed) {
    auto c =
        run("%\nO0001\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P2\nN30 M30\nO2\nG91 G00 X1.\nM98 P2\nM99\n%\n", Dialect::fanuc);
    auto named = c.of(MoveKind::not_simulated);
    ASSERT_EQ(named.size(), 1u);
    EXPECT_NE(named[0].note.find("recursion"), std::string::npos) << named[0].note;
    EXPECT_EQ(named[0].where.line, 8u);
}

// A program that calls only itself still runs: its call is named where it recurs.
TEST(MotionSubprograms, ProgramCallingItselfStillRuns) {
    auto c = run("%\nO0001\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P1\nN30 M30\n%\n", Dialect::fanuc);
    EXPECT_EQ(c.of(MoveKind::rapid).size(), 1u);
    auto named = c.of(MoveKind::not_simulated);
    ASSERT_EQ(named.size(), 1u);
    EXPECT_EQ(named[0].where.line, 4u);
}

TEST(MotionSubprograms, MissingProgramNamedAtItsBlock) {
    auto c = run("%\nO0001\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P5001 L3\nN30 G00 X1.\nN40 M30\n%\n", Dialect::fanuc);
    auto named = c.of(MoveKind::not_simulated);
    ASSERT_EQ(named.size(), 1u);
    EXPECT_EQ(named[0].where.line, 4u);
    EXPECT_NE(named[0].note.find("program O5001 is not in this text"), std::string::npos) << named[0].note;
    EXPECT_EQ(named[0].end_known, 0u);
}

// A tape: the subprogram's moves carry its own blocks' frames, as the loader gives them in text order.
TEST(MotionSubprograms, MovesCarryTheSubprogramBlocksFrames) {
    std::vector<std::uint64_t> frame_of(fanuc_main.size());
    for (std::size_t i = 0; i < frame_of.size(); ++i) frame_of[i] = 100 + 2 * i;  // leader, and a blank each
    Collect c;
    tape::interpret_each(fanuc_main, frame_of, c, tape::motion_options(Dialect::fanuc));
    tape::LoadOptions lo;
    lo.dialect = Dialect::fanuc;
    auto loaded = tape::load(fanuc_main, frame_of, lo);
    ASSERT_EQ(loaded.programs.size(), 2u);
    const tape::Block& n1 = loaded.programs[1].blocks[1];  // N1 of O1000
    ASSERT_EQ(n1.number_text(), "N1");
    auto lines = c.of(MoveKind::linear);
    ASSERT_EQ(lines.size(), 4u);
    for (const auto& m : lines) {
        EXPECT_EQ(m.where.frame, n1.where.frame);
        EXPECT_EQ(m.where.offset, n1.where.offset);
        EXPECT_EQ(m.where.column, n1.where.column);
        EXPECT_EQ(m.block, n1.ordinal);
    }
}

// Fanuc's ';' ends a block: a subprogram written on one line, its blocks' columns counted on from where
// its body starts on that line.
TEST(MotionSubprograms, BodyStartingInsideALine) {
    std::string text = "%\nO0001;N10 G90 G00 X0 Y0 Z5.;N20 M98 P7;N30 M30;\nO7;N1 G91 G01 X2. F50.;N2 M99;\n%\n";
    auto c = run(text, Dialect::fanuc);
    tape::LoadOptions lo;
    lo.dialect = Dialect::fanuc;
    auto loaded = tape::load(text, {}, lo);
    ASSERT_EQ(loaded.programs.size(), 2u);
    const tape::Block& n1 = loaded.programs[1].blocks[1];
    ASSERT_EQ(n1.number_text(), "N1");
    auto lines = c.of(MoveKind::linear);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].where.line, n1.where.line);
    EXPECT_EQ(lines[0].where.column, n1.where.column);
    EXPECT_EQ(lines[0].where.offset, n1.where.offset);
    EXPECT_NEAR(lines[0].end.x, 2, 1e-9);
}

// Not following (follow_subprograms off): the call is named as before, O1000 runs on its own.
TEST(MotionSubprograms, NotFollowingNamesTheCall) {
    Collect c;
    auto o = tape::motion_options(Dialect::fanuc);
    o.follow_subprograms = false;
    tape::interpret_each(fanuc_main, {}, c, o);
    auto named = c.of(MoveKind::not_simulated);
    ASSERT_EQ(named.size(), 2u);
    EXPECT_NE(named[0].note.find("is not followed"), std::string::npos);
}

// Real programs: fcs_M98_P.nc calls 5001.NC-5013.NC, files beside it that are not in its text: each
// call is named at its block, and nothing else is.
TEST(MotionSubprograms, RealProgramCallsNotInTheTextNamed) {
    SKIP_WITHOUT_SHARED_DATA("outside3/fanuc/fcs_M98_P.nc");
    std::string text = read_text(shared_data("outside3/fanuc/fcs_M98_P.nc"));
    auto c = run(text, Dialect::fanuc);
    std::istringstream in(text);
    std::vector<std::uint64_t> calls;
    std::string line;
    for (std::uint64_t n = 1; std::getline(in, line); ++n)
        if (line.starts_with("M98 ")) calls.push_back(n);
    std::vector<std::uint64_t> named;
    for (const auto& m : c.of(MoveKind::not_simulated)) {
        EXPECT_NE(m.note.find("is not in this text"), std::string::npos) << m.note;
        named.push_back(m.where.line);
    }
    EXPECT_EQ(named, calls);
}

// A restart at a block before a call sends the programs written after the main program with the rest,
// as they were on the tape: the restarted program's moves are the square twice, from the approach's
// end. After the call, the state the subprogram leaves is not rebuilt: refused, saying so.
const std::string square_twice =
    "%\nO0001\nN10 G90 G17 G21 G00 X0 Y0 Z5.\nN20 G01 Z-1. F100.\nN30 G00 X0 Y0\nN40 M98 P1000 L2\n"
    "N50 G90 G00 Z5.\nN60 M30\nO1000\nN1 G91 G01 X10.\nN2 Y10.\nN3 X-10.\nN4 Y-10.\nN5 M99\n%\n";

TEST(MotionSubprograms, RestartBeforeACallSendsTheSubprogram) {
    auto plan = tape::plan_restart(square_twice, "N30", Dialect::fanuc);
    EXPECT_NE(plan.rest.find("O1000\n"), std::string::npos) << plan.rest;
    auto c = run(plan.text(), Dialect::fanuc);
    EXPECT_TRUE(c.of(MoveKind::not_simulated).empty());
    auto lines = c.of(MoveKind::linear);
    ASSERT_GE(lines.size(), 8u);
    std::vector<Move> square(lines.end() - 8, lines.end());
    expect_ends(square,
                {{10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 0}},
                false);
}

TEST(MotionSubprograms, RestartAfterACallRefused) {
    try {
        tape::plan_restart(square_twice, "N50", Dialect::fanuc);
        ADD_FAILURE() << "restart after M98 planned";
    } catch (const tape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("the modal state the subprogram leaves is not rebuilt"), std::string::npos)
            << e.what();
    }
}

// LinuxCNC: the o-sub definitions written before the restart block are sent after the program's start.
TEST(MotionSubprograms, RestartSendsTheOSubDefinitions) {
    std::string text =
        "o<square> sub\n  G91 G1 X10 F100\n  Y10\n  X-10\n  Y-10\n  G90\no<square> endsub\n"
        "N10 G90 G0 X0 Y0 Z1\nN20 G1 Z0 F100\nN30 G0 X20\nN40 o<square> call\nN50 M2\n";
    auto plan = tape::plan_restart(text, "N30", Dialect::linuxcnc);
    EXPECT_TRUE(plan.start.starts_with("o<square> sub\n")) << plan.start;
    auto c = run(plan.text(), Dialect::linuxcnc);
    EXPECT_TRUE(c.of(MoveKind::not_simulated).empty());
    auto lines = c.of(MoveKind::linear);
    ASSERT_GE(lines.size(), 4u);
    std::vector<Move> square(lines.end() - 4, lines.end());
    expect_ends(square, {{30, 0, 0}, {30, 10, 0}, {20, 10, 0}, {20, 0, 0}}, false);
}

}  // namespace

namespace {

// A call without P after a block with one: the P of the block before is not taken for its own (it
// was read through a word of a block already gone).
TEST(MotionSubprograms, CallWithoutPNamesNoEarlierP) {
    auto c = run("%\nO0001\nG0 X0 Y0\nG04 P100\nM97\nM98 P2\nM30\n%\n", Dialect::fanuc);
    auto n = c.of(MoveKind::not_simulated);
    ASSERT_FALSE(n.empty());
    EXPECT_NE(n[0].note.find("M97: no P says which subprogram is called"), std::string::npos) << n[0].note;
}

}  // namespace
