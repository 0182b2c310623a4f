// Restart with the position: the approach plan_restart adds after the modal state, and the property
// that makes it right: the interpreter's moves of the restarted program, after the approach, are the
// whole program's moves from the restart block on.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

#include "tape/decode.hpp"
#include "tape/error.hpp"
#include "tape/motion.hpp"
#include "tape/restart.hpp"
#include "test_util.hpp"

namespace {

using tape::MoveKind;

struct Collect : tape::MotionVisitor {
    std::vector<tape::Move> moves;
    void move(const tape::Move& m) override { moves.push_back(m); }
    std::size_t unsimulated() const {
        std::size_t n = 0;
        for (const auto& m : moves) n += m.kind == MoveKind::not_simulated;
        return n;
    }
};

Collect interpret(const std::string& text, tape::Dialect d, bool lathe = false) {
    Collect c;
    auto options = tape::motion_options(d);
    options.lathe = lathe;
    tape::interpret_each(text, {}, c, options);
    return c;
}

bool near(const tape::Point& a, const tape::Point& b) {
    return std::abs(a.x - b.x) < 1e-6 && std::abs(a.y - b.y) < 1e-6 && std::abs(a.z - b.z) < 1e-6;
}

// "" when the moves agree; else the first difference, in words.
std::string differ(const std::vector<tape::Move>& want, std::size_t from_want, const std::vector<tape::Move>& got,
                   std::size_t from_got) {
    if (want.size() - from_want != got.size() - from_got)
        return std::to_string(want.size() - from_want) + " moves from the block on, " +
               std::to_string(got.size() - from_got) + " after the approach";
    for (std::size_t i = 0; i < want.size() - from_want; ++i) {
        const auto& a = want[from_want + i];
        const auto& b = got[from_got + i];
        bool same = a.kind == b.kind && a.code == b.code && near(a.start, b.start) && near(a.end, b.end);
        if (a.kind == MoveKind::arc)
            same = same && near(a.centre, b.centre) && a.clockwise == b.clockwise && a.turns == b.turns;
        if (!same) return "move " + std::to_string(i) + " (line " + std::to_string(a.where.line) + ") differs";
    }
    return "";
}

std::size_t first_at_line(const std::vector<tape::Move>& moves, std::uint64_t line) {
    std::size_t i = 0;
    while (i < moves.size() && moves[i].where.line < line) ++i;
    return i;
}

std::uint64_t lines_in(const std::string& s) {
    std::uint64_t n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

// The tally of one run of the property over programs.
struct Tally {
    std::size_t programs = 0, blocks = 0, restarted = 0;
    std::map<std::string, std::size_t> refusals;  // by reason, line numbers cut off
};

std::string reason(const std::string& what) {
    auto colon = what.find(": ");
    std::string why = colon == std::string::npos ? what : what.substr(colon + 2);
    for (auto cut : {" (", ": ", " at ", " before "})
        if (auto at = why.find(cut); at != std::string::npos) why.resize(at);
    return why;
}

// For every numbered block of the program (at most ~150 spread over it): refused, or the same moves.
void check_program(const std::string& name, const std::string& text, tape::Dialect d, Tally& t, bool lathe = false) {
    Collect whole = interpret(text, d, lathe);
    if (whole.unsimulated() != 0 || whole.moves.empty()) return;  // not a program the interpreter covers
    tape::LoadOptions lo;
    lo.dialect = d;
    auto loaded = tape::load(text, {}, lo);
    std::map<long long, int> seen;
    std::vector<std::pair<std::string, std::uint64_t>> numbered;
    for (const auto& p : loaded.programs)
        for (const auto& b : p.blocks)
            if (b.number && b.number->integer() && ++seen[*b.number->integer()] == 1)
                numbered.emplace_back(b.number_text(), b.where.line);
    ++t.programs;
    std::size_t stride = numbered.size() / 150 + 1;
    for (std::size_t i = 0; i < numbered.size(); i += stride) {
        const auto& [block, line] = numbered[i];
        if (seen[std::stoll(block.substr(1))] > 1) continue;
        ++t.blocks;
        tape::RestartPlan plan;
        try {
            plan = tape::plan_restart(text, block, d, lathe);
        } catch (const tape::Error& e) {
            ++t.refusals[reason(e.what())];
            continue;
        }
        ++t.restarted;
        Collect again = interpret(plan.text(), d, lathe);
        std::uint64_t rest_line = lines_in(plan.header()) + 1;
        std::string diff =
            differ(whole.moves, first_at_line(whole.moves, line), again.moves, first_at_line(again.moves, rest_line));
        EXPECT_EQ(diff, "") << name << " restarted at " << block << ":\n" << plan.header();
    }
}

void report(const char* what, const Tally& t) {
    std::printf("%s: %zu programs, %zu blocks checked, %zu restarted with the same moves, %zu refused\n", what,
                t.programs, t.blocks, t.restarted, t.blocks - t.restarted);
    for (const auto& [why, n] : t.refusals) std::printf("  %5zu refused: %s\n", n, why.c_str());
}

const std::string issue_example =
    "%\nO0007\nN10 G90 G54 G17 G00 X0 Y0 Z50.\nN20 T1 M06\nN30 S1000 M03\nN40 G00 X10. Y10. Z2.\n"
    "N50 G01 Z-5. F100.\nN60 G01 X50. Y10.\nN70 G02 X70. Y30. I0 J20.\nN80 G01 Y60.\nN90 G00 Z50.\nN100 M30\n%\n";

// The issue's example: N70's arc starts at X50 Y10 Z-5, reached from Z50 (the highest rapid) at F100.
TEST(RestartMotion, IssueExampleApproachesTheArcsStart) {
    auto p = tape::plan_restart(issue_example, "N70");
    EXPECT_EQ(p.approach, (std::vector<std::string>{"G90 G00 Z50.", "G00 X50. Y10.", "G01 Z-5. F100.", "G01 F100."}));
    EXPECT_EQ(p.header().find("G01 F100.\nG90 G00 Z50.\n") != std::string::npos, true) << p.header();
}

// In G91 the approach is absolute, and G91 is in force again before the block.
TEST(RestartMotion, IncrementalProgramBackInG91) {
    std::string text = "%\nO8\nN10 G21 G90 G00 X0 Y0 Z20.\nN20 G91 G01 Z-22. F50.\nN30 X10.\nN40 Y5.\nN50 M30\n%\n";
    auto p = tape::plan_restart(text, "N40");
    EXPECT_EQ(p.approach, (std::vector<std::string>{"G90 G00 Z20.", "G00 X10. Y0.", "G01 Z-2. F50.", "G91 G01 F50."}));
}

// An inch program: the approach in inches, as finely as the program writes.
TEST(RestartMotion, InchProgramInInches) {
    std::string text = "%\nO9\nN10 G20 G90 G00 X0 Y0 Z1.\nN20 G01 Z-0.125 F10.\nN30 X2.5\nN40 Y1.0625\nN50 M30\n%\n";
    auto p = tape::plan_restart(text, "N40");
    EXPECT_EQ(p.approach, (std::vector<std::string>{"G90 G00 Z1.", "G00 X2.5 Y0.", "G01 Z-0.125 F10.", "G01 F10."}));
}

// A lathe, X in diameters: X clear to the largest X, Z, then X at the feed.
TEST(RestartMotion, LatheGoesXThenZThenX) {
    std::string text = "%\nO10\nN10 G21 G18 G00 X50. Z5.\nN20 G01 X20. F0.2\nN30 Z-30.\nN40 X40.\nN50 M30\n%\n";
    auto p = tape::plan_restart(text, "N40", tape::Dialect::fanuc, true);
    EXPECT_EQ(p.approach, (std::vector<std::string>{"G00 X50.", "G00 Z-30.", "G01 X20. F0.2", "G01 F0.2"}));
}

std::string refusal(const std::string& text, const std::string& block, bool lathe = false) {
    try {
        tape::plan_restart(text, block, tape::Dialect::automatic, lathe);
    } catch (const tape::Error& e) {
        EXPECT_EQ(e.code(), tape::Errc::usage);
        return e.what();
    }
    return "";
}

TEST(RestartMotion, RefusedWhereThePlaceIsNotKnown) {
    // Z never set: the height of the arc is not known.
    std::string why = refusal("%\nO1\nN10 G90 G00 X0 Y0\nN20 G01 X5. F100.\nN30 X10.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("where the tool stands in Z at N30 is not known"), std::string::npos) << why;
    // A work offset changed: where the tool stands in the new one is the control's.
    why = refusal("%\nO1\nN10 G90 G54 G00 X0 Y0 Z5.\nN20 G55\nN30 G01 X10. F100.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("in X, Y, Z at N30 is not known"), std::string::npos) << why;
    // A reference return: the tool is where the control keeps.
    why = refusal("%\nO1\nN10 G90 G00 X0 Y0 Z5.\nN20 G28 G91 Z0\nN25 G90\nN30 G01 X10. F100.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("in Z at N30 is not known"), std::string::npos) << why;
    // A block the interpreter does not simulate.
    why = refusal("%\nO1\nN10 G90 G00 X0 Y0 Z5.\nN20 G68 X0 Y0 R45.\nN30 G01 X10. F100.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("line 4"), std::string::npos) << why;
    // A rotation in force at the block (the modal blocks do not send it again): where it goes is not known.
    why = refusal("%\nO1\nN10 G90 G00 X0 Y0 Z5.\nN20 G68 R45.\nN30 G01 X10. F100.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("a coordinate transformation (G68 at line 4) is in force"), std::string::npos) << why;
    // Values without a point: worth what the control's least increment makes them.
    why = refusal("%\nO1\nN10 G90 G00 X1000 Y0 Z5.\nN30 G01 X10. F100.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("X1000 has no decimal point"), std::string::npos) << why;
    // Cutter compensation in force: the tool is off the programmed path.
    why = refusal("%\nO1\nN10 G90 G00 X0 Y0 Z5.\nN20 G41 D1 G01 X5. F100.\nN30 X10.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("cutter compensation (G41 D1)"), std::string::npos) << why;
    // No feed to go down at.
    why = refusal("%\nO1\nN10 G90 G00 X0 Y0 Z5.\nN20 Z-1.\nN30 G01 X10. F100.\nM30\n%\n", "N30");
    EXPECT_NE(why.find("no feed (F)"), std::string::npos) << why;
}

// The property over the project's own programs: the issue's example, the sample tapes, two lathes.
TEST(RestartMotion, SameMovesFromTheBlockOnInTheSamples) {
    Tally t;
    check_program("issue example", issue_example, tape::Dialect::fanuc, t);
    // The sample tapes whose programs write decimal points, decoded (the 16К20Ф3 tape's do not).
    for (const char* name : {"circle-examples.iso.ptp", "gost-20999-format-example.iso.ptp", "koi7-comment.iso.ptp"}) {
        auto decoded = tape::decode(read_frames(sample_path(name)), tape::DecodeOptions{});
        ASSERT_TRUE(decoded.ok()) << name;
        check_program(name, decoded.text, tape::Dialect::gost, t);
    }
    // Lathes: a Fanuc lathe in diameters, a LinuxCNC lathe in G7 with an arc.
    check_program("fanuc lathe",
                  "%\nO10\nN10 G21 G18 G00 X50. Z5.\nN20 G01 X20. F0.2\nN30 Z-30.\nN40 X40.\nN50 M30\n%\n",
                  tape::Dialect::fanuc, t, true);
    check_program("linuxcnc lathe",
                  "G7 G18 G21 G90\nN10 G0 X40. Z2.\nN20 G1 X10. F0.1\nN30 Z-10.\nN40 G2 X20. Z-15. I5. K0\n"
                  "N50 G1 X30.\nN60 G0 X40.\nN70 M2\n",
                  tape::Dialect::linuxcnc, t, true);
    report("samples", t);
    EXPECT_GE(t.programs, 2u);
    EXPECT_GT(t.restarted, 0u);
}

// The property over the outside programs (../shared/data/outside*): every one the interpreter covers
// with nothing left out.
TEST(RestartMotion, SameMovesFromTheBlockOnInTheOutsidePrograms) {
    SKIP_WITHOUT_SHARED_DATA("outside2");
    Tally t;
    std::set<std::string> kinds = {".nc", ".ngc", ".gcode", ".tap", ".NC", ".txt"};
    for (const char* dir : {"outside", "outside2", "outside3"}) {
        if (!std::filesystem::exists(shared_data(dir))) continue;
        for (const auto& e : std::filesystem::recursive_directory_iterator(shared_data(dir))) {
            if (!e.is_regular_file() || !kinds.contains(e.path().extension().string())) continue;
            if (e.file_size() > (2u << 20)) continue;
            std::string text = read_text(e.path().string());
            if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
            check_program(e.path().filename().string(), text, tape::guess_dialect(text).dialect, t);
        }
    }
    report("outside", t);
    EXPECT_GT(t.programs, 0u);
}

// The lathe programs among them, restarted as a lathe's (X clear, Z, X; X in diameters where the
// dialect says so).
TEST(RestartMotion, SameMovesFromTheBlockOnInTheOutsideLathePrograms) {
    SKIP_WITHOUT_SHARED_DATA("outside2");
    Tally t;
    for (const char* name : {"outside/lcnc/lathe_pawn.ngc", "outside/lcnc/lathecomp.ngc",
                             "outside2/fanuc/gcw_FANUC0T.nc", "outside2/other/gcw_TOKARKA.NC",
                             // G71/G70: a block of the contour is refused, the others restart
                             "outside3/haas/cade_lathe-l5.nc", "outside3/haas/cade_O58214.nc"}) {
        if (!std::filesystem::exists(shared_data(name))) continue;
        std::string text = read_text(shared_data(name));
        check_program(name, text, tape::guess_dialect(text).dialect, t, true);
    }
    report("outside lathes", t);
    EXPECT_GT(t.programs, 0u);
}

}  // namespace
