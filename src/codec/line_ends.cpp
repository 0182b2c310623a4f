// Line ends of decoded text (tape/decode.hpp): LFs counted sixteen bytes at a time, and CR LF pairs
// found by the CRs, which most tapes have none of.
#include <cstring>

#include "swar.hpp"
#include "tape/decode.hpp"

namespace tape {

void LineEnds::take(std::string_view text) { take(text, swar::count_newlines(text.data(), text.size())); }

void LineEnds::take(std::string_view text, std::uint64_t newlines) {
    if (text.empty()) return;
    lines += newlines;
    if (after_cr && text.front() == '\n') ++crlf;
    for (const char* cr = static_cast<const char*>(std::memchr(text.data(), '\r', text.size())); cr;) {
        std::size_t next = static_cast<std::size_t>(cr - text.data()) + 1;
        if (next < text.size() && text[next] == '\n') ++crlf;
        cr = static_cast<const char*>(std::memchr(text.data() + next, '\r', text.size() - next));
    }
    after_cr = text.back() == '\r';
}

}  // namespace tape
