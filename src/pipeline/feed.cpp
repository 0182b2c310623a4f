#include "tape/feed.hpp"

#include <algorithm>

namespace tape {
namespace {

std::vector<Frame> image_frames(Input& input, const FeedOptions& o) {
    std::vector<Frame> frames;
    for (auto chunk = input.next_frames(); !chunk.empty(); chunk = input.next_frames())
        frames.insert(frames.end(), chunk.begin(), chunk.end());
    if (!o.replace_leader && !o.replace_trailer) return frames;
    auto data = punched_part(frames);
    auto before = static_cast<std::size_t>(data.data() - frames.data());
    std::size_t lead = o.replace_leader ? o.encode.leader : before;
    std::size_t trail = o.replace_trailer ? o.encode.trailer : frames.size() - before - data.size();
    std::vector<Frame> out(lead, blank_frame);
    out.insert(out.end(), data.begin(), data.end());
    out.insert(out.end(), trail, blank_frame);
    return out;
}

// The last line that is not blank is a lone '%' after the program (not the '%' that starts it).
bool ends_with_percent_line(std::string_view text) {
    auto last = text.find_last_not_of(" \t\r\n");
    if (last == std::string_view::npos || text[last] != '%') return false;
    auto line = text.rfind('\n', last);
    std::size_t from = line == std::string_view::npos ? 0 : line + 1;
    if (text.substr(from, last + 1 - from).find_first_not_of(" \t\r%") != std::string_view::npos) return false;
    return text.find_first_not_of(" \t\r\n") < from;
}

}  // namespace

std::string semicolons_to_line_ends(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    bool in_comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '\n') in_comment = false;
        if (c == '(') in_comment = true;
        if (c == ')') in_comment = false;
        if (c != ';' || in_comment) {
            out += c;
            continue;
        }
        while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
        std::size_t next = text.find_first_not_of(" \t\r", i + 1);
        if (next == std::string_view::npos || text[next] == '\n') {
            i = next == std::string_view::npos ? text.size() : next - 1;  // the line's own end follows
            if (next == std::string_view::npos) out += '\n';
        } else {
            out += '\n';
            i = next - 1;
        }
    }
    return out;
}

std::vector<Frame> frames_to_send(Input& input, const FeedOptions& o, DialectChoice* chosen) {
    if (input.is_image()) return image_frames(input, o);
    DecodeResult all;
    while (input.next_text(all)) {
    }
    std::string& text = all.text;
    DialectChoice choice{o.dialect, {}};
    if (o.dialect == Dialect::automatic) choice = guess_dialect(text);
    if (chosen) *chosen = choice;
    if (choice.dialect == Dialect::fanuc) text = semicolons_to_line_ends(text);
    if (!text.empty() && text.back() != '\n') text += '\n';
    if (o.percent) {
        auto first = text.find_first_not_of(" \t\r\n");
        if (first == std::string::npos || text[first] != '%') text.insert(0, "%\n");
        if (!ends_with_percent_line(text)) text += "%";
    }
    return encode(text, o.encode);
}

}  // namespace tape
