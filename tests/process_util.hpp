// The tape binary run as a real process by the tests: stdout and stderr to files, waits with deadlines.
#pragma once

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "spawn_util.hpp"
#include "test_util.hpp"

// One run of the tape binary, stdout and stderr to files.
class Process {
public:
    /// Starts tape with args; its stdout and stderr go to the files "stdout" and "stderr" in dir.
    Process(const std::vector<std::string>& args, const TempDir& dir) : dir_(dir) {
        pid_ = spawn_to_files(TAPE_BINARY, args, dir.file("stdout"), dir.file("stderr"));
        if (pid_ < 0) throw std::runtime_error("spawn failed");
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
        auto status = wait_for_exit(pid_, timeout);
        if (!status) return -1;
        pid_ = -1;
        return WIFEXITED(*status) ? WEXITSTATUS(*status) : 128 + WTERMSIG(*status);
    }
    std::string err() const { return read_text(dir_.file("stderr")); }
    /// Whether stderr came to hold text within timeout: what the program says when it gets somewhere.
    bool wait_for_err(const std::string& text, std::chrono::milliseconds timeout = std::chrono::seconds(10)) const {
        return eventually([&] { return err().find(text) != std::string::npos; }, timeout);
    }

private:
    const TempDir& dir_;
    pid_t pid_ = -1;
};

/// What one finished run of a program said: its exit status (-1 when killed at the deadline), its
/// standard output and standard error.
struct Outcome {
    int status = -1;
    std::string out, err;
};

/// Runs program with args to the end (killed at timeout), its output in the files "stdout" and "stderr" of dir.
inline Outcome run(const std::string& program, const std::vector<std::string>& args, const TempDir& dir,
                   std::chrono::seconds timeout = std::chrono::seconds(60)) {
    pid_t pid = spawn_to_files(program, args, dir.file("stdout"), dir.file("stderr"));
    if (pid < 0) throw std::runtime_error("spawn failed: " + program);
    auto status = wait_for_exit(pid, timeout);
    Outcome r;
    if (!status) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
    } else {
        r.status = WIFEXITED(*status) ? WEXITSTATUS(*status) : 128 + WTERMSIG(*status);
    }
    r.out = read_text(dir.file("stdout"));
    r.err = read_text(dir.file("stderr"));
    return r;
}

/// The tape binary under test, run so.
inline Outcome tape_run(const std::vector<std::string>& args, const TempDir& dir) {
    return run(TAPE_BINARY, args, dir);
}
