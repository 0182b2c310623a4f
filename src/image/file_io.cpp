#include "tape/file_io.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <utility>

#include "common/fd_util.hpp"
#include "tape/error.hpp"

namespace tape {

std::vector<std::uint8_t> read_file(const std::string& path, std::uint64_t max_bytes, Errc too_big) {
    auto refuse = [&] { throw Error(too_big, "is larger than " + std::to_string(max_bytes) + " bytes"); };
    FileSource source(path);
    std::vector<std::uint8_t> bytes;
    struct stat st {};
    // The size is checked before the memory is asked for.
    if (path != "-" && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
        if (static_cast<std::uint64_t>(st.st_size) > max_bytes) refuse();
        bytes.reserve(static_cast<std::size_t>(st.st_size));
    }
    std::uint8_t buf[65536];
    while (std::size_t n = source.read(buf)) {
        if (bytes.size() + n > max_bytes) refuse();
        bytes.insert(bytes.end(), buf, buf + n);
    }
    return bytes;
}

bool path_exists(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0;
}

namespace {

// The temporary file being written, for discard_pending_output() in a signal handler: a fixed buffer
// because a handler may not allocate.
char pending_temporary[4096];
volatile std::sig_atomic_t pending_set = 0;

// Signals that end a run (the CLI's handlers call discard_pending_output) are held while the
// temporary's name is cleared and it is renamed, so a handler never removes a finished output.
class HoldEndingSignals {
public:
    HoldEndingSignals() {
        sigset_t set;
        sigemptyset(&set);
        for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&set, sig);
        ::pthread_sigmask(SIG_BLOCK, &set, &saved_);
    }
    ~HoldEndingSignals() { ::pthread_sigmask(SIG_SETMASK, &saved_, nullptr); }
    HoldEndingSignals(const HoldEndingSignals&) = delete;
    HoldEndingSignals& operator=(const HoldEndingSignals&) = delete;

private:
    sigset_t saved_;
};

void set_pending(const std::string& tmp) {
    if (tmp.size() >= sizeof pending_temporary) return;
    std::memcpy(pending_temporary, tmp.c_str(), tmp.size() + 1);
    pending_set = 1;
}

// Whether a path reaches its file through /proc or /dev/fd (/dev/stdout is /proc/self/fd/1): such a
// name is a descriptor another process opened, not a place to rename a new file into.
bool through_descriptor_link(std::string path) {
    for (int hop = 0; hop < 40; ++hop) {
        if (path.starts_with("/proc/") || path.starts_with("/dev/fd/")) return true;
        char target[4096];
        ssize_t n = ::readlink(path.c_str(), target, sizeof target - 1);
        if (n < 0) return false;
        target[n] = '\0';
        std::string next(target, static_cast<std::size_t>(n));
        if (!next.starts_with("/")) next = path.substr(0, path.rfind('/') + 1) + next;
        path = std::move(next);
    }
    return false;
}

}  // namespace

void discard_pending_output() noexcept {
    if (pending_set) ::unlink(pending_temporary);
    pending_set = 0;
}

namespace {

// An unnamed file in dir (O_TMPFILE), or -1 where the file system or the kernel has none; linked into
// place through /proc/self/fd, so /proc must be there too.
int open_unnamed(const std::string& dir) {
#ifdef O_TMPFILE
    if (::access("/proc/self/fd", X_OK) != 0) return -1;
    return ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
#else
    (void)dir;
    return -1;
#endif
}

std::string folder_of(const std::string& path) {
    auto slash = path.rfind('/');
    return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

// Gives the unnamed file fd the name path; EEXIST when path exists.
int link_unnamed(int fd, const std::string& path) {
    std::string self = "/proc/self/fd/" + std::to_string(fd);
    return ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, path.c_str(), AT_SYMLINK_FOLLOW);
}

}  // namespace

OutputFile::OutputFile(const std::string& path, bool overwrite) {
    if (path.empty() || path == "-") {
        fd_ = STDOUT_FILENO;
        direct_ = true;
        return;
    }
    struct stat link_st {};
    bool exists = ::lstat(path.c_str(), &link_st) == 0;
    if (exists && !overwrite) throw Error(Errc::exists, "already exists", Hint{Hint::Action::replace_output});
    overwrite_ = overwrite;
    struct stat st {};
    bool target_exists = exists && ::stat(path.c_str(), &st) == 0;
    if (target_exists && S_ISBLK(st.st_mode))
        throw Error(Errc::usage, "is a block device (a disk): tape images go to files, FIFOs or character devices");
    if (target_exists && (!S_ISREG(st.st_mode) || through_descriptor_link(path))) {
        // Devices, FIFOs and descriptors are written into as they are: renaming a file over them would
        // replace the node (as root, /dev/null itself).
        fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY | (S_ISREG(st.st_mode) ? O_APPEND : 0));
        if (fd_ < 0) io_fail("cannot open");
        direct_ = true;
        close_fd_ = true;
        return;
    }
    // A symbolic link to a file: the file it names is replaced, the link stays.
    final_path_ = path;
    if (target_exists && S_ISLNK(link_st.st_mode)) {
        char resolved[PATH_MAX];
        if (::realpath(path.c_str(), resolved)) final_path_ = resolved;
    }
    open_temporary();
    close_fd_ = true;
    if (target_exists) {
        // --force keeps the replaced file's permissions and, where allowed, its owner.
        ::fchmod(fd_, st.st_mode & 07777);
        if (::fchown(fd_, st.st_uid, st.st_gid) != 0) { /* not ours to give away: keep our own */
        }
    } else {
        mode_t mask = ::umask(0);
        ::umask(mask);
        ::fchmod(fd_, 0666 & ~mask);
    }
}

