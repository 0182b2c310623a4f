// file:PATH — a tape image file as a device. Reading serves the image's frames (raw or holes, as
// `tape decode` reads them) and ends at its end; writing appends raw frames to a new file. It takes no
// settings: "file:PATH?key=value" is refused like an unknown serial setting.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

#include "device_backends.hpp"
#include "device_query.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"
#include "tape/image.hpp"
#include "transport_posix.hpp"

namespace tape {
namespace {

class FileTransport : public Transport {
public:
    FileTransport(std::string path, DeviceUse use, bool replace) : path_(std::move(path)) {
        if (use == DeviceUse::read) {  // a file written to has no other side to read from
            try {
                auto bytes = read_file(path_);
                const ImageFormat* f = image_format_for_path(path_);
                if (!f) f = &detect_image_format(std::span(bytes).first(std::min<std::size_t>(bytes.size(), 4096)));
                frames_ = f->read(bytes);
            } catch (const Error& e) {
                // The file layer names no file; a device error names its device, where in it included.
                std::string where = e.where().describe();
                throw Error(e.code(), name() + ": " + (where.empty() ? "" : where + ": ") + e.what());
            }
        }
        if (use != DeviceUse::read) {
            int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (replace ? O_TRUNC : O_EXCL);
            fd_ = ::open(path_.c_str(), flags, 0666);
            if (fd_ < 0) {
                if (errno == EEXIST) throw Error(Errc::usage, name() + ": already exists (use --force to replace it)");
                posix::fail(name(), "cannot create");
            }
        }
    }
    ~FileTransport() override {
        if (fd_ >= 0) ::close(fd_);
    }

    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds) override {
        if (fd_ >= 0) return {};
        std::size_t n = std::min(buffer.size(), frames_.size() - pos_);
        std::memcpy(buffer.data(), frames_.data() + pos_, n);
        pos_ += n;
        return {n, pos_ == frames_.size()};
    }
    void write(std::span<const std::uint8_t> bytes) override {
        if (fd_ < 0) throw Error(Errc::usage, name() + ": opened for reading only");
        posix::write_fd(fd_, bytes, name());
    }
    void drain() override {
        if (fd_ >= 0 && ::fsync(fd_) != 0) posix::fail(name(), "cannot flush to disk");
    }
    std::string name() const override { return "file:" + path_; }

private:
    std::string path_;
    std::vector<Frame> frames_;
    std::size_t pos_ = 0;
    int fd_ = -1;
};

}  // namespace

std::string file_device_path(std::string_view rest) {
    DeviceQuery q("file", rest, {});
    if (q.path().empty()) q.fail("no path, e.g. file:part.ptp");
    return q.path();
}

std::unique_ptr<Transport> open_file_device(std::string_view rest, DeviceUse use, bool replace) {
    return std::make_unique<FileTransport>(file_device_path(rest), use, replace);
}

}  // namespace tape
