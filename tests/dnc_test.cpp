// The DNC service: requests read from punch-outs and checked as untrusted input, the library looked
// up, punch-outs filed, and tape dnc itself run over pseudo-terminals with the controls played here.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "dnc/punch_out.hpp"
#include "dnc_service_util.hpp"
#include "tape/dnc_request.hpp"
#include "tape/dnc_service.hpp"

namespace {

using namespace std::chrono_literals;
using tape::dnc::Request;

TEST(DncRequest, ProgramNamesInOrder) {
    auto r = tape::dnc::parse_request("%\nO9999\n( PRG = O1234 , O0012,bracket.nc )\nM30\n%\n");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->kind, Request::Kind::programs);
    EXPECT_EQ(r->names, (std::vector<std::string>{"O1234", "O0012", "bracket.nc"}));
    EXPECT_TRUE(r->refused.empty());
}

TEST(DncRequest, Restart) {
    auto r = tape::dnc::parse_request("%\n(restart=O1234, N50)\n%\n");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->kind, Request::Kind::restart);
    EXPECT_EQ(r->names, std::vector<std::string>{"O1234"});
    EXPECT_EQ(r->block, "N50");
    auto bad = tape::dnc::parse_request("(RESTART=O1234)");
    ASSERT_TRUE(bad);
    EXPECT_TRUE(bad->names.empty());
    ASSERT_EQ(bad->refused.size(), 1u);
}

TEST(DncRequest, NoneInAnOrdinaryProgram) {
    EXPECT_FALSE(tape::dnc::parse_request("%\nO1\nN10 G00 X1 (PROGRAM FOR BRACKET)\nM30\n%\n"));
    EXPECT_FALSE(tape::dnc::parse_request("(PRG=O1\n"));  // a comment never closed
}

// Every way out of the library a name from a line might try: refused, each with its reason.
TEST(DncRequest, PathTraversalRefused) {
    const std::string cases[] = {
        "../secret", "../../etc/passwd",   "/etc/passwd",           "a/b", "..", "O1..", ".hidden", "a\\b", "O12 3",
        "O1;rm",     std::string(65, 'A'), std::string("O1\0/x", 5)};
    for (const auto& name : cases) {
        std::string text = "(PRG=" + name + ")\n";
        auto r = tape::dnc::parse_request(text);
        ASSERT_TRUE(r) << name;
        EXPECT_TRUE(r->names.empty()) << name;
        ASSERT_EQ(r->refused.size(), 1u) << name;
        EXPECT_FALSE(tape::dnc::name_problem(name).empty()) << name;
    }
    EXPECT_NE(tape::dnc::name_problem("../x").find("a path"), std::string::npos);
    EXPECT_NE(tape::dnc::name_problem(std::string(65, 'A')).find("over-long"), std::string::npos);
    EXPECT_NE(tape::dnc::name_problem(std::string("a\0b", 3)).find("NUL"), std::string::npos);
    EXPECT_EQ(tape::dnc::name_problem(std::string(64, 'A')), "");
}

TEST(DncLibrary, FindsByStemCaseAndProgramNumber) {
    TempDir dir;
    std::ofstream(dir.file("O1234.nc")) << "%\nO1234\nM30\n%\n";
    std::ofstream(dir.file("bracket.NC")) << "%\nO0012 (BRACKET)\nM30\n%\n";
    std::ofstream(dir.file("flange.nc")) << "%\nO77\nM30\n%\n";
    std::ofstream(dir.file("flange-copy.nc")) << "%\nO77\nM30\n%\n";
    EXPECT_EQ(tape::dnc::find_program(dir.path, "O1234").path, dir.file("O1234.nc"));
    EXPECT_EQ(tape::dnc::find_program(dir.path, "o1234").path, dir.file("O1234.nc"));
    EXPECT_EQ(tape::dnc::find_program(dir.path, "BRACKET").path, dir.file("bracket.NC"));
    EXPECT_EQ(tape::dnc::find_program(dir.path, "O12").path, dir.file("bracket.NC"));
    auto two = tape::dnc::find_program(dir.path, "O77");
    EXPECT_EQ(two.path, "");
    EXPECT_NE(two.problem.find("ambiguous"), std::string::npos);
    EXPECT_EQ(tape::dnc::find_program(dir.path, "O999").problem, "not in the library");
}