void OutputFile::open_temporary() {
    // Unnamed until committed: a run killed outright (SIGKILL, a power cut) leaves nothing behind.
    fd_ = open_unnamed(folder_of(final_path_));
    if (fd_ >= 0) {
        unnamed_ = true;
        return;
    }
    // Else a named temporary beside it, removed by the CLI's signal handlers (discard_pending_output).
    temporary_ = final_path_ + ".tmpXXXXXX";
    {
        HoldEndingSignals hold;
        fd_ = ::mkstemp(temporary_.data());
        if (fd_ >= 0) set_pending(temporary_);
    }
    if (fd_ < 0) io_fail("cannot create a temporary file beside it");
}

OutputFile::~OutputFile() {
    if (!committed_) discard();
}

void OutputFile::write(std::string_view data) {
    if (fd_ < 0) throw Error(Errc::io, "output already closed");
    if (!write_all(fd_, data)) {
        int saved = errno;
        discard();
        errno = saved;
        io_fail("cannot write");
    }
}

void OutputFile::discard() noexcept {
    if (close_fd_ && fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temporary_.empty()) {
        HoldEndingSignals hold;
        ::unlink(temporary_.c_str());
        pending_set = 0;
        temporary_.clear();
    }
}

void OutputFile::commit() {
    if (fd_ < 0) throw Error(Errc::io, "output already closed");
    if (direct_) {
        bool ok = !close_fd_ || ::close(fd_) == 0;
        fd_ = -1;
        committed_ = true;
        if (!ok) io_fail("cannot write");
        return;
    }
    if (::fsync(fd_) != 0) {
        int saved = errno;
        discard();
        errno = saved;
        io_fail("cannot write");
    }
    int r;
    {
        HoldEndingSignals hold;
        r = unnamed_ ? put_unnamed_in_place() : put_temporary_in_place();
    }
    int saved = errno;
    if (r == 0 && ::close(std::exchange(fd_, -1)) == 0) {
        committed_ = true;
        return;
    }
    if (r == 0) saved = errno;
    discard();
    errno = saved;
    if (errno == EEXIST) throw Error(Errc::exists, "already exists", Hint{Hint::Action::replace_output});
    io_fail("cannot write");
}

int OutputFile::put_temporary_in_place() {
    // RENAME_NOREPLACE closes the gap between the check when opening and the rename.
    int r = overwrite_ ? ::rename(temporary_.c_str(), final_path_.c_str())
                       : ::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, final_path_.c_str(), RENAME_NOREPLACE);
    if (r != 0 && !overwrite_ && errno == EINVAL) {  // a file system without RENAME_NOREPLACE
        r = ::link(temporary_.c_str(), final_path_.c_str());
        if (r == 0) ::unlink(temporary_.c_str());
    }
    if (r == 0) {
        pending_set = 0;
        temporary_.clear();
    }
    return r;
}

int OutputFile::put_unnamed_in_place() {
    // A new name is linked only where nothing is (EEXIST otherwise): no check-then-write gap.
    if (!overwrite_) return link_unnamed(fd_, final_path_);
    // Replacing: linked under a passing name, then renamed over the old file in one step.
    for (int attempt = 0; attempt < 100; ++attempt) {
        temporary_ = final_path_ + ".tmp" + std::to_string(::getpid()) + "." + std::to_string(attempt);
        if (link_unnamed(fd_, temporary_) == 0) {
            set_pending(temporary_);
            return put_temporary_in_place();
        }
        temporary_.clear();
        if (errno != EEXIST) return -1;
    }
    return -1;
}

void write_file_atomic(const std::string& path, std::string_view data, bool overwrite) {
    OutputFile out(path, overwrite);
    out.write(data);
    out.commit();
}

std::size_t ByteSource::read_full(std::span<std::uint8_t> buffer) {
    std::size_t have = 0;
    while (have < buffer.size()) {
        std::size_t n = read(buffer.subspan(have));
        if (n == 0) break;
        have += n;
    }
    return have;
}

std::size_t MemorySource::read(std::span<std::uint8_t> buffer) {
    std::size_t n = std::min(buffer.size(), bytes_.size());
    std::copy_n(bytes_.begin(), n, buffer.begin());
    bytes_ = bytes_.subspan(n);
    return n;
}

FileSource::FileSource(const std::string& path) {
    fd_ = path == "-" || path.empty() ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) io_fail("cannot open");
    struct stat st {};
    if (::fstat(fd_, &st) == 0 && S_ISDIR(st.st_mode)) {
        close();
        errno = EISDIR;
        io_fail("cannot read");
    }
}

FileSource::~FileSource() { close(); }

void FileSource::close() noexcept {
    if (fd_ >= 0 && fd_ != STDIN_FILENO) ::close(fd_);
    fd_ = -1;
}

std::size_t FileSource::read(std::span<std::uint8_t> buffer) {
    for (;;) {
        ssize_t n = ::read(fd_, buffer.data(), buffer.size());
        if (n >= 0) return static_cast<std::size_t>(n);
        if (errno != EINTR) io_fail("cannot read");
    }
}

}  // namespace tape
