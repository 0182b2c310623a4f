// file:PATH — a tape image file as a device. Reading serves the image's frames (in any readable
// format, as `tape decode` reads them) and ends at its end; writing appends frames to a new file in
// the format of its extension (raw by default), through the image writers. It takes no
// settings: "file:PATH?key=value" is refused like an unknown serial setting.

#include <algorithm>
#include <cstring>

#include "device_backends.hpp"
#include "device_query.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"
#include "tape/frame_file_writer.hpp"
#include "tape/image.hpp"
#include "tape/image_input.hpp"

namespace tape {
namespace {

class FileTransport : public Transport {
public:
    FileTransport(std::string path, DeviceUse use, bool replace) : path_(std::move(path)) {
        try {
            if (use == DeviceUse::read) {  // a file written to has no other side to read from
                image_ = std::make_unique<ImageInput>(path_, nullptr);
            } else {
                const ImageFormat* format = image_format_for_path(path_);
                writer_ = std::make_unique<FrameFileWriter>(path_, format ? *format : default_image_format(), nullptr,
                                                            replace);
            }
        } catch (const Error& e) {
            rethrow_named(e);
        }
    }

    // Frames a chunk at a time, as the image reader gives them: a tape of any length in bounded memory.
    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds) override {
        if (!image_) return {};
        try {
            if (pos_ == chunk_.size() && !ended_) {
                chunk_ = image_->next();
                pos_ = 0;
                ended_ = chunk_.empty();
            }
        } catch (const Error& e) {
            rethrow_named(e);
        }
        std::size_t n = std::min(buffer.size(), chunk_.size() - pos_);
        if (n) std::memcpy(buffer.data(), chunk_.data() + pos_, n);  // an ended image has no chunk at all
        pos_ += n;
        return {n, ended_};
    }
    void write(std::span<const std::uint8_t> bytes) override {
        if (!writer_) throw Error(Errc::usage, name() + ": opened for reading only");
        try {
            writer_->append(bytes);
        } catch (const Error& e) {
            rethrow_named(e);
        }
    }
    void drain() override {
        if (!writer_) return;
        try {
            writer_->sync();
        } catch (const Error& e) {
            rethrow_named(e);
        }
    }
    std::string name() const override { return "file:" + path_; }
    int tracks() const override { return image_ ? image_->format().tracks : 8; }

private:
    // The file layer names no file; a device error names its device, where in it included.
    [[noreturn]] void rethrow_named(const Error& e) const {
        std::string where = e.where().describe();
        throw Error(e.code(), name() + ": " + (where.empty() ? "" : where + ": ") + e.what(), e.hint());
    }

    std::string path_;
    std::unique_ptr<ImageInput> image_;
    std::span<const Frame> chunk_;
    std::size_t pos_ = 0;
    bool ended_ = false;
    std::unique_ptr<FrameFileWriter> writer_;
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
