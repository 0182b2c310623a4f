#include "transport_posix.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>

#include "tape/error.hpp"

namespace tape::posix {

int open_line(const std::string& path, const std::string& name) {
    auto refuse = [&name] {
        throw Error(Errc::usage,
                    name +
                        ": is no serial port or pseudo-terminal (a character device): lines are reached through "
                        "their device, e.g. /dev/ttyUSB0 or /dev/ttyACM0");
    };
    struct stat st {};
    // Looked at before opening (a FIFO or a file is never opened for writing) and after (it may have changed).
    if (::stat(path.c_str(), &st) == 0 && !S_ISCHR(st.st_mode)) refuse();
    int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) fail(name, "cannot open");
    if (::fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) {
        ::close(fd);
        refuse();
    }
    return fd;
}

void fail(const std::string& name, const std::string& what) {
    throw Error(Errc::io, name + ": " + what + ": " + std::strerror(errno));
}

ReadResult read_fd(int fd, std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout, const std::string& name) {
    pollfd p{fd, POLLIN, 0};
    // poll takes an int: a longer wait is cut to about 24 days (the caller loops anyway), never wrapped.
    int wait = static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(timeout.count(), 0, INT_MAX));
    int r;
    do {
        r = ::poll(&p, 1, wait);
    } while (r < 0 && errno == EINTR);
    if (r < 0) fail(name, "cannot wait for data");
    if (r == 0) return {};
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
        ssize_t n;
        do {
            n = ::read(fd, buffer.data(), buffer.size());
        } while (n < 0 && errno == EINTR);
        if (n > 0) return {static_cast<std::size_t>(n), false};
        if (n == 0 || errno == EIO) return {0, true};  // EIO: a pseudo-terminal whose other side closed
        if (errno == EAGAIN) return {};
        fail(name, "cannot read");
    }
    return {0, (p.revents & POLLNVAL) != 0};
}

void write_fd(int fd, std::span<const std::uint8_t> bytes, const std::string& name) {
    while (!bytes.empty()) {
        ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            if (errno == EAGAIN) {
                pollfd p{fd, POLLOUT, 0};
                ::poll(&p, 1, 100);
                continue;
            }
            if (errno == EIO) throw Error(Errc::io, name + ": the other side hung up");
            fail(name, "cannot write");
        }
        bytes = bytes.subspan(static_cast<std::size_t>(n));
    }
}

}  // namespace tape::posix
