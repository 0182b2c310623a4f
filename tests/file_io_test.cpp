// Outputs are written whole or not at all, and never replace a file without permission.
#include <gtest/gtest.h>

#include <filesystem>

#include "tape/error.hpp"
#include "tape/file_io.hpp"
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
        EXPECT_EQ(e.code(), Errc::usage);
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
