// What the file and serial transports share: poll-based reads and full writes on a descriptor.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>

#include "tape/device.hpp"

namespace tape::posix {

/// Reads with a time-out; end = true on end of file or hang-up.
ReadResult read_fd(int fd, std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout, const std::string& name);
/// Writes everything; throws Error(Errc::io) (hang-up included).
void write_fd(int fd, std::span<const std::uint8_t> bytes, const std::string& name);
/// Opens path read-write, non-blocking, as a line: only a character device (a serial port, a
/// pseudo-terminal) is taken, so that a mistaken path (a tape image, a FIFO) is never written into.
/// Throws Error(Errc::usage) for anything else, Error(Errc::io) when it cannot be opened.
int open_line(const std::string& path, const std::string& name);
/// Error(Errc::io) "NAME: what: strerror(errno)".
[[noreturn]] void fail(const std::string& name, const std::string& what);

}  // namespace tape::posix
