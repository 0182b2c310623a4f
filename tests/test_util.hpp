// Small helpers shared by the unit tests.
#pragma once

#include <stdlib.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "tape/frame.hpp"

/// A fresh folder under /tmp, removed with everything in it at the end of the test.
struct TempDir {
    std::string path;
    TempDir() {
        char tmpl[] = "/tmp/tape-test-XXXXXX";
        path = ::mkdtemp(tmpl);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string file(const std::string& name) const { return path + "/" + name; }
};

/// Whether pred() came true within timeout, looked at every few milliseconds: a test waits for what it
/// expects to happen, with a deadline, never for a fixed time that a loaded machine overruns.
template <class Pred>
bool eventually(Pred pred, std::chrono::milliseconds timeout = std::chrono::seconds(10)) {
    auto end = std::chrono::steady_clock::now() + timeout;
    while (!pred()) {
        if (std::chrono::steady_clock::now() >= end) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
}

inline std::string sample_path(const std::string& name) { return std::string(TAPE_SOURCE_DIR) + "/tapes/" + name; }

/// Where the real data from outside lies (other people's files, never in the project): ../shared/data beside
/// the repository, or beside the main checkout of a worktree one folder deeper; "" when it is absent.
inline std::string shared_data_dir() {
    for (const char* up : {"/../shared/data", "/../../shared/data"})
        if (std::filesystem::exists(std::string(TAPE_SOURCE_DIR) + up)) return std::string(TAPE_SOURCE_DIR) + up;
    return "";
}

/// The path of a file of ../shared/data: other people's files, read where they are, never copied in.
inline std::string shared_data(const std::string& path) {
    std::string dir = shared_data_dir();
    return (dir.empty() ? std::string(TAPE_SOURCE_DIR) + "/../shared/data" : dir) + "/" + path;
}

/// Skips the test, saying why, where the real file it was found on is absent (a user's clone has none).
#define SKIP_WITHOUT_SHARED_DATA(path)               \
    if (!std::filesystem::exists(shared_data(path))) \
    GTEST_SKIP() << "no ../shared/data/" << (path) << ": the real data this case was found on is absent"

inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

inline std::vector<tape::Frame> read_frames(const std::string& path) {
    std::string s = read_text(path);
    return {s.begin(), s.end()};
}

/// Writes frames as a raw image file.
inline void write_frames(const std::string& path, const std::vector<tape::Frame>& frames) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(frames.data()), static_cast<std::streamsize>(frames.size()));
}
