// tape dnc as a real process over pseudo-terminals: the controls that request, punch out, pause with
// XOFF, hang up, send garbage or flood, run out of buffer, and the signals that reload and end it.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <random>
#include <set>

#include "dnc_service_util.hpp"

namespace {

using namespace std::chrono_literals;

const std::string program_1234 =
    "%\nO1234 (BRACKET)\nN10 G21 G17 G90\nN20 T1 M06\nN30 S1200 M03\nN40 G00 X10. Y10. Z5.\nN50 G01 Z-1. F100.\n"
    "N60 X20.\nN70 M30\n%\n";

// A long program: n blocks.
std::string long_program(int blocks) {
    std::string text = "%\nO2000\n";
    for (int i = 1; i <= blocks; ++i) text += "N" + std::to_string(i * 10) + " G01 X" + std::to_string(i) + ". Y1.\n";
    return text + "M30\n%\n";
}

// The program's text as it came, from its first '%' on.
std::string from_percent(const std::string& text) {
    auto at = text.find('%');
    return at == std::string::npos ? "" : text.substr(at);
}

TEST(DncService, RequestAnsweredWithTheProgram) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1234.nc", program_1234);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(PRG=O1234)\n%\n");
    EXPECT_EQ(from_percent(run.controls[0]->receive_text(500ms, 10s)), program_1234);
    ASSERT_TRUE(run.wait_log("done", 5s)) << run.log();
    EXPECT_NE(run.log().find("<6>m0: sent O1234"), std::string::npos) << run.log();
    EXPECT_TRUE(run.received_files().empty());  // a request is no program to file
}

TEST(DncService, SeveralNamesInOrderUnknownLogged) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1.nc", "%\nO1\nM30\n%\n");
    run.add_program("O2.nc", "%\nO2\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(PRG=O2,NOPE,O1)\n%\n");
    std::string got = run.controls[0]->receive_text(500ms, 10s);
    auto o2 = got.find("O2\n"), o1 = got.find("O1\n");
    ASSERT_NE(o2, std::string::npos) << got;
    ASSERT_NE(o1, std::string::npos) << got;
    EXPECT_LT(o2, o1);
    ASSERT_TRUE(run.wait_log("done", 5s, 2)) << run.log();
    EXPECT_NE(run.log().find("<4>m0: no program 'NOPE' sent: not in the library"), std::string::npos) << run.log();
}

TEST(DncService, PathTraversalFromTheLineRefusedAndLogged) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    std::ofstream(run.dir.file("secret.nc")) << "%\nO1\n(SECRET)\nM30\n%\n";
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(PRG=../secret.nc,/etc/passwd)\n%\n");
    ASSERT_TRUE(run.wait_log("request refused", 5s, 2)) << run.log();
    EXPECT_EQ(run.controls[0]->receive_text(500ms, 2s), "");
    EXPECT_NE(run.log().find("'../secret.nc': a path"), std::string::npos) << run.log();
}

TEST(DncService, PunchOutsFiledByNumberNeverReplaced) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O4321.nc", "%\nO4321\nN10 G00 X1\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\nO4321\nN10 G00 X1\nM30\n%\n");
    ASSERT_TRUE(run.wait_log("filed as", 5s)) << run.log();
    run.controls[0]->punch("%\nO4321\nN10 G00 X2\nM30\n%\n");
    ASSERT_TRUE(run.wait_log("filed as", 5s, 2)) << run.log();
    EXPECT_EQ(run.received_files(), (std::vector<std::string>{"O4321-2.nc", "O4321.nc"}));
    EXPECT_EQ(read_text(run.received() + "/O4321-2.nc"), "%\nO4321\nN10 G00 X2\nM30\n%\n");
    EXPECT_NE(run.log().find("same as the library's O4321.nc"), std::string::npos) << run.log();
    EXPECT_NE(run.log().find("differs from the library's O4321.nc from program line 2"), std::string::npos);
}

TEST(DncService, HangUpMidPunchOutKeptAsFailed) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\nO55\nN10 G00 X1\nN20 G01");
    ASSERT_NE(run.wait_received("%\nO55\nN10 G00 X1\nN20 G01", 5s), "") << run.log();  // all taken, then the hang-up
    run.controls[0]->pty.close_master();
    ASSERT_TRUE(run.wait_log("hung up", 5s)) << run.log();
    auto files = run.received_files();
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].rfind("FAILED-m0-", 0), 0u);
    EXPECT_EQ(read_text(run.received() + "/" + files[0]), "%\nO55\nN10 G00 X1\nN20 G01");
}

