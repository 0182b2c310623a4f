// Lines of a text image (line_reader.hpp).
#include "line_reader.hpp"

#include "tape/error.hpp"

namespace tape {
namespace {

constexpr std::size_t longest_line = 4096;

}  // namespace

void LineReader::read(std::span<const std::uint8_t> bytes, std::vector<Frame>& out) {
    for (std::uint8_t c : bytes) {
        if (c == '\n') {
            take(out);
            continue;
        }
        if (line_.size() >= longest_line)
            throw Error(Errc::bad_image, Position{.line = line_no_ + 1}, "a line of more than 4096 characters");
        line_ += static_cast<char>(c);
    }
}

void LineReader::finish(std::vector<Frame>& out) {
    if (!line_.empty()) take(out);
    lines_done(out);
}

void LineReader::fail(const std::string& why) const { throw Error(Errc::bad_image, Position{.line = line_no_}, why); }

void LineReader::take(std::vector<Frame>& out) {
    ++line_no_;
    take_line(line_, out);
    line_.clear();
}

}  // namespace tape
