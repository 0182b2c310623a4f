// tape dnc over pseudo-terminals: where a punch-out ends and what it is. A request only when it holds
// nothing else, punch-outs cut at their closing '%' (what follows in the same read is the next), a full
// received/ folder, and noise on the line.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>

#include <random>

#include "dnc_service_util.hpp"

namespace {

using namespace std::chrono_literals;

// A program of n blocks with number `number`; `extra` stands as its third line.
std::string program(const std::string& number, int blocks, const std::string& extra = "") {
    std::string text = "%\n" + number + "\nN1 G21 G90\n" + extra;
    for (int i = 1; i <= blocks; ++i) text += "N" + std::to_string(10 * i) + " G01 X" + std::to_string(i) + ". Y-1.\n";
    return text + "M30\n%\n";
}

// The 203-line program that names another in a comment is filed; nothing is sent for it.
TEST(DncPunchOuts, ProgramMentioningARequestIsFiledNotTaken) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1234.nc", "%\nO1234\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::string o2001 = program("O2001", 198, "(PRG=O1234)\n");  // the comment on line 4
    run.controls[0]->punch(o2001);
    ASSERT_TRUE(run.wait_log("filed as", 10s)) << run.log();
    EXPECT_EQ(read_text(run.received() + "/O2001.nc"), o2001);
    EXPECT_NE(run.log().find("it holds (PRG=O1234) among other text: a program, not a request"), std::string::npos)
        << run.log();
    EXPECT_EQ(run.controls[0]->receive_text(300ms, 1s), "");
    EXPECT_EQ(run.log_count("m0: request"), 0u) << run.log();
}

// Two programs in one write: two files, each with its own text.
TEST(DncPunchOuts, BackToBackProgramsFiledApart) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::string a = program("O1111", 20), b = program("O2222", 30);
    run.controls[0]->punch(a + b);
    ASSERT_TRUE(run.wait_log("filed as", 10s, 2)) << run.log();
    EXPECT_EQ(run.received_files(), (std::vector<std::string>{"O1111.nc", "O2222.nc"})) << run.log();
    EXPECT_EQ(read_text(run.received() + "/O1111.nc"), a);
    EXPECT_EQ(read_text(run.received() + "/O2222.nc"), b);
}

// A request and a program at once: the program sent, the other filed.
TEST(DncPunchOuts, RequestThenProgramBothHandled) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1.nc", "%\nO1\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::string o3333 = program("O3333", 5);
    run.controls[0]->punch("%\n(PRG=O1)\n%\n" + o3333);
    ASSERT_TRUE(run.wait_log("filed as", 10s)) << run.log();
    ASSERT_TRUE(run.wait_log("sent O1 ", 10s)) << run.log();
    EXPECT_EQ(read_text(run.received() + "/O3333.nc"), o3333);
    EXPECT_NE(run.controls[0]->receive_text(300ms, 5s).find("O1\nM30"), std::string::npos);
}

// Fifty requests in one burst (the rest of them read while the first are answered): fifty answers.
TEST(DncPunchOuts, BurstOfRequestsAllAnswered) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1.nc", "%\nO1\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::string burst;
    for (int i = 0; i < 50; ++i) burst += "%\n(PRG=O1)\n%\n";
    run.controls[0]->punch(burst);
    std::vector<std::uint8_t> got;
    run.controls[0]->pty.receive_until_quiet(got, 1500ms, 60s);
    std::string text = Control::text_of(got);
    std::size_t answers = 0;
    for (auto at = text.find("O1\nM30\n%"); at != std::string::npos; at = text.find("O1\nM30\n%", at + 1)) ++answers;
    EXPECT_EQ(answers, 50u) << run.log();
    EXPECT_TRUE(run.wait_log("sent O1 ", 5s, 50)) << run.log();
    EXPECT_EQ(run.log_count("request (PRG=O1)"), 50u) << run.log();
    EXPECT_TRUE(run.received_files().empty());
}

// received/ on a small file system of its own, mounted for the test (root only).
struct SmallFolder {
    std::string path, error;
    bool mounted = false;
    SmallFolder(const std::string& at, const std::string& size) : path(at) {
        if (::mount("tmpfs", at.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0)
            mounted = true;
        else
            error = std::string("cannot mount a tmpfs for a full disk: ") + std::strerror(errno);
    }
    ~SmallFolder() {
        if (mounted) ::umount2(path.c_str(), MNT_DETACH);
    }
};

// A full disk: what was written keeps its FAILED name, the rest of the punch-out is dropped until the
// line is quiet and said; once there is room a punch-out is filed whole, nothing else under a real name.
TEST(DncPunchOuts, FullReceivedFolderDropsTheRestUntilQuiet) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    SmallFolder small(run.received(), "16k");
    if (!small.mounted) GTEST_SKIP() << small.error;
    std::string filler(12 * 1024, 'x');
    std::ofstream(run.received() + "/filler") << filler;
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::string o7777 = program("O7777", 600);  // some 14 KB: more than the 4 KB left
    run.controls[0]->punch(o7777);
    ASSERT_TRUE(run.wait_log("dropped until the line was quiet", 15s)) << run.log();
    EXPECT_NE(run.log().find("No space left on device"), std::string::npos) << run.log();
    std::filesystem::remove(run.received() + "/filler");
    std::string o8888 = program("O8888", 20);
    run.controls[0]->punch(o8888);
    ASSERT_TRUE(run.wait_log("filed as", 10s)) << run.log();
    run.service->signal(SIGTERM);
    EXPECT_EQ(run.service->wait(5s), 0);
    auto files = run.received_files();
    EXPECT_EQ(read_text(run.received() + "/O8888.nc"), o8888);
    for (const auto& f : files) {
        if (f == "O8888.nc") continue;
        EXPECT_EQ(f.rfind("FAILED-m0-", 0), 0u) << f;  // no fragment under a program's name
        EXPECT_EQ(o7777.rfind(read_text(run.received() + "/" + f), 0), 0u) << f << ": the start of O7777 only";
    }
    EXPECT_LE(files.size(), 2u) << run.log();
    EXPECT_EQ(run.log_count("<3>m0: received: "), 1u) << run.log();
}

// Noise with many a '%' in it: one FAILED file for the whole noisy spell, nothing filed as a program.
TEST(DncPunchOuts, NoiseKeptAsOneFailedFile) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1.nc", "%\nO1\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::mt19937 random(11);
    std::vector<std::uint8_t> noise(24000);
    for (auto& b : noise) b = static_cast<std::uint8_t>(random());
    std::size_t percents = std::count(noise.begin(), noise.end(), 0xA5);  // '%' with even parity
    ASSERT_GT(percents, 50u);
    ASSERT_EQ(::write(run.controls[0]->pty.master, noise.data(), noise.size()), 24000);
    ASSERT_TRUE(run.wait_log("noise on the line", 15s)) << run.log();
    run.controls[0]->punch("%\n(PRG=O1)\n%\n");  // the line serves again
    EXPECT_EQ(run.controls[0]->receive_text(500ms, 10s).find("%\nO1\nM30\n%\n") != std::string::npos, true);
    auto files = run.received_files();
    ASSERT_EQ(files.size(), 1u) << run.log();
    EXPECT_EQ(files[0].rfind("FAILED-m0-", 0), 0u);
    EXPECT_EQ(run.log_count("filed as"), 0u) << run.log();
    EXPECT_EQ(run.log_count("noise on the line"), 1u) << run.log();
}

}  // namespace
