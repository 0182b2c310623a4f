// Punch-outs on disk: decoded as they arrive, written under a FAILED- name from the first character
// on, renamed once complete. Nothing is replaced, nothing already received is held only in memory.
#include "punch_out.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <ctime>

#include "common/fd_util.hpp"
#include "tape/dnc_request.hpp"
#include "tape/error.hpp"
#include "tape/feed.hpp"
#include "tape/file_io.hpp"

namespace tape::dnc {
namespace {

constexpr std::size_t head_limit = 64 * 1024;

bool is_content(char c) { return c != '%' && c != ' ' && c != '\t' && c != '\r' && c != '\n'; }

std::string local_time_stamp() {
    std::time_t now = std::time(nullptr);
    std::tm tm{};
    ::localtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &tm);
    return text;
}

// Renames from to to unless to exists (also on a file system without RENAME_NOREPLACE). errno on failure.
bool rename_no_replace(const std::string& from, const std::string& to) {
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
    if (errno != EINVAL) return false;
    if (::link(from.c_str(), to.c_str()) != 0) return false;
    ::unlink(from.c_str());
    return true;
}

// The lines of a program that say what it does: ';' ends of block as line ends, CR, trailing blanks,
// blank lines and lone '%' left out.
std::vector<std::string> program_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::string all = semicolons_to_line_ends(text);
    for (std::size_t from = 0; from < all.size();) {
        auto end = all.find('\n', from);
        if (end == std::string::npos) end = all.size();
        std::string line = all.substr(from, end - from);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
        if (!line.empty() && line.find_first_not_of("% \t") != std::string::npos) lines.push_back(line);
        from = end + 1;
    }
    return lines;
}

}  // namespace

bool PunchOutWatch::take(Frame f) {
    if (state_ == State::ended) return false;
    FrameKind kind = code_.kind(f);
    char c = kind == FrameKind::character ? code_.character(f) : '\0';
    if (state_ == State::closing) {
        if (c == '\r') return true;
        state_ = State::ended;
        return c == '\n';
    }
    if (kind == FrameKind::blank || kind == FrameKind::rubout) return true;
    ++punched_;
    if (kind != FrameKind::character) return ++bad_, true;
    if (end_.feed(c) == ProgramEndWatch::Event::program_end) program_end_ = true;
    if (c == '%' && content_ && !noise()) state_ = State::closing;
    if (is_content(c)) content_ = true;
    return true;
}

bool Reception::ends_after(Frame f) {
    if (!write_error.empty()) return false;  // dropped until the line is quiet
    if (watch.take(f)) ++taken_;
    flood = flood || file.bytes() > max_bytes;
    return watch.ended() || flood;
}

void Reception::sink(std::span<const Frame> got) {
    if (!write_error.empty()) {
        dropped += got.size();
        return;
    }
    // The watch took a read's frames from its first on: the rest of the read is the next punch-out's.
    auto mine = static_cast<std::size_t>(std::min<std::uint64_t>(taken_ - frames, got.size()));
    try {
        file.append(got.first(mine));
    } catch (const Error& e) {
        write_error = e.what();
        dropped += got.size();
        frames += mine;
        return;
    }
    frames += mine;
    rest.insert(rest.end(), got.begin() + static_cast<std::ptrdiff_t>(mine), got.end());
}

PunchOutFile::PunchOutFile(std::string folder, std::string machine, const DecodeOptions& decode)
    : folder_(std::move(folder)), machine_(std::move(machine)), decoder_(decode) {}

PunchOutFile::~PunchOutFile() {
    if (fd_ >= 0) ::close(fd_);
}

void PunchOutFile::open() {
    std::string base = folder_ + "/FAILED-" + machine_ + "-" + local_time_stamp();
    for (int n = 1; fd_ < 0; ++n) {
        path_ = base + (n > 1 ? "-" + std::to_string(n) : "") + ".nc";
        fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
        if (fd_ < 0 && (errno != EEXIST || n > 1000)) io_fail(path_ + ": cannot create");
    }
}

void PunchOutFile::append(std::span<const Frame> frames) {
    decoded_.text.clear();
    decoded_.diagnostics.clear();
    decoder_.feed(frames, decoded_);
    if (decoded_.text.empty()) return;
    if (fd_ < 0) open();
    if (!write_all(fd_, decoded_.text)) io_fail(path_ + ": cannot write");
    bytes_ += decoded_.text.size();
    if (head_.size() < head_limit) head_.append(decoded_.text.substr(0, head_limit - head_.size()));
}

std::string PunchOutFile::keep_failed() {
    decoded_.text.clear();
    decoder_.finish(decoded_);
    if (fd_ >= 0 && !decoded_.text.empty()) write_all(fd_, decoded_.text);
    if (fd_ >= 0) ::fsync(fd_);
    return path_;
}

std::string PunchOutFile::file_as(const std::string& stem) {
    keep_failed();
    for (int n = 1; n < 10000; ++n) {
        std::string to = folder_ + "/" + stem + (n > 1 ? "-" + std::to_string(n) : "") + ".nc";
        if (rename_no_replace(path_, to)) {
            int dir = ::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
            if (dir >= 0) ::fsync(dir), ::close(dir);  // the new name on disk too
            return path_ = to;
        }
        if (errno != EEXIST) io_fail(to + ": cannot rename " + path_ + " to it");
    }
    throw Error(Errc::io, folder_ + ": 10000 versions of " + stem + ".nc already");
}

std::string PunchOutFile::keep_written() {
    if (fd_ < 0) return "";
    struct stat st {};
    bool any = ::fstat(fd_, &st) == 0 && st.st_size > 0;  // a failed write may have left part of its text
    if (any) ::fsync(fd_);
    ::close(fd_);
    fd_ = -1;
    if (any) return path_;
    ::unlink(path_.c_str());
    return "";
}

void PunchOutFile::discard() {
    if (fd_ < 0) return;
    ::close(fd_);
    fd_ = -1;
    ::unlink(path_.c_str());
}

std::string compare_with(const std::string& received_text, const std::string& library_path) {
    std::string name = library_path.substr(library_path.rfind('/') + 1);
    std::string library_text;
    try {
        library_text = read_program(library_path);
    } catch (const Error&) {
        return "the library's " + name + " cannot be read";
    }
    auto ours = program_lines(received_text), theirs = program_lines(library_text);
    for (std::size_t i = 0; i < std::max(ours.size(), theirs.size()); ++i)
        if (i >= ours.size() || i >= theirs.size() || ours[i] != theirs[i])
            return "differs from the library's " + name + " from program line " + std::to_string(i + 1);
    return "same as the library's " + name;
}

}  // namespace tape::dnc