TEST(DncService, XoffPausesTheSenderNothingLostOrDoubled) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    std::string program = long_program(150);
    run.add_program("O2000.nc", program);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    const Control& c = *run.controls[0];
    c.punch("%\n(PRG=O2000)\n%\n");
    std::vector<std::uint8_t> got;
    c.pty.receive_until_size(got, 300, 10s);
    c.pty.send(tape::dc3);
    std::size_t at_xoff = got.size();
    c.pty.receive_until_quiet(got, 300ms, 3s);
    EXPECT_LE(got.size() - at_xoff, 32u) << "frames sent after DC3";  // one burst, and one under way
    std::size_t paused = got.size();
    c.pty.receive(got, 700ms);
    EXPECT_EQ(got.size(), paused) << "frames sent while paused";
    c.pty.send(tape::dc1);
    c.pty.receive_until_quiet(got, 500ms, 20s);
    EXPECT_EQ(from_percent(Control::text_of(got)), program);
    ASSERT_TRUE(run.wait_log("1 pause(s): done", 5s)) << run.log();
}

// A control that executes characters from a buffer of `capacity` at `pace` a second and raises an
// overrun alarm when one arrives with the buffer full; with XON/XOFF it says DC3 at high water and
// DC1 at low water, as a Fanuc control's reader interface does.
struct PacedControl {
    const Pty& pty;
    double pace;
    bool xonxoff;
    std::size_t capacity = 64, high = 24, low = 8;  // room after DC3 for a burst of 16 and one under way
    bool alarm = false;
    std::vector<std::uint8_t> taken{};

    void run(std::string_view request, std::size_t expect, std::chrono::milliseconds limit) {
        Control::punch_on(pty, request);  // ready to take the answer from the first frame on
        auto end = std::chrono::steady_clock::now() + limit, last = std::chrono::steady_clock::now();
        double buffered = 0;
        bool paused = false;
        while (taken.size() < expect && std::chrono::steady_clock::now() < end) {
            std::vector<std::uint8_t> got;
            pty.receive(got, 5ms);
            auto now = std::chrono::steady_clock::now();
            buffered = std::max(0.0, buffered - pace * std::chrono::duration<double>(now - last).count());
            last = now;
            for (auto b : got) {
                if (buffered + 1 > capacity) alarm = true;
                buffered += 1;
                taken.push_back(b);
            }
            if (xonxoff && paused != (buffered >= high || (paused && buffered > low))) {
                paused = !paused;
                pty.send(paused ? tape::dc3 : tape::dc1);
            }
        }
    }
};

TEST(DncService, ControlsThatRunOutOfBufferRaiseNoAlarm) {
    DncRun run(3);
    DNC_OR_SKIP(run);
    std::string program = long_program(60);
    run.add_program("O2000.nc", program);
    // m0: XON/XOFF at the line's speed; m1: no flow control, paced at the control's speed; m2: no flow
    // control at the line's speed, which a control at 300 characters a second cannot take.
    run.write_config("", "baud=9600&flow=xonxoff", {"", "flow = \"none\"\nrate = 290", "flow = \"none\""});
    ASSERT_TRUE(run.start()) << run.log();
    std::vector<std::unique_ptr<PacedControl>> controls;
    std::vector<std::thread> threads;
    auto frames = Control::iso(program).size() + 8;  // leader and trailer
    for (std::size_t i = 0; i < 3; ++i) {
        controls.push_back(std::make_unique<PacedControl>(PacedControl{run.controls[i]->pty, 300, i == 0}));
    }
    for (auto& c : controls) threads.emplace_back([&c, frames] { c->run("%\n(PRG=O2000)\n%\n", frames, 30s); });
    for (auto& t : threads) t.join();
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(from_percent(Control::text_of(controls[i]->taken)), program) << i;
    EXPECT_FALSE(controls[0]->alarm) << "XON/XOFF";
    EXPECT_FALSE(controls[1]->alarm) << "paced at the control's speed";
    EXPECT_TRUE(controls[2]->alarm) << "the model control must alarm when blocks come faster than its pace";
}

TEST(DncService, GarbageAndFloodKeptAsFailedThenRequestsStillAnswered) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1.nc", "%\nO1\nM30\n%\n");
    run.write_config("max_punch_out = 4096");
    ASSERT_TRUE(run.start()) << run.log();
    std::mt19937 random(7);
    std::vector<std::uint8_t> garbage(20000);
    for (auto& b : garbage) b = static_cast<std::uint8_t>('A' + random() % 26);  // no '%': never complete
    ASSERT_EQ(::write(run.controls[0]->pty.master, garbage.data(), garbage.size()), 20000);
    ASSERT_TRUE(run.wait_log("flood dropped", 10s)) << run.log();
    run.controls[0]->punch("%\n(PRG=O1)\n%\n");
    EXPECT_EQ(from_percent(run.controls[0]->receive_text(500ms, 10s)), "%\nO1\nM30\n%\n");
    auto files = run.received_files();
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].rfind("FAILED-m0-", 0), 0u);
    EXPECT_GE(std::filesystem::file_size(run.received() + "/" + files[0]), 4096u);
}

