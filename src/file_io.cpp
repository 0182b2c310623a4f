#include "tape/file_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "tape/error.hpp"

namespace tape {
namespace {

[[noreturn]] void io_fail(const std::string& what) { throw Error(Errc::io, what + ": " + std::strerror(errno)); }

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

}  // namespace

std::vector<std::uint8_t> read_file(const std::string& path) {
    int fd = path == "-" ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) io_fail("cannot open");
    std::vector<std::uint8_t> bytes;
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
        if (fd != STDIN_FILENO) ::close(fd);
        errno = EISDIR;
        io_fail("cannot read");
    }
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) bytes.reserve(static_cast<std::size_t>(st.st_size));
    std::uint8_t buf[65536];
    for (;;) {
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n == 0) break;
        if (n < 0) {
            if (errno == EINTR) continue;
            int saved = errno;
            if (fd != STDIN_FILENO) ::close(fd);
            errno = saved;
            io_fail("cannot read");
        }
        bytes.insert(bytes.end(), buf, buf + n);
    }
    if (fd != STDIN_FILENO) ::close(fd);
    return bytes;
}

bool path_exists(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0;
}

void write_file_atomic(const std::string& path, std::string_view data, bool overwrite) {
    if (!overwrite && path_exists(path)) throw Error(Errc::usage, "already exists (use --force to replace it)");
    std::string tmp = path + ".tmpXXXXXX";
    int fd = ::mkstemp(tmp.data());
    if (fd < 0) io_fail("cannot create a temporary file beside it");
    mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    bool ok = write_all(fd, data) && ::fsync(fd) == 0;
    int saved = errno;
    ok = (::close(fd) == 0) && ok;
    if (ok) {
        // RENAME_NOREPLACE closes the gap between the check above and the rename.
        int r = overwrite ? ::rename(tmp.c_str(), path.c_str())
                          : ::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, path.c_str(), RENAME_NOREPLACE);
        if (r != 0 && !overwrite && errno == EINVAL) {  // a file system without RENAME_NOREPLACE
            r = ::link(tmp.c_str(), path.c_str());
            if (r == 0) ::unlink(tmp.c_str());
        }
        if (r == 0) return;
        saved = errno;
    }
    ::unlink(tmp.c_str());
    errno = saved;
    if (errno == EEXIST) throw Error(Errc::usage, "already exists (use --force to replace it)");
    io_fail("cannot write");
}

}  // namespace tape

#include "tape/code.hpp"
#include "tape/image.hpp"

namespace tape {

FrameFileWriter::FrameFileWriter(const std::string& path, const ImageFormat& format, const FrameCode* annotate, bool replace)
    : path_(path), format_(format), annotate_(annotate), last_sync_(std::chrono::steady_clock::now()) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | (replace ? O_TRUNC : O_EXCL), 0666);
    if (fd_ < 0) {
        if (errno == EEXIST) throw Error(Errc::usage, "already exists (use --force to replace it)");
        io_fail("cannot create");
    }
    std::string header = format_.write({}, ImageWriteOptions{annotate_, 1, true});
    if (!write_all(fd_, header)) io_fail("cannot write");
}

FrameFileWriter::~FrameFileWriter() {
    if (fd_ < 0) return;
    ::fsync(fd_);
    ::close(fd_);
}

void FrameFileWriter::append(std::span<const std::uint8_t> frames) {
    if (frames.empty()) return;
    std::string data = format_.write(frames, ImageWriteOptions{annotate_, frames_ + 1, false});
    if (!write_all(fd_, data)) io_fail("cannot write");
    frames_ += frames.size();
    if (std::chrono::steady_clock::now() - last_sync_ >= std::chrono::seconds(1)) sync();
}

void FrameFileWriter::sync() {
    if (::fsync(fd_) != 0) io_fail("cannot flush to disk");
    last_sync_ = std::chrono::steady_clock::now();
}

}  // namespace tape
