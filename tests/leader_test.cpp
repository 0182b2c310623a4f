// What stands before the first '%' is leader in every dialect (a label, never a program, never an
// error), unless it is a program the '%' closes; comments between '%' and the O number; the corner
// words typed with a space; the dialect chosen from whole lines (issue 31, items 1-3, 5, 6).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tape/dialect.hpp"
#include "tape/lint.hpp"
#include "tape/program.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

constexpr Dialect every_dialect[] = {Dialect::gost, Dialect::fanuc, Dialect::linuxcnc, Dialect::none,
                                     Dialect::automatic};

std::vector<std::string> rules_of(const LoadedTape& t) {
    std::vector<std::string> r;
    for (const auto& f : lint(t)) r.emplace_back(f.rule);
    return r;
}

std::size_t blocks_of(const LoadedTape& t) {
    std::size_t n = 0;
    for (const auto& p : t.programs) n += p.blocks.size();
    return n;
}

// The loader fed a few bytes at a time: the label, programs and findings of load().
LoadedTape load_in_pieces(const std::string& text, Dialect d, std::size_t piece) {
    struct Collect : ProgramVisitor {
        LoadedTape t;
        void label(std::string_view s) override { t.label += s; }
        void program_start(const Program& h) override { t.programs.push_back(h); }
        void block(const Block& b) override { t.programs.back().blocks.push_back(b); }
        void dialect(const DialectChoice& c) override { t.dialect = c.dialect; }
        void finding(const Finding& f) override { t.findings.push_back(f); }
    } c;
    ProgramLoader loader(c, LoadOptions{d});
    for (std::size_t i = 0; i < text.size(); i += piece) loader.feed(std::string_view(text).substr(i, piece));
    loader.finish();
    return c.t;
}

}  // namespace

// The first example: a comment before the '%' hid the program and its error, exit 0.
TEST(Leader, ACommentBeforeThePercentIsLabelInEveryDialect) {
    const std::string text = "(POSTED BY CAM)\n%\nO1234\nG01 X1. X2. F100\nM30\n%\n";
    for (Dialect d : every_dialect) {
        LoadedTape t = load(text, {}, LoadOptions{d});
        EXPECT_EQ(t.label, "(POSTED BY CAM)\n") << dialect_name(d);
        ASSERT_EQ(t.programs.size(), 1U) << dialect_name(d);
        EXPECT_EQ(t.programs[0].start.line, 2U) << dialect_name(d);
        auto rules = rules_of(t);
        if (d != Dialect::none) {  // none checks only what holds for every control
            EXPECT_NE(std::find(rules.begin(), rules.end(), "repeated-dimension"), rules.end()) << dialect_name(d);
        }
    }
    LoadedTape t = load(text, {}, LoadOptions{Dialect::automatic});
    EXPECT_EQ(t.dialect, Dialect::fanuc) << t.dialect_reason;
    EXPECT_EQ(t.programs[0].number, "O1234");
    EXPECT_EQ(rules_of(t), std::vector<std::string>{"repeated-dimension"});
}

// The second: a readable label; auto picked ГОСТ, and with --dialect fanuc no program was listed.
TEST(Leader, AReadableLabelBeforeThePercent) {
    const std::string text =
        "PART 17 REV B\n%\nO1234 (BRACKET)\nN10 G90 G54 G00 X0 Y0\nN20 G01 X10. Y5. F100.\nN40 M30\n%\n";
    for (Dialect d : {Dialect::fanuc, Dialect::automatic}) {
        LoadedTape t = load(text, {}, LoadOptions{d});
        EXPECT_EQ(t.dialect, Dialect::fanuc) << t.dialect_reason;
        EXPECT_EQ(t.label, "PART 17 REV B\n");
        ASSERT_EQ(t.programs.size(), 1U);
        EXPECT_EQ(t.programs[0].number, "O1234");
        EXPECT_EQ(t.programs[0].blocks.size(), 4U);
        EXPECT_TRUE(rules_of(t).empty());
    }
}

// Files with no '%' (CAM output, LinuxCNC programs) are programs, as before; so is a program the '%'
// after it closes (LinuxCNC's closing '%', Fanuc's end of record).
TEST(Leader, TextThatEndsAProgramBeforeThePercentIsTheProgram) {
    for (Dialect d : {Dialect::fanuc, Dialect::linuxcnc, Dialect::none}) {
        LoadedTape none = load("(CAM)\nG21\nG0 X1\nG1 X2 F100\nM2\n", {}, LoadOptions{d});
        ASSERT_EQ(none.programs.size(), 1U) << dialect_name(d);
        EXPECT_EQ(none.programs[0].blocks.size(), 5U) << dialect_name(d);
        EXPECT_EQ(none.label, "");
        LoadedTape closed = load("(CAM)\nG21\nG0 X1\nG1 X2 F100\nM2\n%\n", {}, LoadOptions{d});
        ASSERT_EQ(closed.programs.size(), 1U) << dialect_name(d);
        EXPECT_EQ(closed.programs[0].blocks.size(), 5U) << dialect_name(d);
        EXPECT_EQ(closed.label, "");
        EXPECT_TRUE(rules_of(closed).empty()) << dialect_name(d);
    }
    LoadedTape open = load("G21\nG0 X1\n", {}, LoadOptions{Dialect::linuxcnc});  // no end, no '%': as before
    ASSERT_EQ(open.programs.size(), 1U);
    EXPECT_EQ(rules_of(open), std::vector<std::string>{"program-end"});
}

