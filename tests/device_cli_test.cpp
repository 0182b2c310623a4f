// The real `tape` binary driving real pseudo-terminals: feed, receive, read, punch, emulate.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <thread>

#include "pty_util.hpp"
#include "tape/encode.hpp"
#include "tape/line_state.hpp"
#include "tape/image.hpp"
#include "test_util.hpp"

extern char** environ;

using namespace tape;
using namespace std::chrono_literals;

namespace {

// One run of the tape binary, stdout and stderr to files.
class Process {
public:
    Process(const std::vector<std::string>& args, const TempDir& dir) : dir_(dir) {
        std::vector<std::string> argv_s = {TAPE_BINARY};
        argv_s.insert(argv_s.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (auto& a : argv_s) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t fa;
        posix_spawn_file_actions_init(&fa);
        posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
        posix_spawn_file_actions_addopen(&fa, 1, dir.file("stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&fa, 2, dir.file("stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (posix_spawn(&pid_, argv[0], &fa, nullptr, argv.data(), environ) != 0) throw std::runtime_error("spawn failed");
        posix_spawn_file_actions_destroy(&fa);
    }
    ~Process() {
        if (pid_ > 0) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
    }
    void interrupt() const { ::kill(pid_, SIGINT); }
    /// Exit status, or -1 when it had to be killed after timeout.
    int wait(std::chrono::milliseconds timeout = 10s) {
        auto end = std::chrono::steady_clock::now() + timeout;
        int status = 0;
        while (std::chrono::steady_clock::now() < end) {
            if (::waitpid(pid_, &status, WNOHANG) == pid_) {
                pid_ = -1;
                return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            }
            std::this_thread::sleep_for(5ms);
        }
        return -1;
    }
    std::string err() const { return read_text(dir_.file("stderr")); }

private:
    const TempDir& dir_;
    pid_t pid_ = -1;
};

std::vector<Frame> image_frames(const std::string& path) {
    std::string bytes = read_text(path);
    auto* f = image_format_for_path(path);
    return f->read({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
}

}  // namespace

TEST(CliFeed, SendsTheProgramThroughPausesExactlyOnce) {
    TempDir dir;
    Pty pty;
    std::string text = read_text(sample_path("gost-20999-format-example.txt"));
    auto expected = encode(text + "%", EncodeOptions{.leader = 5, .trailer = 5});
    Process tape({"feed", sample_path("gost-20999-format-example.txt"), pty.device("baud=38400&flow=xonxoff"), "--leader", "5",
                  "--trailer", "5", "--rate", "2000"},
                 dir);
    std::vector<std::uint8_t> got;
    int pauses = 0;
    while (got.size() < expected.size() && pty.receive(got, 5000ms) > 0) {
        if (got.size() > 40 * static_cast<std::size_t>(pauses + 1) && pauses < 4) {
            pty.send(dc3);
            pty.receive_until_quiet(got, 50ms);
            std::vector<std::uint8_t> quiet;
            pty.receive(quiet, 50ms);
            EXPECT_TRUE(quiet.empty());
            ++pauses;
            pty.send(dc1);
        }
    }
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(got, expected) << got.size() << " of " << expected.size();
    EXPECT_EQ(pauses, 4);
}

TEST(CliFeed, WaitXonGivesUpOnASilentController) {
    TempDir dir;
    Pty pty;
    Process tape({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device(), "--wait-xon", "--xon-timeout", "0.5"}, dir);
    EXPECT_EQ(tape.wait(), 3);
    EXPECT_NE(tape.err().find("no DC1 (XON)"), std::string::npos) << tape.err();
    std::vector<std::uint8_t> got;
    pty.receive(got, 10ms);
    EXPECT_TRUE(got.empty());
}

TEST(CliFeed, ControllerHangingUpEndsWithADeviceError) {
    TempDir dir;
    Pty pty;
    Process tape({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device(), "--rate", "1000"}, dir);
    std::vector<std::uint8_t> got;
    while (got.size() < 50) ASSERT_GT(pty.receive(got, 5000ms), 0U);
    pty.release_slave();
    pty.close_master();
    EXPECT_EQ(tape.wait(), 3);
    EXPECT_NE(tape.err().find("hung up"), std::string::npos) << tape.err();
}

TEST(CliFeed, CtrlCStopsCleanly) {
    TempDir dir;
    Pty pty;
    Process tape({"feed", sample_path("16k20f3s5-turning.iso.ptp"), pty.device(), "--rate", "1000"}, dir);
    std::vector<std::uint8_t> got;
    while (got.size() < 20) ASSERT_GT(pty.receive(got, 5000ms), 0U);
    pty.send(dc3);
    std::this_thread::sleep_for(50ms);
    tape.interrupt();
    EXPECT_EQ(tape.wait(), 130);
    EXPECT_NE(tape.err().find("stopped after"), std::string::npos) << tape.err();
}

TEST(CliReceive, KeepsTheProgramUpToThePercentAfterM02) {
    TempDir dir;
    Pty pty;
    Process tape({"receive", pty.device(), "-o", dir.file("in.ptp"), "--timeout", "5"}, dir);
    std::this_thread::sleep_for(200ms);  // let it open the line
    auto program = encode("%\nN1 G01 X1\nN2 M30\n%", EncodeOptions{.leader = 4, .trailer = 0});
    std::vector<std::uint8_t> wire = {dc2};
    wire.insert(wire.end(), program.begin(), program.end());
    wire.push_back(dc4);
    ASSERT_EQ(::write(pty.master, wire.data(), wire.size()), static_cast<ssize_t>(wire.size()));
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(image_frames(dir.file("in.ptp")), program);
    EXPECT_NE(tape.err().find("end of program"), std::string::npos) << tape.err();
}

TEST(CliRead, KeepsEveryFrameWhenTheOtherSideCloses) {
    TempDir dir;
    Pty pty;
    Process tape({"read", pty.device("baud=9600&flow=none"), "-o", dir.file("in.holes"), "--timeout", "5"}, dir);
    std::this_thread::sleep_for(200ms);
    auto frames = image_frames(sample_path("16k20f3s5-turning.iso.ptp"));
    ASSERT_EQ(::write(pty.master, frames.data(), 200), 200);
    std::this_thread::sleep_for(100ms);
    ASSERT_EQ(::write(pty.master, frames.data() + 200, frames.size() - 200), static_cast<ssize_t>(frames.size() - 200));
    std::this_thread::sleep_for(200ms);
    pty.release_slave();
    pty.close_master();
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(image_frames(dir.file("in.holes")), frames);
}

TEST(CliRead, RefusesAnExistingOutputWithoutForce) {
    TempDir dir;
    Pty pty;
    std::ofstream(dir.file("in.ptp")) << "keep";
    Process tape({"read", pty.device(), "-o", dir.file("in.ptp"), "--timeout", "1"}, dir);
    EXPECT_EQ(tape.wait(), 2);
    EXPECT_EQ(read_text(dir.file("in.ptp")), "keep");
}

TEST(CliPunch, SendsEveryFrameOfTheImage) {
    TempDir dir;
    Pty pty;
    Process tape({"punch", sample_path("16k20f3s5-turning.eia.ptp"), pty.device("baud=115200&flow=none"), "--rate", "5000"}, dir);
    auto frames = image_frames(sample_path("16k20f3s5-turning.eia.ptp"));
    std::vector<std::uint8_t> got;
    pty.receive_until_size(got, frames.size(), 10s);
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    EXPECT_EQ(got, frames);
}

TEST(CliEmulate, ReadsTheProgramOnDc1AndRewindsAtItsEnd) {
    TempDir dir;
    Pty pty;
    Process tape({"emulate", sample_path("gost-20999-format-example.iso.ptp"), pty.device(), "--rate", "3000"}, dir);
    pty.send(dc1);
    std::vector<std::uint8_t> got;
    auto frames = image_frames(sample_path("gost-20999-format-example.iso.ptp"));
    std::vector<Frame> program(frames.begin() + 100, frames.end() - 100);  // no leader; stops after M02's LF
    pty.receive_until_size(got, program.size(), 10s);
    pty.receive_until_quiet(got, 200ms);
    EXPECT_EQ(got, program);
    tape.interrupt();
    EXPECT_EQ(tape.wait(), 0) << tape.err();
    std::string log = tape.err();
    EXPECT_NE(log.find("frame 101: start"), std::string::npos) << log;
    EXPECT_NE(log.find("end of program"), std::string::npos) << log;
    EXPECT_NE(log.find("frame 101: rewound to the '%' stop"), std::string::npos) << log;
}
