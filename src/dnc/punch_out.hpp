// A punch-out as it arrives: where it ends, and its text on disk from the first frame on.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "tape/code.hpp"
#include "tape/decode.hpp"
#include "tape/line_state.hpp"

namespace tape::dnc {

/// Watches a punch-out's frames: it ends at the first '%' after any content (a Fanuc-style closing
/// '%', a ГОСТ rewind stop after M02/M30), and it is complete when it ended so or its program's end
/// (the block with M02/M30) was seen.
class PunchOutWatch {
public:
    explicit PunchOutWatch(const FrameCode& code) : code_(code) {}
    /// Takes one frame; true when the punch-out ends with it.
    bool feed(Frame f);
    bool content() const { return content_; }
    /// True when the last character was no LF: the closing '%' line's end may still come.
    bool line_open() const { return last_ != '\n'; }
    bool complete() const { return closed_ || program_end_; }

private:
    const FrameCode& code_;
    ProgramEndWatch end_;
    bool content_ = false, closed_ = false, program_end_ = false;
    char last_ = '\n';
};

/// The text of one punch-out, decoded as it arrives and written straight to received/ under the name
/// FAILED-<machine>-<time>.nc, so that whatever ends the service (SIGKILL included) leaves what came;
/// when the punch-out is complete it is renamed to its program's name. Never replaces a file.
class PunchOutFile {
public:
    /// Creates nothing yet: the file appears with the first characters.
    PunchOutFile(std::string folder, std::string machine, const DecodeOptions& decode);
    ~PunchOutFile();
    PunchOutFile(const PunchOutFile&) = delete;
    PunchOutFile& operator=(const PunchOutFile&) = delete;

    /// Decodes frames and appends their text. Throws Error(Errc::io) when the file cannot be written.
    void append(std::span<const Frame> frames);
    /// True once any character (beyond blank tape) came.
    bool started() const { return fd_ >= 0; }
    /// The first 64 KiB of the text, for the request and the program number.
    const std::string& head() const { return head_; }
    std::uint64_t bad_frames() const { return decoder_.bad_frames(); }
    std::uint64_t bytes() const { return bytes_; }
    const std::string& path() const { return path_; }

    /// Flushes it to disk under its FAILED- name; returns that path.
    std::string keep_failed();
    /// Flushes it and renames it to stem.nc, or stem-2.nc, stem-3.nc... beside an existing one; returns
    /// the new path. Throws Error(Errc::io).
    std::string file_as(const std::string& stem);
    /// Removes it (a request, not a program).
    void discard();

private:
    void open();
    std::string folder_, machine_;
    Decoder decoder_;
    DecodeResult decoded_;
    std::string head_, path_;
    std::uint64_t bytes_ = 0;
    int fd_ = -1;
};

/// Says whether a received text is the library's program: "same as F", "differs from F at line N".
std::string compare_with(const std::string& received_text, const std::string& library_path);

}  // namespace tape::dnc