TEST(DncService, AStalledLineDelaysNoOther) {
    DncRun run(2);
    DNC_OR_SKIP(run);
    run.add_program("O2000.nc", long_program(300));
    run.add_program("O1.nc", "%\nO1\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(PRG=O2000)\n%\n");
    std::vector<std::uint8_t> got;
    run.controls[0]->pty.receive_until_size(got, 50, 5s);
    run.controls[0]->pty.send(tape::dc3);  // and never a DC1: m0 waits for ever
    run.controls[1]->punch("%\n(PRG=O1)\n%\n");
    EXPECT_EQ(from_percent(run.controls[1]->receive_text(300ms, 5s)), "%\nO1\nM30\n%\n");
    run.controls[1]->punch("%\nO77\nM30\n%\n");
    ASSERT_TRUE(run.wait_log("filed as", 5s)) << run.log();
}

TEST(DncService, SigtermEndsSoonKeepingPartialPunchOutsAsFailed) {
    DncRun run(2);
    DNC_OR_SKIP(run);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\nO10\nN10 G00");
    run.controls[1]->punch("%\nO11\nN10 X");
    ASSERT_NE(run.wait_received("%\nO10\nN10 G00", 5s), "") << run.log();
    ASSERT_NE(run.wait_received("%\nO11\nN10 X", 5s), "") << run.log();
    auto asked = std::chrono::steady_clock::now();
    run.service->signal(SIGTERM);
    EXPECT_EQ(run.service->wait(5s), 0);
    EXPECT_LT(std::chrono::steady_clock::now() - asked, 2s);
    auto files = run.received_files();
    ASSERT_EQ(files.size(), 2u) << run.log();
    std::set<std::string> texts;
    for (const auto& f : files) {
        EXPECT_EQ(f.rfind("FAILED-m", 0), 0u);
        texts.insert(read_text(run.received() + "/" + f));
    }
    EXPECT_EQ(texts, (std::set<std::string>{"%\nO10\nN10 G00", "%\nO11\nN10 X"}));
}

TEST(DncService, SigkillLosesNothingAlreadyReceived) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\nO12\nN10 G00 X1\nN20 Y");
    std::string path = run.wait_received("%\nO12\nN10 G00 X1\nN20 Y", 5s);
    ASSERT_FALSE(path.empty()) << "the punch-out is on disk as it arrives";
    run.service->signal(SIGKILL);
    run.service->wait(5s);
    EXPECT_EQ(read_text(run.received() + "/" + path), "%\nO12\nN10 G00 X1\nN20 Y");
    EXPECT_EQ(path.rfind("FAILED-m0-", 0), 0u);
}

TEST(DncService, ReloadKeepsTheTransferOfAnUnchangedMachine) {
    DncRun run(2);
    DNC_OR_SKIP(run);
    std::string program = long_program(80);
    run.add_program("O2000.nc", program);
    run.write_config("", "baud=9600&flow=xonxoff", {"rate = 1000", ""});
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(PRG=O2000)\n%\n");
    std::vector<std::uint8_t> got;
    run.controls[0]->pty.receive_until_size(got, 100, 5s);
    run.write_config("", "baud=9600&flow=xonxoff", {"rate = 1000", "answer_unknown = true"});
    run.service->signal(SIGHUP);
    ASSERT_TRUE(run.wait_log("reloaded", 5s)) << run.log();
    run.controls[0]->pty.receive_until_quiet(got, 500ms, 20s);
    EXPECT_EQ(from_percent(Control::text_of(got)), program);
    ASSERT_TRUE(run.wait_log("done", 5s)) << run.log();
    run.controls[1]->punch("%\n(PRG=NOPE)\n%\n");  // m1 restarted with its new setting: it answers
    EXPECT_NE(run.controls[1]->receive_text(500ms, 5s).find("(NOPE NOT SENT"), std::string::npos) << run.log();
}

TEST(DncService, BadReloadKeepsTheRunningConfig) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1.nc", "%\nO1\nM30\n%\n");
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    std::ofstream(run.config(), std::ios::app) << "rat = 5\n";
    run.service->signal(SIGHUP);
    ASSERT_TRUE(run.wait_log("the running configuration stays in force", 5s)) << run.log();
    EXPECT_NE(run.log().find("<3>tape dnc: " + run.config() + ": line "), std::string::npos) << run.log();
    run.controls[0]->punch("%\n(PRG=O1)\n%\n");
    EXPECT_EQ(from_percent(run.controls[0]->receive_text(500ms, 5s)), "%\nO1\nM30\n%\n");
}

