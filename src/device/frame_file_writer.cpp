#include "tape/frame_file_writer.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

#include "common/fd_util.hpp"
#include "tape/error.hpp"

namespace tape {

FrameFileWriter::FrameFileWriter(const std::string& path, const ImageFormat& format, const FrameCode* annotate,
                                 bool replace)
    : last_sync_(std::chrono::steady_clock::now()) {
    if (!format.can_write())
        throw Error(Errc::usage, "cannot write " + std::string(format.id) + " images, only read them");
    writer_ = format.make_writer(ImageWriteOptions{annotate, 1, true});
    // "-" is standard output (a copy of it, closed at the end as a file would be).
    fd_ = path == "-"
              ? ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 0)
              : ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | O_NOCTTY | (replace ? O_TRUNC : O_EXCL), 0666);
    if (fd_ < 0) {
        if (errno == EEXIST) throw Error(Errc::exists, "already exists", Hint{Hint::Action::replace_output});
        io_fail("cannot create");
    }
    // Only a file on a disk is flushed to it: /dev/null, a FIFO or a pipe has no disk to flush to.
    struct stat st {};
    syncs_ = ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode);
    writer_->write({}, buffer_);  // the header, so that even a tape that never came says what it is
    put(buffer_);
}

FrameFileWriter::~FrameFileWriter() {
    if (fd_ < 0) return;
    try {
        close();
    } catch (const Error&) {  // a destructor cannot report: what was written before stays
    }
    if (fd_ >= 0) ::close(fd_);
}

void FrameFileWriter::close() {
    buffer_.clear();
    writer_->finish(buffer_);
    put(buffer_);
    sync();
    int fd = std::exchange(fd_, -1);
    if (::close(fd) != 0) io_fail("cannot close");
}

void FrameFileWriter::append(std::span<const Frame> frames) {
    if (frames.empty()) return;
    buffer_.clear();
    writer_->write(frames, buffer_);
    put(buffer_);
    frames_ += frames.size();
    if (std::chrono::steady_clock::now() - last_sync_ >= std::chrono::seconds(1)) sync();
}

void FrameFileWriter::put(const std::string& data) {
    if (!write_all(fd_, data)) io_fail("cannot write");
}

void FrameFileWriter::sync() {
    if (syncs_ && ::fsync(fd_) != 0) io_fail("cannot flush to disk");
    last_sync_ = std::chrono::steady_clock::now();
}

}  // namespace tape