// A leader longer than the dialect sample is not held: it is read as the program it then must be.
TEST(Leader, ALongTextBeforeThePercentIsReadAsTheProgram) {
    std::string text;
    while (text.size() <= dialect_sample_bytes) text += "G01 X1. Y2. F100\n";
    LoadedTape t = load(text + "%\nO1\nM30\n%\n", {}, LoadOptions{Dialect::fanuc});
    EXPECT_EQ(t.label, "");
    ASSERT_GE(t.programs.size(), 1U);
    EXPECT_GT(t.programs[0].blocks.size(), 1000U);
}

// However the text is cut, the loader holds the leader and gives what load() gives.
TEST(Leader, TheSameInPieces) {
    const std::string text = "PART 17 REV B\n(SETUP)\n%\n(HEADER)\nO1234\nG01 X1. X2. F100\nM30\n%\n";
    for (Dialect d : every_dialect) {
        LoadedTape whole = load(text, {}, LoadOptions{d});
        for (std::size_t piece : {std::size_t{1}, std::size_t{3}, std::size_t{7}}) {
            LoadedTape cut = load_in_pieces(text, d, piece);
            EXPECT_EQ(cut.label, whole.label) << dialect_name(d) << " " << piece;
            EXPECT_EQ(cut.programs.size(), whole.programs.size()) << dialect_name(d) << " " << piece;
            EXPECT_EQ(blocks_of(cut), blocks_of(whole)) << dialect_name(d) << " " << piece;
            ASSERT_EQ(cut.findings.size(), whole.findings.size()) << dialect_name(d) << " " << piece;
            for (std::size_t i = 0; i < cut.findings.size(); ++i)
                EXPECT_EQ(cut.findings[i].where.byte, whole.findings[i].where.byte);
        }
    }
}

TEST(Leader, RealGasCuttingSampleHasItsCommentAsLabel) {
    SKIP_WITHOUT_SHARED_DATA("outside3/other/fcs_gas_Sample12.nc");
    std::string text = read_text(shared_data("outside3/other/fcs_gas_Sample12.nc"));
    for (Dialect d : every_dialect) {
        LoadedTape t = load(text, {}, LoadOptions{d});
        EXPECT_TRUE(t.label.starts_with("($Message(")) << dialect_name(d);
        ASSERT_EQ(t.programs.size(), 1U) << dialect_name(d);
        EXPECT_EQ(t.programs[0].start.line, 2U) << dialect_name(d);
        EXPECT_EQ(t.programs[0].blocks.front().number_text(), "N0") << dialect_name(d);
    }
}

// Item 2: a comment between '%' and the O number made a program of its own, "not ended".
TEST(Leader, ACommentBetweenThePercentAndTheONumberIsInItsProgram) {
    LoadedTape t = load("%\n(HEADER COMMENT)\n\nO0001\nG90 G01 X1. F100\nM30\n%\n", {}, LoadOptions{Dialect::fanuc});
    ASSERT_EQ(t.programs.size(), 1U);
    EXPECT_EQ(t.programs[0].number, "O0001");
    ASSERT_EQ(t.programs[0].blocks.size(), 4U);
    EXPECT_EQ(t.programs[0].blocks[0].comments.at(0).text, "HEADER COMMENT");
    EXPECT_EQ(t.programs[0].blocks[0].where.line, 2U);
    EXPECT_EQ(t.programs[0].blocks[1].where.line, 4U);
    EXPECT_TRUE(rules_of(t).empty());
    // Without an O number the comment is the program's first block, as it always was.
    LoadedTape plain = load("%\n(HEADER)\nG90 G01 X1. F100\nM30\n%\n", {}, LoadOptions{Dialect::fanuc});
    ASSERT_EQ(plain.programs.size(), 1U);
    EXPECT_EQ(plain.programs[0].blocks.size(), 3U);
    EXPECT_FALSE(plain.programs[0].number);
}

