// Writing what a command makes: the image format of OUT, standard output, atomic files.
#pragma once

#include <string>

#include "tape/image.hpp"

namespace cli {

/// The image format to write OUT in: --format, else by OUT's extension, else raw; fails (usage) for a
/// format that can only be read.
const tape::ImageFormat& output_format(const std::string& format_id, const std::string& path);

/// Fails (usage) when a binary image would go to standard output on a terminal without --force.
void refuse_binary_terminal(const std::string& path, bool binary, bool force);

/// Writes data to OUT ("-" or empty = stdout) atomically; refuses to replace a file without force,
/// and a binary image on a terminal without force.
void write_output(const std::string& path, const std::string& data, bool binary, bool force);

}  // namespace cli
