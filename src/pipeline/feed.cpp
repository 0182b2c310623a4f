#include "tape/feed.hpp"

#include <algorithm>

namespace tape {
namespace {

std::vector<Frame> image_frames(Input& input, const FeedOptions& o) {
    std::vector<Frame> frames;
    for (auto chunk = input.next_frames(); !chunk.empty(); chunk = input.next_frames())
        frames.insert(frames.end(), chunk.begin(), chunk.end());
    if (!o.replace_leader && !o.replace_trailer) return frames;
    auto first = std::find_if(frames.begin(), frames.end(), [](Frame f) { return f != blank_frame; });
    auto last = std::find_if(frames.rbegin(), std::make_reverse_iterator(first), [](Frame f) {
                    return f != blank_frame;
                }).base();
    std::size_t lead = o.replace_leader ? o.encode.leader : static_cast<std::size_t>(first - frames.begin());
    std::size_t trail = o.replace_trailer ? o.encode.trailer : static_cast<std::size_t>(frames.end() - last);
    std::vector<Frame> out(lead, blank_frame);
    out.insert(out.end(), first, last);
    out.insert(out.end(), trail, blank_frame);
    return out;
}

}  // namespace

std::vector<Frame> frames_to_send(Input& input, const FeedOptions& o) {
    if (input.is_image()) return image_frames(input, o);
    DecodeResult all;
    while (input.next_text(all)) {
    }
    std::string& text = all.text;
    auto first = text.find_first_not_of(" \t\r\n");
    if (o.percent_first && (first == std::string::npos || text[first] != '%')) text.insert(0, "%\n");
    if (!text.empty() && text.back() != '\n') text += '\n';
    if (o.percent_end) text += "%";
    return encode(text, o.encode);
}

}  // namespace tape
