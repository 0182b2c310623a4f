// A tape image read a chunk at a time: the one way commands and programs open a tape from a file or
// standard input, in bounded memory.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tape/detect.hpp"
#include "tape/file_io.hpp"
#include "tape/frame.hpp"
#include "tape/image.hpp"

namespace tape {

class ImageInput {
public:
    /// Opens path ("-": standard input). The format is the one given, else the one of the file name's
    /// extension, else the one the first bytes fit best; content never overrides a given format.
    /// Throws Error(Errc::io) when the file cannot be read.
    ImageInput(const std::string& path, const ImageFormat* format);
    /// The same over any source; name is used for the extension only.
    ImageInput(std::unique_ptr<ByteSource> source, const std::string& name, const ImageFormat* format);

    const ImageFormat& format() const { return *format_; }

    /// The next frames, valid until the next call; empty once the tape has ended.
    /// Throws Error(Errc::bad_image) where the file does not follow its format.
    std::span<const Frame> next();

    /// Decides the code as detect_code() does on the whole tape, from the frames at its start (read
    /// ahead and given again by read()). At most a few MiB are held, however long the leader.
    CodeDetection detect();

private:
    bool fill();  // reads the next chunk of bytes into frames_; false at the end

    std::unique_ptr<ByteSource> source_;
    const ImageFormat* format_ = nullptr;
    std::vector<std::uint8_t> bytes_;             // read but not yet parsed (holes: an unfinished line)
    std::vector<Frame> ahead_;                    // frames read ahead for detection, given out first
    std::vector<Frame> given_;                    // what next() returned last (ahead_ swapped in)
    std::unique_ptr<std::uint8_t[]> raw_buffer_;  // raw images are read straight into it
    bool ended_ = false;
    bool whole_file_format_ = false;  // a binary format other than raw: parsed whole
    std::uint64_t lines_before_ = 0;  // lines of a text format already parsed
};

}  // namespace tape