TEST(DncService, StatusThroughAnOwnerOnlySocket) {
    DncRun run(2);
    DNC_OR_SKIP(run);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    struct stat dir {
    }, sock{};
    ASSERT_EQ(::stat(run.dir.file("run").c_str(), &dir), 0);
    ASSERT_EQ(::stat(run.dir.file("run/control.sock").c_str(), &sock), 0);
    EXPECT_EQ(dir.st_mode & 0777, 0700u);
    EXPECT_EQ(sock.st_mode & 077, 0u);
    std::string table;
    // Asked again until both lines are open: right after "serving" a machine may still be opening its line.
    eventually(
        [&] {
            TempDir out;
            Process status({"dnc", "status", "--config", run.config()}, out);
            EXPECT_EQ(status.wait(10s), 0) << status.err();
            table = read_text(out.file("stdout"));
            auto listening = table.find("listening");
            return listening != std::string::npos && table.find("listening", listening + 1) != std::string::npos;
        },
        10s);
    EXPECT_EQ(table.rfind("MACHINE", 0), 0u) << table;
    EXPECT_NE(table.find("m0 "), std::string::npos) << table;
    EXPECT_NE(table.find("m1 "), std::string::npos) << table;
    EXPECT_NE(table.find("listening"), std::string::npos) << table;
}

TEST(DncService, RestartAfterAToolBreak) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O1234.nc", program_1234);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(RESTART=O1234,N50)\n%\n");
    EXPECT_EQ(
        from_percent(run.controls[0]->receive_text(500ms, 10s)),
        "%\nO1234 (BRACKET)\n(RESTART AT N50)\nG21 G17 G90\nT1 M06\nS1200 M03\nG00\nG90 G00 Z5.\nG00 X10. Y10.\nG00\n"
        "N50 G01 Z-1. F100.\n"
        "N60 X20.\nN70 M30\n%\n");
    ASSERT_TRUE(run.wait_log("sent O1234 from N50", 5s)) << run.log();
}

// On a machine said to be a lathe, the approach goes X clear (the largest X reached by rapid), Z, then X.
TEST(DncService, RestartOnALathe) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.add_program("O10.nc", "%\nO10\nN10 G21 G18 G00 X50. Z5.\nN20 G01 X20. F0.2\nN30 Z-30.\nN40 X40.\nN50 M30\n%\n");
    run.write_config("dialect = \"fanuc\"\nlathe = true");
    ASSERT_TRUE(run.start()) << run.log();
    run.controls[0]->punch("%\n(RESTART=O10,N40)\n%\n");
    EXPECT_EQ(from_percent(run.controls[0]->receive_text(500ms, 10s)),
              "%\nO10\n(RESTART AT N40)\nG21 G18\nG01 F0.2\nG00 X50.\nG00 Z-30.\nG01 X20. F0.2\nG01 F0.2\nN40 X40.\n"
              "N50 M30\n%\n");
    ASSERT_TRUE(run.wait_log("sent O10 from N40", 5s)) << run.log();
}

}  // namespace

namespace {

// The sample config of packaging/ is a config tape dnc takes: every profile in it starts (its ports are
// not there, which the service says and waits for).
TEST(DncService, SampleConfigServes) {
    DncRun run(0);
#ifndef TAPE_WITH_TOML
    GTEST_SKIP() << "tape was built without toml++: tape dnc cannot read a config";
#endif
    std::string sample = read_text(std::string(TAPE_SOURCE_DIR) + "/packaging/dnc.toml");
    for (auto [from, to] : {std::pair<std::string, std::string>{"/srv/tape/programs", run.programs()},
                            {"/srv/tape/received", run.received()},
                            {"/run/tape-dnc", run.dir.file("run")}})
        for (auto at = sample.find(from); at != std::string::npos; at = sample.find(from, at + to.size()))
            sample.replace(at, from.size(), to);
    std::ofstream(run.config()) << sample;
    ASSERT_TRUE(run.start()) << run.log();
    EXPECT_NE(run.log().find("serving 10 machine(s)"), std::string::npos) << run.log();
    ASSERT_TRUE(run.wait_log("trying again every 2 s", 5s, 10)) << run.log();
    run.service->signal(SIGTERM);
    EXPECT_EQ(run.service->wait(5s), 0) << run.log();
}

}  // namespace

namespace {

// A second service on the same runtime folder is refused before it opens any line.
TEST(DncService, SecondServiceOnTheSameSocketRefused) {
    DncRun run(1);
    DNC_OR_SKIP(run);
    run.write_config();
    ASSERT_TRUE(run.start()) << run.log();
    TempDir out;
    Process second({"dnc", "--config", run.config()}, out);
    EXPECT_EQ(second.wait(10s), 2);
    EXPECT_NE(second.err().find("another tape dnc answers there already"), std::string::npos) << second.err();
    EXPECT_EQ(second.err().find("serving"), std::string::npos) << second.err();
}

}  // namespace