TEST(Leader, RealCollegeProjectIsOneProgram) {
    SKIP_WITHOUT_SHARED_DATA("outside3/fanuc/rodolfo_new_college_project.nc");
    LoadedTape t = load(read_text(shared_data("outside3/fanuc/rodolfo_new_college_project.nc")), {},
                        LoadOptions{Dialect::automatic});
    EXPECT_EQ(t.dialect, Dialect::fanuc) << t.dialect_reason;
    ASSERT_EQ(t.programs.size(), 1U);
    EXPECT_EQ(t.programs[0].number, "O0001");
    for (const auto& f : lint(t)) {
        EXPECT_NE(f.rule, "program-end") << f.message;
        EXPECT_NE(f.rule, "unexpected-character") << f.message;  // item 5: ", R 15" is a corner word
    }
}

// Item 3: an O number on its own line after '%' is Fanuc's, with or without a label before.
TEST(Leader, AnONumberOnItsOwnLineAfterThePercentIsFanuc) {
    for (std::string label : {"", "PART 17 REV B\n", "(POSTED BY CAM)\n"}) {
        auto choice = guess_dialect(label + "%\nO1234\nN10 G90 G00 X0 Y0\nN20 G01 X10. Y5. F100.\nN30 M30\n%\n");
        EXPECT_EQ(choice.dialect, Dialect::fanuc) << label << choice.reason;
        EXPECT_NE(choice.reason.find("O program number"), std::string::npos) << choice.reason;
    }
}

// Item 5: Fanuc skips spaces, also between ',' and the corner word's letter.
TEST(Leader, CornerWordsWithASpace) {
    LoadedTape t = load("%\nO1\nG01 X92. Y50., R15. F100\nG01 Y0 , C 8.\nM30\n%\n", {}, LoadOptions{Dialect::fanuc});
    ASSERT_EQ(t.programs.size(), 1U);
    const auto& w = t.programs[0].blocks.at(1).words;
    ASSERT_EQ(w.size(), 5U);
    EXPECT_EQ(w[3].text, ",R15.");
    EXPECT_EQ(w[3].address, ',');
    EXPECT_EQ(t.programs[0].blocks.at(2).words.at(2).text, ",C8.");
    EXPECT_TRUE(rules_of(t).empty());
}

// Item 6: the dialect is chosen from whole lines. The shape of sergey_petlya_step.nc: a line starts at
// the sample's last byte; fed in pieces of 4 KiB the sample was cut in it ("G1 Y", a word
// with no digits), which tipped the choice to fanuc.
TEST(Leader, DialectSampleEndsAtALineEnd) {
    std::string text = "(Exported by FreeCAD)\nG17 G90\nG21\n";
    const std::string move = "G1 X-10.258 Y-19.582 Z-0.223 F400.000\n";
    while (text.size() + move.size() < dialect_sample_bytes) text += move;
    text += std::string(dialect_sample_bytes - 2 - text.size(), ' ') + "\n";  // the next line starts at its last byte
    for (int i = 0; i < 100; ++i) text += move;
    ASSERT_EQ(text[dialect_sample_bytes - 2], '\n');
    auto whole = guess_dialect(text);
    for (std::size_t piece : {std::size_t{4096}, std::size_t{65535}, std::size_t{65536}, std::size_t{1} << 20}) {
        LoadedTape t = load_in_pieces(text, Dialect::automatic, piece);
        EXPECT_EQ(t.dialect, whole.dialect) << piece << ": " << whole.reason;
    }
}

TEST(Leader, RealFreecadOutputIsLinuxcncAsItsFirstLines) {
    SKIP_WITHOUT_SHARED_DATA("outside3/cam/sergey_petlya_step.nc");
    std::string text = read_text(shared_data("outside3/cam/sergey_petlya_step.nc"));
    auto first_lines = text.substr(0, text.find("\n", 60000) + 1);
    EXPECT_EQ(guess_dialect(first_lines).dialect, Dialect::linuxcnc);
    EXPECT_EQ(guess_dialect(text).dialect, Dialect::linuxcnc) << guess_dialect(text).reason;
    EXPECT_EQ(load_in_pieces(text, Dialect::automatic, 4096).dialect, Dialect::linuxcnc);  // 16 pieces: 64 KiB
    EXPECT_EQ(load_in_pieces(text, Dialect::automatic, 65535).dialect, Dialect::linuxcnc);
}

namespace {

// Programs P: the real ones that start with '%' (after blank lines), and one written here so that the
// property is tested where ../shared/data is absent.
std::vector<std::pair<std::string, std::string>> programs_starting_with_percent() {
    std::vector<std::pair<std::string, std::string>> found = {
        {"hand-written",
         "\n%\nO0011 (PLATE)\nN10 G90 G54 G00 X0 Y0\nN20 G01 X10. X11. F100.\nN30 G71 P40 Q50\n"
         "N40 G01 X1.\nN50 M30\n%\n"}};
    std::string dir = shared_data_dir();
    if (dir.empty()) return found;
    std::vector<std::string> paths;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        std::string ext = e.path().extension().string();
        if (e.is_regular_file() && (ext == ".nc" || ext == ".NC" || ext == ".ngc")) paths.push_back(e.path().string());
    }
    std::sort(paths.begin(), paths.end());
    for (const auto& path : paths) {
        std::string text = read_text(path);
        auto first = text.find_first_not_of(" \t\r\n");
        if (first != std::string::npos && text[first] == '%' && text.find('\x1A') == std::string::npos)
            found.emplace_back(std::filesystem::relative(path, dir).string(), text);
    }
    return found;
}

