// Files that lose nothing: whole reads, atomic writes that never replace without permission.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

struct ImageFormat;
class FrameCode;

/// The whole file, or standard input for "-". Throws Error(Errc::io) with the system's reason.
std::vector<std::uint8_t> read_file(const std::string& path);

/// Writes data to path atomically: a temporary file in the same folder, flushed to disk, then
/// renamed over path, so a failure leaves no half file. Unless overwrite, an existing path is left
/// alone and Error(Errc::usage) is thrown. Throws Error(Errc::io) when the system refuses.
void write_file_atomic(const std::string& path, std::string_view data, bool overwrite);

/// An image written as frames arrive from a device: appended, flushed to disk at least once a second,
/// so that a run cut short keeps every frame already received.
class FrameFileWriter {
public:
    /// Creates path (refuses an existing one unless replace: Error(Errc::usage)); format raw or holes.
    FrameFileWriter(const std::string& path, const ImageFormat& format, const FrameCode* annotate, bool replace);
    ~FrameFileWriter();
    FrameFileWriter(const FrameFileWriter&) = delete;
    FrameFileWriter& operator=(const FrameFileWriter&) = delete;

    void append(std::span<const std::uint8_t> frames);
    /// Flushes to disk now.
    void sync();
    std::uint64_t frames() const { return frames_; }

private:
    std::string path_;
    const ImageFormat& format_;
    const FrameCode* annotate_;
    int fd_ = -1;
    std::uint64_t frames_ = 0;
    std::chrono::steady_clock::time_point last_sync_;
};

/// True when path names an existing file (or anything else that exists).
bool path_exists(const std::string& path);

}  // namespace tape
