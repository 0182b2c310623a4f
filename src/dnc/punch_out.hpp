// A punch-out as it arrives: where it ends, and its text on disk from the first frame on.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tape/code.hpp"
#include "tape/decode.hpp"
#include "tape/line_state.hpp"

namespace tape::dnc {

/// Watches a punch-out's frames and says where it ends: at the first '%' after any content (a
/// Fanuc-style closing '%', a ГОСТ rewind stop after M02/M30) and the end of that line (CR, LF) when
/// it follows at once; a frame after that starts the next punch-out. It is complete when it ended so
/// or its program's end (the block with M02/M30) was seen. A punch-out a quarter or more of whose
/// punched frames are bad is noise: no '%' ends it (only a quiet line does), and it is no program.
class PunchOutWatch {
public:
    explicit PunchOutWatch(const FrameCode& code) : code_(code) {}
    /// Takes one frame; false when it is not this punch-out's (the punch-out ended before it).
    bool take(Frame f);
    /// The closing '%' and its line end came (or a frame that is not its line end).
    bool ended() const { return state_ == State::ended; }
    /// The closing '%' came, its line end not yet: it follows at once when it comes at all.
    bool closing() const { return state_ == State::closing; }
    /// Any character besides '%', blanks and line ends came.
    bool content() const { return content_; }
    bool complete() const { return state_ != State::open || program_end_; }
    bool noise() const { return bad_ > 0 && bad_ * 4 >= punched_; }
    std::uint64_t bad_frames() const { return bad_; }
    std::uint64_t punched_frames() const { return punched_; }

private:
    enum class State { open, closing, ended };
    const FrameCode& code_;
    ProgramEndWatch end_;
    State state_ = State::open;
    bool content_ = false, program_end_ = false;
    std::uint64_t bad_ = 0, punched_ = 0;  // frames failing the code, frames besides blank tape and DEL
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
    /// Removes it (a request, not a program, or nothing but blanks and line ends).
    void discard();
    /// Stops writing after a failed write: keeps what is on disk under its FAILED- name (removes it
    /// when nothing is), takes no more frames. Returns that path, or "" when nothing was kept.
    std::string keep_written();

private:
    void open();
    std::string folder_, machine_;
    Decoder decoder_;
    DecodeResult decoded_;
    std::string head_, path_;
    std::uint64_t bytes_ = 0;
    int fd_ = -1;
};

/// One punch-out as it is received, read by read: receive_frames asks ends_after of each frame and
/// then gives the read's frames to sink. The frames the watch takes are written to the file; those
/// after its end go to `rest`, the start of the next punch-out. After a failed write nothing more is
/// written: the file keeps what it had, every frame after is counted as dropped, and write_error says why.
struct Reception {
    Reception(const FrameCode& code, std::string folder, std::string machine, const DecodeOptions& decode,
              std::uint64_t max_bytes, std::vector<std::uint8_t>& rest)
        : watch(code), file(std::move(folder), std::move(machine), decode), max_bytes(max_bytes), rest(rest) {}

    /// True once the punch-out ended (or grew past max_bytes: a flood).
    bool ends_after(Frame f);
    void sink(std::span<const Frame> frames);

    PunchOutWatch watch;
    PunchOutFile file;
    std::uint64_t max_bytes;
    std::vector<std::uint8_t>& rest;
    std::uint64_t frames = 0;   ///< this punch-out's frames handed to the file (or dropped after a failure)
    std::uint64_t dropped = 0;  ///< frames dropped after a failed write
    bool flood = false;
    std::string write_error;

private:
    std::uint64_t taken_ = 0;  // frames the watch took as this punch-out's
};

/// Says whether a received text is the library's program: "same as F", "differs from F at line N".
std::string compare_with(const std::string& received_text, const std::string& library_path);

}  // namespace tape::dnc
