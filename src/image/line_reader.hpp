// The text image formats with one record a line (hex lines, dumps, bit transcriptions) share how a file
// is cut into lines: here, whatever the chunks it comes in.
#pragma once

#include <string>
#include <string_view>

#include "tape/image.hpp"

namespace tape {

/// Cuts the file into lines and gives each, without its LF, to take_line(). A line longer than 4096
/// characters is refused (no line of these formats is, and memory stays bounded); the last line may
/// lack its LF.
class LineReader : public ImageReader {
public:
    void read(std::span<const std::uint8_t> bytes, std::vector<Frame>& out) final;
    void finish(std::vector<Frame>& out) final;

protected:
    /// One whole line; line_number() is its number, from 1.
    virtual void take_line(std::string_view line, std::vector<Frame>& out) = 0;
    /// After the last line: what a format checks at the end.
    virtual void lines_done(std::vector<Frame>& out) { (void)out; }
    std::uint64_t line_number() const { return line_no_; }
    /// Error(Errc::bad_image) at the line being taken.
    [[noreturn]] void fail(const std::string& why) const;

private:
    void take(std::vector<Frame>& out);

    std::string line_;  // the line being read: a chunk may end inside it
    std::uint64_t line_no_ = 0;
};

}  // namespace tape
