// Outputs are written whole or not at all, and never replace a file without permission.
#include "tape/file_io.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include "process_util.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {
int entries(const TempDir& dir) {
    int n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path)) ++n;
    return n;
}
}  // namespace

TEST(FileIo, WritesAndReadsBack) {
    TempDir dir;
    std::string p = dir.path + "/out.ptp";
    write_file_atomic(p, std::string("\xA5\x0A", 2), false);
    EXPECT_EQ(read_file(p), (std::vector<std::uint8_t>{0xA5, 0x0A}));
    EXPECT_EQ(entries(dir), 1);  // no temporary left behind
}

TEST(FileIo, RefusesToReplaceWithoutOverwrite) {
    TempDir dir;
    std::string p = dir.path + "/out.ptp";
    write_file_atomic(p, "old", false);
    try {
        write_file_atomic(p, "new", false);
        FAIL() << "replaced an existing file";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::exists);
        EXPECT_EQ(e.hint().action, Hint::Action::replace_output);
        EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << "no command-line option: " << e.what();
    }
    EXPECT_EQ(read_text(p), "old");
    write_file_atomic(p, "new", true);
    EXPECT_EQ(read_text(p), "new");
    EXPECT_EQ(entries(dir), 1);
}

TEST(FileIo, FailuresAreIoErrorsAndLeaveNothing) {
    TempDir dir;
    try {
        write_file_atomic(dir.path + "/no/such/dir/out.ptp", "x", false);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::io);
    }
    try {
        read_file(dir.path + "/missing.ptp");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::io);
        EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos);
    }
    EXPECT_EQ(entries(dir), 0);
}

TEST(FileIo, ForceKeepsModeAndWritesDevicesInPlace) {
    TempDir dir;
    std::string p = dir.file("out.ptp");
    write_file_atomic(p, "old", false);
    ASSERT_EQ(::chmod(p.c_str(), 0600), 0);
    write_file_atomic(p, "new", true);
    struct stat st {};
    ASSERT_EQ(::stat(p.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0600u);
    // A character device stays one: written into, not renamed over. A private null device node, so that
    // a regression cannot replace the system's /dev/null.
    std::string node = dir.file("null");
    if (::mknod(node.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0)
        GTEST_SKIP() << "cannot make a device node (not root)";
    write_file_atomic(node, "frames", true);
    ASSERT_EQ(::stat(node.c_str(), &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
    EXPECT_EQ(entries(dir), 2);
}

// A run interrupted while it writes its output leaves neither a half output nor a temporary file: the
// output is an unnamed file (O_TMPFILE) until it is whole, or a temporary one removed by the handler.
TEST(FileIo, SignalDuringWriteLeavesNothingBehind) {
    TempDir dir;
    std::string big = dir.file("big.txt");
    {
        std::string block = "N0001 G01 X+012500 Y-003000 F1000 S0800 T0101 M03\n";
        std::ofstream out(big, std::ios::binary);
        out << "%\n";
        for (int i = 0; i < 1'500'000; ++i) out << block;  // about 80 MB: writing it takes a while
        out << "M02\n";
    }
    std::uintmax_t whole = 0;  // the output's size when the run is left alone
    {
        TempDir logs, elsewhere;
        Process run({"encode", big, "-o", elsewhere.file("whole.ptp")}, logs);
        ASSERT_EQ(run.wait(std::chrono::seconds(120)), 0) << run.err();
        whole = std::filesystem::file_size(elsewhere.file("whole.ptp"));
    }
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        TempDir logs;  // stdout and stderr elsewhere, so that only the output could appear here
        Process run({"encode", big, "-o", dir.file("out.ptp")}, logs);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));  // under way, the output being written
        run.signal(sig);
        int status = run.wait(std::chrono::seconds(30));
        ASSERT_NE(status, -1) << "the run did not end within 30 s of the signal";
        if (entries(dir) == 2) {
            // The run had finished its output before the signal landed (this thread slept long on a busy
            // machine): then the output is whole, never a part of it.
            EXPECT_EQ(std::filesystem::file_size(dir.file("out.ptp")), whole) << "a half output was left behind";
            std::filesystem::remove(dir.file("out.ptp"));
            continue;
        }
        EXPECT_EQ(status, 128 + sig) << run.err();
        EXPECT_EQ(entries(dir), 1) << "a temporary output was left behind";
    }
}

TEST(FileIo, AnOutputHasNoNameInItsFolderUntilItIsCommitted) {
    TempDir dir;
    {
        tape::OutputFile out(dir.file("out.ptp"), false);
        out.write("half a tape");
        EXPECT_EQ(entries(dir), 0) << "a name appeared before the output was whole";
        out.write(" and the rest");
        out.commit();
    }
    EXPECT_EQ(read_text(dir.file("out.ptp")), "half a tape and the rest");
    {
        tape::OutputFile out(dir.file("out.ptp"), true);
        out.write("replaced");
        EXPECT_EQ(entries(dir), 1);
    }  // not committed: the old file stays, nothing else appears
    EXPECT_EQ(read_text(dir.file("out.ptp")), "half a tape and the rest");
    EXPECT_EQ(entries(dir), 1);
}
