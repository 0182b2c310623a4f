// An image written as frames arrive from a device, in any image format that can write.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "tape/code.hpp"
#include "tape/image.hpp"

namespace tape {

/// Appends frames to an image file as they come, flushed to disk at least once a second, so that a
/// run cut short keeps every frame already received (never written to a temporary file first).
class FrameFileWriter {
public:
    /// Creates path ("-": standard output); an existing file is refused with Error(Errc::exists) unless
    /// replace. Only a regular file is flushed to disk (a FIFO, a pipe or /dev/null is not). annotate:
    /// the code whose characters a text picture shows beside the frames, or nullptr.
    FrameFileWriter(const std::string& path, const ImageFormat& format, const FrameCode* annotate, bool replace);
    ~FrameFileWriter();
    FrameFileWriter(const FrameFileWriter&) = delete;
    FrameFileWriter& operator=(const FrameFileWriter&) = delete;

    void append(std::span<const Frame> frames);
    /// Flushes to disk now (a regular file).
    void sync();
    /// Writes the format's ending, flushes and closes, throwing Error(Errc::io) where the destructor
    /// could only keep silent. Nothing may be appended after.
    void close();
    std::uint64_t frames() const { return frames_; }
    /// True when the image is a regular file (it can be read back), not a pipe, FIFO or device.
    bool is_file() const { return syncs_; }

private:
    void put(const std::string& data);

    std::unique_ptr<ImageWriter> writer_;
    std::string buffer_;
    int fd_ = -1;
    bool syncs_ = false;  ///< a regular file: fsync() means something
    std::uint64_t frames_ = 0;
    std::chrono::steady_clock::time_point last_sync_;
};

}  // namespace tape
