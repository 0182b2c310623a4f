// The tape binary run as a real process by the tests: stdout and stderr to files, waits with deadlines.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "test_util.hpp"

extern char** environ;

// One run of the tape binary, stdout and stderr to files.
class Process {
public:
    /// Starts tape with args; its stdout and stderr go to the files "stdout" and "stderr" in dir.
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
        if (posix_spawn(&pid_, argv[0], &fa, nullptr, argv.data(), environ) != 0)
            throw std::runtime_error("spawn failed");
        posix_spawn_file_actions_destroy(&fa);
    }
    ~Process() {
        if (pid_ > 0) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
    }
    void interrupt() const { ::kill(pid_, SIGINT); }
    void signal(int sig) const { ::kill(pid_, sig); }
    /// Exit status, or -1 when it had to be killed after timeout.
    int wait(std::chrono::milliseconds timeout = std::chrono::seconds(10)) {
        auto end = std::chrono::steady_clock::now() + timeout;
        int status = 0;
        while (std::chrono::steady_clock::now() < end) {
            if (::waitpid(pid_, &status, WNOHANG) == pid_) {
                pid_ = -1;
                return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return -1;
    }
    std::string err() const { return read_text(dir_.file("stderr")); }

private:
    const TempDir& dir_;
    pid_t pid_ = -1;
};
