#include "cli/outputs.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <iostream>

#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "tape/file_io.hpp"

namespace cli {

const tape::ImageFormat& output_format(const std::string& format_id, const std::string& path) {
    const tape::ImageFormat* format = format_id.empty() ? nullptr : tape::find_image_format(format_id);
    if (!format && path != "-") format = tape::image_format_for_path(path);
    if (!format) format = &tape::default_image_format();
    if (!format->can_write())
        fail(path, tape::Errc::usage,
             std::string(format->id) + " images can only be read; write " + format_choices(true));
    return *format;
}

std::string image_text(const tape::ImageFormat& format, std::span<const tape::Frame> frames,
                       const tape::ImageWriteOptions& options, const std::string& path) {
    try {
        return format.write(frames, options);
    } catch (const tape::Error& e) {
        fail(path == "-" ? "stdout" : path, e);
    }
}

void refuse_binary_terminal(const std::string& path, bool binary, bool force) {
    if ((path.empty() || path == "-") && binary && ::isatty(STDOUT_FILENO) && !force)
        fail("", tape::Errc::usage,
             "refusing to write a binary tape image to a terminal (use -o FILE, --format holes, or --force)");
}

bool written_into(const std::string& path) {
    struct stat st {};
    return !path.empty() && path != "-" && ::stat(path.c_str(), &st) == 0 &&
           (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode));
}

void refuse_existing(const std::string& path, bool force) {
    struct stat st {};
    if (force || path.empty() || path == "-" || ::lstat(path.c_str(), &st) != 0 || written_into(path)) return;
    fail(path, tape::Error(tape::Errc::exists, "already exists", tape::Hint{tape::Hint::Action::replace_output}));
}

std::unique_ptr<tape::OutputFile> open_output(const std::string& path, bool force) {
    claim_output(path);
    try {
        return std::make_unique<tape::OutputFile>(path, force || written_into(path));
    } catch (const tape::Error& e) {
        fail(path.empty() || path == "-" ? "stdout" : path, e);
    }
}

void write_output(const std::string& path, const std::string& data, bool binary, bool force) {
    claim_output(path);
    if (path.empty() || path == "-") {
        refuse_binary_terminal(path, binary, force);
        std::cout.write(data.data(), static_cast<std::streamsize>(data.size()));
        std::cout.flush();
        if (!std::cout) fail("stdout", tape::Errc::io, "cannot write");
        return;
    }
    try {
        tape::write_file_atomic(path, data, force || written_into(path));
    } catch (const tape::Error& e) {
        fail(path, e);
    }
}

}  // namespace cli
