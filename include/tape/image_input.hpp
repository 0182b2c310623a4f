// A tape image read a chunk at a time: the one way commands and programs open a tape from a file or
// standard input, in bounded memory.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tape/detect.hpp"
#include "tape/file_io.hpp"
#include "tape/frame.hpp"
#include "tape/image.hpp"
#include "tape/label.hpp"

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

    /// The verdict of detect_code() on the tape, from a read-ahead of its first 256 Ki frames (the whole
    /// of most tapes), given again by next(). That many frames are held, 4 MiB past an endless leader.
    /// A leader label's frames are read as blank tape for the verdict.
    CodeDetection detect(const CodeTable* eia_table = nullptr);

    /// The code the image's header names ("# code: mtk2" in hex5, hex8 and holes files this tool wrote),
    /// looked for in the first chunk; nullopt when it names none.
    std::optional<Code> declared_code();

    /// The label in the tape's leader (tape/label.hpp), looked for once, before the first next(), in a
    /// read-ahead of the leader and label_search_frames more (given again by next()); nullopt when
    /// there is none or next() had already given frames.
    const std::optional<LeaderLabel>& label();

private:
    bool fill();
    void allocate_buffer();  // reads the next chunk of bytes into frames_; false at the end

    std::unique_ptr<ByteSource> source_;
    const ImageFormat* format_ = nullptr;
    std::unique_ptr<ImageReader> reader_;
    std::vector<std::uint8_t> bytes_;  // read for format detection, not yet given to reader_
    std::vector<Frame> ahead_;         // frames read ahead for detection, given out first
    std::vector<Frame> given_;         // what next() returned last (ahead_ swapped in)
    // Chunks are read into it (raw frames straight from it); page-aligned, where read() copies fastest.
    std::unique_ptr<std::uint8_t, void (*)(void*)> read_buffer_{nullptr, std::free};
    bool ended_ = false;
    bool given_any_ = false;  // next() has given frames: the read-ahead no longer starts the tape
    bool label_checked_ = false;
    std::optional<LeaderLabel> label_;
};

}  // namespace tape
