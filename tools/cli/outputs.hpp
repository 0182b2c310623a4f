// Writing what a command makes: the image format of OUT, standard output, atomic files.
#pragma once

#include <memory>
#include <span>
#include <string>

#include "tape/file_io.hpp"
#include "tape/image.hpp"

namespace cli {

/// The image format to write OUT in: --format, else by OUT's extension, else raw; fails (usage) for a
/// format that can only be read.
const tape::ImageFormat& output_format(const std::string& format_id, const std::string& path);

/// The image file of frames in format; a frame the format cannot hold (a punched track 6-8 in a
/// 5-track image) ends the program naming path (usage, exit 2).
std::string image_text(const tape::ImageFormat& format, std::span<const tape::Frame> frames,
                       const tape::ImageWriteOptions& options, const std::string& path);

/// Fails (usage) when a binary image would go to standard output on a terminal without --force.
void refuse_binary_terminal(const std::string& path, bool binary, bool force);

/// Whether OUT is written into as it is, never replaced: a character device (/dev/null, a terminal) or a
/// FIFO. Such an output is no file that needs --force to be written.
bool written_into(const std::string& path);

/// Fails (exists, exit 2) when OUT is a file that exists and force is not given: called for every output of
/// a run before the first is written, so that a refusal leaves nothing half done.
void refuse_existing(const std::string& path, bool force);

/// OUT ("-" or empty = stdout) opened to be written as it comes and made final by commit(), after the
/// checks every output gets (not an input or another output of the run; not replaced without force).
/// Failure ends the program naming OUT.
std::unique_ptr<tape::OutputFile> open_output(const std::string& path, bool force);

/// Writes data to OUT ("-" or empty = stdout) atomically; refuses to replace a file without force,
/// and a binary image on a terminal without force.
void write_output(const std::string& path, const std::string& data, bool binary, bool force);

}  // namespace cli
