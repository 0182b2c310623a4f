#include "fd_util.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "tape/error.hpp"

namespace tape {

void io_fail(const std::string& what) { throw Error(Errc::io, what + ": " + std::strerror(errno)); }

bool write_all(int fd, std::string_view data) {
    while (!data.empty()) {
        ssize_t n = ::write(fd, data.data(), data.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

}  // namespace tape