// A file beside the library is never reached, whatever the name.
TEST(DncLibrary, NothingOutsideTheLibrary) {
    TempDir dir;
    std::filesystem::create_directory(dir.file("programs"));
    std::ofstream(dir.file("secret.nc")) << "%\nO1\nM30\n%\n";
    for (const char* name : {"../secret.nc", "../secret", "/etc/passwd", "..", "O1"})
        EXPECT_EQ(tape::dnc::find_program(dir.file("programs"), name).path, "") << name;
}

TEST(DncPunchOut, OnDiskAsItArrivesThenFiledBesideNeverReplacing) {
    TempDir dir;
    tape::DecodeOptions decode{.keep_going = true};
    std::ofstream(dir.file("O4321.nc")) << "an older punch-out\n";
    tape::dnc::PunchOutFile file(dir.path, "mill", decode);
    auto part = Control::iso("%\nO4321\nN10 G00 X1\n");
    file.append(part);
    ASSERT_TRUE(file.started());
    EXPECT_EQ(file.path().find(dir.path + "/FAILED-mill-"), 0u);
    EXPECT_EQ(read_text(file.path()), "%\nO4321\nN10 G00 X1\n");  // there before the end came
    file.append(Control::iso("M30\n%\n"));
    EXPECT_EQ(file.file_as("O4321"), dir.file("O4321-2.nc"));
    EXPECT_EQ(read_text(dir.file("O4321.nc")), "an older punch-out\n");
    EXPECT_EQ(read_text(dir.file("O4321-2.nc")), "%\nO4321\nN10 G00 X1\nM30\n%\n");
}

TEST(DncPunchOut, EndsAtTheClosingPercent) {
    auto code = tape::FrameCode::iso();
    tape::dnc::PunchOutWatch watch(code);
    std::size_t ended_at = 0, i = 0;
    for (auto f : Control::iso("%\n%\n(PRG=O1)\n%\nO2")) {
        ++i;
        if (watch.feed(f) && !ended_at) ended_at = i;
    }
    EXPECT_EQ(ended_at, std::string("%\n%\n(PRG=O1)\n%").size());
    EXPECT_TRUE(watch.complete());
}

TEST(DncPunchOut, ComparedWithTheLibrarysCopy) {
    TempDir dir;
    std::ofstream(dir.file("O1.nc")) << "%\r\nO1;\r\nN10 G00 X1;\r\nM30;\r\n%\r\n";
    EXPECT_EQ(tape::dnc::compare_with("%\nO1\nN10 G00 X1\nM30\n%\n", dir.file("O1.nc")), "same as the library's O1.nc");
    EXPECT_EQ(tape::dnc::compare_with("%\nO1\nN10 G00 X2\nM30\n%\n", dir.file("O1.nc")),
              "differs from the library's O1.nc from program line 2");
}

TEST(DncStatus, LinesRoundTrip) {
    tape::dnc::MachineStatus m{.name = "mill-1", .device = "serial:/dev/ttyS0"};
    m.state = tape::dnc::LineState::sending;
    m.program = "O1234";
    m.frames = 10;
    m.total = 100;
    m.sent = 3;
    m.last = "a\tline";
    auto back = tape::dnc::parse_status_lines(tape::dnc::status_lines({m}));
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].name, "mill-1");
    EXPECT_EQ(back[0].state, tape::dnc::LineState::sending);
    EXPECT_EQ(back[0].total, 100u);
    EXPECT_EQ(back[0].last, "a line");
}

}  // namespace
