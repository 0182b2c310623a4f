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
#include "tape/error.hpp"

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

// A request is a punch-out that holds nothing else: a program that mentions one is a program.
TEST(DncRequest, OnlyAPunchOutOfNothingElse) {
    for (const char* request : {"%\n(PRG=O1)\n%\n", "(PRG=O1)", "%\r\nO9999 (PRG=O1);\r\nM30;\r\n%\r\n",
                                "%\n:9999\nN1 (PRG=O1)\nN2 M02\n%\n", "%1234\n(RESTART=O1,N5)\nM99\n"})
        EXPECT_TRUE(tape::dnc::parse_request(request)) << request;
    std::string program = "%\nO2001\nN10 G21\n(PRG=O1234)\n";
    for (int i = 0; i < 200; ++i) program += "N" + std::to_string(20 + i) + " G01 X1.\n";
    for (const std::string& text : {program + "M30\n%\n", std::string("%\n(PRG=O1)\n(PRG=O2)\n%\n"),
                                    std::string("%\n(PRG=O1)\nG00 X1\n%\n"), std::string("(MILL 3)\n(PRG=O1)\n")}) {
        EXPECT_FALSE(tape::dnc::parse_request(text)) << text;
        EXPECT_TRUE(tape::dnc::request_comment_in(text)) << text;  // said in the log when it is filed
    }
}

// Empty names are one refusal, and a thousand bad names a few lines.
TEST(DncRequest, RefusalsCountedNotRepeated) {
    auto r = tape::dnc::parse_request("(PRG=O1234,,,,, ,)");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->names, std::vector<std::string>{"O1234"});
    ASSERT_EQ(r->refused.size(), 1u);
    EXPECT_EQ(r->refused[0], "6 empty names (commas with nothing between them)");
    std::string many = "(PRG=";
    for (int i = 0; i < 1000; ++i) many += "../x,";
    r = tape::dnc::parse_request(many + "O1)");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->names, std::vector<std::string>{"O1"});
    ASSERT_EQ(r->refused.size(), 9u);
    EXPECT_EQ(r->refused.back(), "992 more name(s) refused, not listed");
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

// A symbolic link in the library is no program of it: neither by its name nor by the number of what
// it points to.
TEST(DncLibrary, SymbolicLinksNeverFollowed) {
    TempDir dir;
    std::filesystem::create_directory(dir.file("programs"));
    std::ofstream(dir.file("outside.nc")) << "%\nO5555\nM30\n%\n";
    std::filesystem::create_symlink("/etc/passwd", dir.file("programs/passwd"));
    std::filesystem::create_symlink(dir.file("outside.nc"), dir.file("programs/O5555.nc"));
    std::filesystem::create_symlink(dir.file("outside.nc"), dir.file("programs/fixture.nc"));
    std::ofstream(dir.file("programs/O1.nc")) << "%\nO1\nM30\n%\n";
    for (const char* name : {"passwd", "O5555", "O5555.nc", "fixture", "5555"})
        EXPECT_EQ(tape::dnc::find_program(dir.file("programs"), name).path, "") << name;
    EXPECT_EQ(tape::dnc::find_program(dir.file("programs"), "O1").path, dir.file("programs/O1.nc"));
    // A file made a link after it was found is not read through it either.
    std::filesystem::remove(dir.file("programs/O1.nc"));
    std::filesystem::create_symlink("/etc/passwd", dir.file("programs/O1.nc"));
    EXPECT_THROW(tape::dnc::read_program(dir.file("programs/O1.nc")), tape::Error);
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

// How many frames of text the watch takes as one punch-out's before it ends.
std::size_t taken_of(std::string_view text) {
    static const auto code = tape::FrameCode::iso();
    tape::dnc::PunchOutWatch watch(code);
    std::size_t taken = 0;
    for (auto f : Control::iso(text)) taken += watch.take(f);
    return taken;
}

TEST(DncPunchOut, EndsAtTheClosingPercentAndItsLineEnd) {
    EXPECT_EQ(taken_of("%\n%\n(PRG=O1)\n%\nO2"), std::string("%\n%\n(PRG=O1)\n%\n").size());
    EXPECT_EQ(taken_of("%\nO1\nM30\n%\r\n%\nO2\n"), std::string("%\nO1\nM30\n%\r\n").size());
    EXPECT_EQ(taken_of("%\nO1\nM30\n%%\nO2\n"), std::string("%\nO1\nM30\n%").size());  // the next one's '%'
    auto code = tape::FrameCode::iso();
    tape::dnc::PunchOutWatch watch(code);
    for (auto f : Control::iso("%\nO1\nM30\n%")) EXPECT_TRUE(watch.take(f));
    EXPECT_TRUE(watch.closing());
    EXPECT_TRUE(watch.complete());
    EXPECT_FALSE(watch.ended());
}

// Noise: once a quarter of the punched frames are bad, no '%' ends the punch-out.
TEST(DncPunchOut, NoiseIsNotCutAtItsPercents) {
    auto code = tape::FrameCode::iso();
    tape::dnc::PunchOutWatch watch(code);
    std::vector<std::uint8_t> frames = Control::iso("%\nAB");
    for (std::uint8_t bad : {0x01, 0x02, 0x04, 0x07, 0x08, 0x10}) frames.push_back(bad);  // odd parity
    for (auto f : Control::iso("%\nO1\n%\n")) frames.push_back(f);
    for (auto f : frames) EXPECT_TRUE(watch.take(f));
    EXPECT_FALSE(watch.ended());
    EXPECT_TRUE(watch.noise());
    EXPECT_EQ(watch.bad_frames(), 6u);
}

// What follows a punch-out's end in the same read is kept for the next; nothing is lost or doubled.
TEST(DncPunchOut, ReceptionCutsAReadAtTheEnd) {
    TempDir dir;
    auto code = tape::FrameCode::iso();
    std::vector<std::uint8_t> rest;
    tape::dnc::Reception rx(code, dir.path, "m", tape::DecodeOptions{.keep_going = true}, 1 << 20, rest);
    auto read = Control::iso("%\nO1111\nM30\n%\n%\nO2222\nM30\n%\n");
    bool ended = false;
    for (auto f : read) ended = rx.ends_after(f) || ended;
    rx.sink(read);
    EXPECT_TRUE(ended);
    EXPECT_EQ(read_text(rx.file.path()), "%\nO1111\nM30\n%\n");
    EXPECT_EQ(Control::text_of(rest), "%\nO2222\nM30\n%\n");
    EXPECT_EQ(rx.frames + rest.size(), read.size());
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
