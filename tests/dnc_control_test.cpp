// tape dnc against a hostile local user and a careless config: symbolic links out of the library, a
// runtime folder open to others, idle peers on the control socket, refusals said and answered, and the
// defaults the man page gives.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>

#include "dnc_service_util.hpp"
#include "tape/dnc_service.hpp"

namespace {

using namespace std::chrono_literals;

// A link to a file outside the library is sent neither by its name nor by the number of what it holds.
TEST(DncControl, SymbolicLinksInTheLibraryNeverSent) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    std::ofstream(run.dir.file("outside.nc")) << "%\nO5555\n(OUTSIDE)\nM30\n%\n";
    std::filesystem::create_symlink("/etc/passwd", run.programs() + "/passwd");
    std::filesystem::create_symlink(run.dir.file("outside.nc"), run.programs() + "/fixture.nc");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    for (const char* name : {"passwd", "fixture", "O5555"}) {
        run.controls[0]->punch("%\n(PRG=" + std::string(name) + ")\n%\n");
        ASSERT_TRUE(run.wait_log("no program '" + std::string(name) + "' sent: not in the library", 5s)) << run.log();
    }
    EXPECT_EQ(run.controls[0]->receive_text(300ms, 1s), "");
    EXPECT_EQ(run.log().find("sent passwd"), std::string::npos) << run.log();
}

// A runtime folder open to others is refused, and left as it was (a 1777 folder keeps its mode).
TEST(DncControl, RuntimeFolderOpenToOthersRefusedUnchanged) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    ::chmod(run.dir.file("run").c_str(), 01777);
    run.write_config();
    TempDir out;
    Process service({"dnc", "--config", run.config()}, out);
    EXPECT_EQ(service.wait(10s), 2);
    EXPECT_NE(service.err().find("the runtime folder is open to others (mode 1777)"), std::string::npos)
        << service.err();
    struct stat st {};
    ASSERT_EQ(::stat(run.dir.file("run").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 01777u);
}

// A runtime folder that is not there is made owner-only; the socket is 0600 as tape(1) says.
TEST(DncControl, RuntimeFolderMadeOwnerOnlySocket0600) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    std::filesystem::remove(run.dir.file("run"));
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    struct stat dir {
    }, sock{};
    ASSERT_EQ(::stat(run.dir.file("run").c_str(), &dir), 0);
    ASSERT_EQ(::stat(run.dir.file("run/control.sock").c_str(), &sock), 0);
    EXPECT_EQ(dir.st_mode & 07777, 0700u);
    EXPECT_EQ(sock.st_mode & 0777, 0600u);
}

int connect_to(const std::string& path) {
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    std::snprintf(a.sun_path, sizeof a.sun_path, "%s", path.c_str());
    int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) ::close(fd), fd = -1;
    return fd;
}

// Twenty peers that connect and say nothing keep no status waiting; status reads only the socket's
// place from a config the service could not run with.
TEST(DncControl, IdlePeersKeepNoStatusWaiting) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::vector<int> idle;
    for (int i = 0; i < 20; ++i) idle.push_back(connect_to(run.dir.file("run/control.sock")));
    ASSERT_EQ(std::count(idle.begin(), idle.end(), -1), 0);
    std::ofstream(run.config(), std::ios::app) << "rat = 5\n";  // being edited: no config to serve with
    TempDir out;
    auto asked = std::chrono::steady_clock::now();
    Process status({"dnc", "status", "--config", run.config()}, out);
    ASSERT_EQ(status.wait(10s), 0) << status.err();
    EXPECT_LT(std::chrono::steady_clock::now() - asked, 1500ms);
    EXPECT_NE(read_text(out.file("stdout")).find("m0 "), std::string::npos) << read_text(out.file("stdout"));
    TempDir by_socket;
    Process status2({"dnc", "status", "--socket", run.dir.file("run/control.sock")}, by_socket);
    ASSERT_EQ(status2.wait(10s), 0) << status2.err();
    EXPECT_NE(read_text(by_socket.file("stdout")).find("listening"), std::string::npos);
    for (int fd : idle) ::close(fd);
}

TEST(DncControl, ReplyOnlyToAWholeStatusLine) {
    auto status = [] { return std::string("tape-dnc status 1\n"); };
    EXPECT_EQ(tape::dnc::control_reply("stat", false, status), std::nullopt);
    EXPECT_EQ(tape::dnc::control_reply("status\n", false, status), status());
    EXPECT_EQ(tape::dnc::control_reply("status\r\n", false, status), status());
    EXPECT_EQ(tape::dnc::control_reply("status", true, status), status());
    EXPECT_EQ(tape::dnc::control_reply("statusx\n", false, status), "");
    EXPECT_EQ(tape::dnc::control_reply(std::string(64, 's'), false, status), "");
}

// Empty names are one line; a refused name is answered with a comment when answer_unknown says so.
TEST(DncControl, RefusalsSaidOnceAndAnswered) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1234.nc", "%\nO1234\nM30\n%\n");
    run.write_config("answer_unknown = true");
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(PRG=O1234,,,,,,,,../x)\n%\n");
    std::string got = run.controls[0]->receive_text(500ms, 10s);
    ASSERT_TRUE(run.wait_log("sent O1234 ", 5s)) << run.log();
    EXPECT_EQ(run.log_count("request refused"), 2u) << run.log();
    EXPECT_NE(run.log().find("request refused: 7 empty names"), std::string::npos) << run.log();
    EXPECT_NE(got.find("(REFUSED 7 EMPTY NAMES"), std::string::npos) << got;
    EXPECT_NE(got.find("A PATH"), std::string::npos) << got;
    EXPECT_NE(got.find("O1234\nM30"), std::string::npos) << got;
}

// The defaults tape(1) gives are the service's.
TEST(DncControl, ManPageGivesTheBurstDefault) {
    std::string man = read_text(std::string(TAPE_SOURCE_DIR) + "/man/tape.1");
    auto at = man.find("\\fBburst\\fR (frames");
    ASSERT_NE(at, std::string::npos);
    EXPECT_NE(man.substr(at, 200).find("default " + std::to_string(tape::dnc::MachineSettings{}.burst) + ":"),
              std::string::npos)
        << man.substr(at, 200);
}

}  // namespace

namespace {

// machine = "fanuc-0" puts the profile's line (4800 baud, 7 bits, 2 stop bits, even parity) into the
// device string where it does not say otherwise; the string's own flow=none stays.
TEST(DncControl, MachineProfileSetsTheSerialLine) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.write_config("machine = \"fanuc-0\"", "flow=none");
    ASSERT_TRUE(run.start()) << run.log();
    TempDir out;
    Process status({"dnc", "status", "--config", run.config()}, out);
    ASSERT_EQ(status.wait(10s), 0) << status.err();
    std::string text = read_text(out.file("stdout"));
    EXPECT_NE(text.find("?flow=none&baud=4800&bits=7&stop=2&parity=even"), std::string::npos) << text;
}

}  // namespace
