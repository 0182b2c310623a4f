// Whole writes and errno-carrying errors on descriptors, shared by the file writers.
#pragma once

#include <string>
#include <string_view>

namespace tape {

/// Error(Errc::io) "what: strerror(errno)".
[[noreturn]] void io_fail(const std::string& what);
/// Writes all of data, retrying after signals; false (errno set) on failure.
bool write_all(int fd, std::string_view data);

}  // namespace tape
