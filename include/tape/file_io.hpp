// Files that lose nothing: whole reads, atomic writes that never replace without permission.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

/// The whole file, or standard input for "-". Throws Error(Errc::io) with the system's reason.
std::vector<std::uint8_t> read_file(const std::string& path);

/// Writes data to path atomically: a temporary file in the same folder, flushed to disk, then
/// renamed over path, so a failure leaves no half file. Unless overwrite, an existing path is left
/// alone and Error(Errc::usage) is thrown. Throws Error(Errc::io) when the system refuses.
void write_file_atomic(const std::string& path, std::string_view data, bool overwrite);

/// True when path names an existing file (or anything else that exists).
bool path_exists(const std::string& path);

}  // namespace tape