// Leaders L as tapes and files carry them: comments, part names, set-up notes, blank lines, Cyrillic,
// CR LF, an O number in a drawing reference; none holds a '%'.
const std::vector<std::string> leaders = {
    "(POSTED BY CAM)\n",
    "PART 17 REV B\n",
    "\n\n(SETUP: VISE, JAWS 6MM)\n(T1 D10 END MILL)\n\n",
    "ДЕТАЛЬ 7-114 КОРПУС\r\n",
    "O1234 DRAWING 55-12 SHEET 2\n",
    "($Message(\"IMPORTANT! Load the machine settings\") )\r\n",
    "part 17 rev b, cut from 6061\n",
    " \t \r\n",
};

struct Listing {
    Dialect dialect;
    std::vector<std::string> programs;  // number and blocks, as written, with their lines
    std::vector<std::string> findings;  // rule, line, column
};

Listing listing(const std::string& text, Dialect d, std::uint64_t lines_before) {
    LoadedTape t = load(text, {}, LoadOptions{d});
    Listing l{t.dialect, {}, {}};
    for (const auto& p : t.programs) {
        l.programs.push_back("program " + p.number.value_or("") + " at " + std::to_string(p.start.line - lines_before));
        for (const auto& b : p.blocks)
            l.programs.push_back(std::to_string(b.where.line - lines_before) + " " + b.source);
    }
    for (const auto& f : lint(t))
        l.findings.push_back(std::string(f.rule) + " " +
                             (f.where.line ? std::to_string(*f.where.line - lines_before) : "-") + ":" +
                             std::to_string(f.where.column.value_or(0)));
    return l;
}

}  // namespace

// For any program P and leader L without '%': L + P lists the programs and findings of P alone, at the
// same places after L, and L as its label, in every dialect and as auto chooses.
TEST(Leader, AnyLeaderBeforeAnyProgramChangesNothingButTheLabel) {
    auto programs = programs_starting_with_percent();
    EXPECT_GE(programs.size(), shared_data_dir().empty() ? 1U : 6U);
    for (const auto& [name, p] : programs)
        for (const auto& l : leaders) {
            auto lines = static_cast<std::uint64_t>(std::count(l.begin(), l.end(), '\n'));
            for (Dialect d : every_dialect) {
                Listing alone = listing(p, d, 0), led = listing(l + p, d, lines);
                EXPECT_EQ(led.dialect, alone.dialect) << name << " after " << l;
                EXPECT_EQ(led.programs, alone.programs) << name << " after " << l << " in " << dialect_name(d);
                EXPECT_EQ(led.findings, alone.findings) << name << " after " << l << " in " << dialect_name(d);
                EXPECT_EQ(load(l + p, {}, LoadOptions{d}).label, l + load(p, {}, LoadOptions{d}).label)
                    << name << " after " << l << " in " << dialect_name(d);
            }
        }
}

// Item 12: words after a ';' on its line are one remark, one finding, not one a word.
TEST(Leader, ARemarkAfterASemicolonIsOneFinding) {
    for (Dialect d : {Dialect::fanuc, Dialect::gost}) {
        LoadedTape t = load("%\nO1\nG00 X0 Y0 ; Implement the changes suggested - DONE\nM30\n%\n", {}, LoadOptions{d});
        auto rules = rules_of(t);
        EXPECT_EQ(rules.size(), 1U) << dialect_name(d);
        ASSERT_FALSE(t.findings.empty());
        EXPECT_EQ(t.findings[0].where.line, 3U);
        EXPECT_NE(t.findings[0].message.find("Implement the changes suggested - DONE"), std::string::npos)
            << t.findings[0].message;
    }
}

TEST(Leader, RealRemarkAfterASemicolon) {
    SKIP_WITHOUT_SHARED_DATA("outside3/fanuc/rodolfo_new_college_project.nc");
    LoadedTape t = load(read_text(shared_data("outside3/fanuc/rodolfo_new_college_project.nc")), {},
                        LoadOptions{Dialect::automatic});
    auto on_76 =
        std::count_if(t.findings.begin(), t.findings.end(), [](const Finding& f) { return f.where.line == 76U; });
    EXPECT_EQ(on_76, 1);
}
