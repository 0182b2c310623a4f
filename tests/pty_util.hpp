// A real kernel pseudo-terminal for device tests: the test plays the controller on the master side,
// the code under test opens the slave by its path as serial:PATH.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/inotify.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

/// Declares `Pty name;` and skips the test, saying why, when the system gives no pseudo-terminal
/// (a container without /dev/pts, say): such a test needs one, it does not fail for lack of one.
#define PTY_OR_SKIP(name) \
    Pty name;             \
    if (!name.ok()) GTEST_SKIP() << "no pseudo-terminal here: " << name.error

struct Pty {
    int master = -1;
    std::string slave_path;
    int slave_keep = -1;  // held open so the slave side exists until the code under test opens it
    int open_watch = -1;  // inotify: the slave opened by anyone but us (the code under test)
    std::string error;    // why there is none, when openpty failed

    Pty() {
        int slave = -1;
        char name[128];
        if (::openpty(&master, &slave, name, nullptr, nullptr) != 0) {
            error = std::string("openpty: ") + std::strerror(errno);
            master = -1;
            return;
        }
        termios t{};
        ::tcgetattr(slave, &t);
        ::cfmakeraw(&t);
        ::tcsetattr(slave, TCSANOW, &t);
        slave_path = name;
        slave_keep = slave;
        // Spawned processes must not inherit our ends: a hang-up is the last close of the master.
        ::fcntl(master, F_SETFD, FD_CLOEXEC);
        ::fcntl(slave, F_SETFD, FD_CLOEXEC);
        // Watched from now on, before the code under test starts: our own open came before.
        open_watch = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
        if (open_watch >= 0 && ::inotify_add_watch(open_watch, name, IN_OPEN) < 0) {
            ::close(open_watch);
            open_watch = -1;
        }
    }
    ~Pty() {
        close_master();
        if (slave_keep >= 0) ::close(slave_keep);
        if (open_watch >= 0) ::close(open_watch);
    }
    Pty(const Pty&) = delete;
    Pty& operator=(const Pty&) = delete;

    bool ok() const { return !slave_path.empty(); }
    void release_slave() {
        if (slave_keep >= 0) ::close(slave_keep);
        slave_keep = -1;
    }
    void close_master() {
        if (master >= 0) ::close(master);
        master = -1;
    }
    /// Whether the code under test opened the slave within timeout. A test that hangs up must wait for
    /// this: hung up before, the line is gone (or its number taken by another test's pseudo-terminal).
    bool wait_opened(std::chrono::milliseconds timeout = std::chrono::seconds(10)) const {
        if (open_watch < 0) return false;
        auto end = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            alignas(inotify_event) char buf[sizeof(inotify_event) + 256];
            if (::read(open_watch, buf, sizeof buf) > 0) return true;  // IN_OPEN is the only event watched
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
            if (left.count() <= 0) return false;
            pollfd p{open_watch, POLLIN, 0};
            ::poll(&p, 1, static_cast<int>(left.count()) + 1);
        }
    }
    std::string device(const std::string& settings = "baud=115200&flow=xonxoff") const {
        return "serial:" + slave_path + "?" + settings;
    }

    void send(std::uint8_t b) const {
        if (::write(master, &b, 1) != 1) throw std::runtime_error("pty write failed");
    }
    /// Appends what arrives within timeout (returns at the first data, or at the time-out).
    std::size_t receive(std::vector<std::uint8_t>& into, std::chrono::milliseconds timeout) const {
        pollfd p{master, POLLIN, 0};
        if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0 || !(p.revents & POLLIN)) return 0;
        std::uint8_t buf[4096];
        ssize_t n = ::read(master, buf, sizeof buf);
        if (n <= 0) return 0;
        into.insert(into.end(), buf, buf + n);
        return static_cast<std::size_t>(n);
    }
    /// Until `into` holds `size` bytes or `timeout` has passed (robust against slow starts under load).
    void receive_until_size(std::vector<std::uint8_t>& into, std::size_t size,
                            std::chrono::milliseconds timeout) const {
        auto end = std::chrono::steady_clock::now() + timeout;
        while (into.size() < size && std::chrono::steady_clock::now() < end)
            receive(into, std::chrono::milliseconds(50));
    }
    /// Everything that arrives until the line has been quiet for `quiet`, or until `limit` has passed:
    /// a sender that never pauses cannot hold the test.
    void receive_until_quiet(std::vector<std::uint8_t>& into, std::chrono::milliseconds quiet,
                             std::chrono::milliseconds limit = std::chrono::seconds(10)) const {
        auto end = std::chrono::steady_clock::now() + limit;
        while (std::chrono::steady_clock::now() < end && receive(into, quiet) > 0) {
        }
    }
};
