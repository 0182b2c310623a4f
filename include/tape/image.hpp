// Tape image formats: each is a module in one table (raw, holes, hex, hex8, hex5).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/code.hpp"
#include "tape/frame.hpp"

namespace tape {

/// How the holes writer annotates frames: decoded character and frame number, by this code.
struct ImageWriteOptions {
    const FrameCode* annotate = nullptr;  ///< nullptr: frame numbers only
    std::uint64_t first_number = 1;       ///< number of the first frame (when appending to an image)
    bool header = true;                   ///< write the format's header, if it has one
};

/// Reads one image format a chunk at a time, so that a file of any length is read in bounded memory.
class ImageReader {
public:
    virtual ~ImageReader() = default;
    /// Parses the next bytes of the file and appends the frames they complete to out; a piece not yet
    /// complete (a text line cut by the chunk's end) is kept for the next call. Throws
    /// Error(Errc::bad_image) with the line or byte offset counted from the start of the file.
    virtual void read(std::span<const std::uint8_t> bytes, std::vector<Frame>& out) = 0;
    /// The file has ended: appends the frames of what was kept.
    virtual void finish(std::vector<Frame>& out) = 0;
    /// The code the file's header comment names ("# code: mtk2", as this tool's writers put it), once the
    /// header has been read; nullopt when it names none or the format has no header.
    virtual std::optional<Code> declared_code() const { return std::nullopt; }
};

/// Writes one image format a piece at a time; the output is the concatenation of what it appends.
class ImageWriter {
public:
    virtual ~ImageWriter() = default;
    /// Appends the picture of the next frames (and, the first time, the format's header) to out.
    virtual void write(std::span<const Frame> frames, std::string& out) = 0;
    /// The last frames have been written: appends what closes the file, if the format has anything.
    virtual void finish(std::string& out) { (void)out; }
};

/// One image format: one file under src/image/ and one line in the table of src/image/image.cpp.
/// A format may only read (a reader's dump) or only write (a picture): the other function is null.
struct ImageFormat {
    std::string_view id;  ///< "raw", "holes"
    std::string_view description;
    std::span<const std::string_view> extensions;  ///< with the dot: ".ptp"
    bool binary;                                   ///< not for a terminal
    /// The file's bytes are its frames, one byte each: readers may take them without parsing.
    bool bytes_are_frames;
    /// How sure the format is that bytes (a prefix of the file) are its own: 0 (no) to 100.
    int (*match)(std::span<const std::uint8_t> prefix);
    std::unique_ptr<ImageReader> (*make_reader)();                                  ///< null: cannot read
    std::unique_ptr<ImageWriter> (*make_writer)(const ImageWriteOptions& options);  ///< null: cannot write
    /// The tape the format holds: 8 tracks (any byte), or 5 (frames below 0x20, whose code, ITA2 or
    /// МТК-2, only the user can say).
    int tracks = 8;

    bool can_read() const { return make_reader != nullptr; }
    bool can_write() const { return make_writer != nullptr; }
    /// Frames from a whole file in memory, through the reader.
    std::vector<Frame> read(std::span<const std::uint8_t> bytes) const;
    /// The whole file for frames, through the writer.
    std::string write(std::span<const Frame> frames, const ImageWriteOptions& options) const;
};

/// All formats, in the order detection tries them.
std::span<const ImageFormat> image_formats();
/// By id, or nullptr.
const ImageFormat* find_image_format(std::string_view id);
/// By the file name's extension (case-insensitive), or nullptr.
const ImageFormat* image_format_for_path(std::string_view path);
/// True for a name whose extension says nothing sure (".txt": a holes picture as often as a text
/// program): there the content decides, where an image extension (".ptp", ".holes") otherwise does.
bool extension_is_ambiguous(std::string_view path);
/// The format whose match is most confident for this prefix (raw when nothing else fits); only formats
/// that can read are considered.
const ImageFormat& detect_image_format(std::span<const std::uint8_t> prefix);
/// The format written when none is asked for (raw: what readers and simulators take).
const ImageFormat& default_image_format();

}  // namespace tape
