// Files that lose nothing: whole reads, atomic writes that never replace without permission.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/error.hpp"

namespace tape {

struct ImageFormat;
class FrameCode;

/// The whole file, or standard input for "-". Throws Error(Errc::io) with the system's reason, and
/// Error(too_big) for a file of more than max_bytes: a regular file before anything is read, anything
/// else (a pipe, /dev/zero) once that much came.
std::vector<std::uint8_t> read_file(const std::string& path, std::uint64_t max_bytes = UINT64_MAX,
                                    Errc too_big = Errc::usage);

/// Writes data to path atomically: an unnamed file in the same folder (O_TMPFILE, where the file system
/// has it, else a named temporary), flushed to disk, then given its name, so a failure or a killed run
/// leaves no half file. Unless overwrite, an existing path is left
/// alone and Error(Errc::usage) is thrown. Throws Error(Errc::io) when the system refuses.
/// With overwrite, a replaced file's permissions are kept; a symbolic link is followed and the file it
/// names replaced; other hard links keep the old contents. A character device, FIFO, socket or
/// /dev/stdout-style descriptor is written into directly, never replaced; a block device is refused.
void write_file_atomic(const std::string& path, std::string_view data, bool overwrite);

/// An output written as it comes, in bounded memory, and made final by commit(): a file is written to an
/// unnamed file in its folder (O_TMPFILE) and linked into place at commit, or where the file system has
/// no O_TMPFILE to a temporary file beside it renamed over path (with the rules of write_file_atomic),
/// so an output that is not committed (an error, an exception, a kill) leaves nothing under path. Standard output
/// ("-" or empty), character devices, FIFOs and /dev/stdout-style descriptors are written directly.
class OutputFile {
public:
    /// Throws Error(Errc::usage) for an existing path without overwrite, Error(Errc::io) when the
    /// system refuses.
    OutputFile(const std::string& path, bool overwrite);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    void write(std::string_view data);
    /// Flushes to disk and puts the file in place.
    void commit();
    /// Removes the temporary file; nothing appears under path.
    void discard() noexcept;

private:
    void open_temporary();
    int put_temporary_in_place();
    int put_unnamed_in_place();

    std::string final_path_, temporary_;
    int fd_ = -1;
    bool direct_ = false, close_fd_ = false, overwrite_ = false, committed_ = false;
    bool unnamed_ = false;  ///< an O_TMPFILE file, given its name at commit
};

/// Where bytes come from, a chunk at a time: a file, standard input, a pipe.
class ByteSource {
public:
    virtual ~ByteSource() = default;
    /// Up to buffer.size() bytes; 0 only at the end. May wait (a pipe, a terminal).
    virtual std::size_t read(std::span<std::uint8_t> buffer) = 0;
    /// Reads until buffer is full or the source ends; how many bytes came.
    std::size_t read_full(std::span<std::uint8_t> buffer);
};

/// Bytes already in memory, as a source.
class MemorySource : public ByteSource {
public:
    explicit MemorySource(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
    std::size_t read(std::span<std::uint8_t> buffer) override;

private:
    std::span<const std::uint8_t> bytes_;
};

/// A file, or standard input for "-". Throws Error(Errc::io) with the system's reason.
class FileSource : public ByteSource {
public:
    explicit FileSource(const std::string& path);
    ~FileSource() override;
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;
    std::size_t read(std::span<std::uint8_t> buffer) override;

private:
    void close() noexcept;
    int fd_ = -1;
};

/// Removes the temporary file of a write_file_atomic under way, if any. Async-signal-safe: for a
/// SIGINT/SIGTERM handler, so that an interrupted run leaves no OUT.tmpXXXXXX behind.
void discard_pending_output() noexcept;

/// True when path names an existing file (or anything else that exists).
bool path_exists(const std::string& path);

}  // namespace tape
