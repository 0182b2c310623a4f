// The pictures' pieces made one read (tape/scan.hpp): stitched, turned to the tape's direction, the
// doubtful frames gathered into runs as a reader's flagged rows are.
#include "scan/scan_result.hpp"

#include <algorithm>

#include "tape/error.hpp"

namespace tape {

std::string_view tape_start_name(TapeStart s) {
    switch (s) {
        case TapeStart::automatic:
            return "auto";
        case TapeStart::left:
            return "left";
        case TapeStart::right:
            return "right";
        case TapeStart::top:
            return "top";
        case TapeStart::bottom:
            return "bottom";
    }
    return "?";
}

std::optional<TapeStart> parse_tape_start(std::string_view word) {
    for (auto s : {TapeStart::automatic, TapeStart::left, TapeStart::right, TapeStart::top, TapeStart::bottom})
        if (tape_start_name(s) == word) return s;
    return std::nullopt;
}

bool ScanResult::complete() const {
    for (const auto& i : images)
        if (!i.strip || i.parts_unread) return false;
    return gaps.empty() && doubts.runs.empty() && doubts.unkept == 0;
}

}  // namespace tape

namespace tape::scan {
namespace {

// True when picture m's frames run in the read as in the picture (left to right, top to bottom).
bool runs_forward(const Piece& read, std::uint32_t m) {
    std::optional<std::uint32_t> first;
    for (std::size_t k = 0; k < read.frames.size(); ++k) {
        if (read.image[k] != m) continue;
        if (first && read.index[k] != *first) return read.index[k] > *first;
        first = read.index[k];
    }
    return true;
}

// The direction: as the user said (for the first picture read), else as the tape tells.
DirectionChoice direction_of(const Piece& read, const ScanOptions& o, bool& reverse) {
    if (o.start == TapeStart::automatic)
        return decide_direction(read.frames, DirectionEvidence{read.start_cut, read.end_cut}, reverse);
    std::uint32_t first = read.image.empty() ? 0 : *std::min_element(read.image.begin(), read.image.end());
    bool natural_start = o.start == TapeStart::left || o.start == TapeStart::top;
    reverse = runs_forward(read, first) != natural_start;
    return {DirectionBasis::user, false,
            "--start " + std::string(tape_start_name(o.start)) + ": the tape starts at the first picture's " +
                std::string(tape_start_name(o.start))};
}

// Runs of doubtful frames alike, numbered from 1.
FrameDoubts doubt_runs(const Piece& read) {
    FrameDoubts out;
    for (std::size_t i = 0; i < read.frames.size(); ++i) {
        if (read.doubt[i].empty()) continue;
        std::uint64_t frame = i + 1;
        if (!out.runs.empty() && out.runs.back().last + 1 == frame && out.runs.back().what == read.doubt[i])
            out.runs.back().last = frame;
        else
            out.runs.push_back({frame, frame, read.doubt[i]});
    }
    return out;
}

// Each picture's place in the read, its frames turned to the read's direction.
void place_images(const Piece& read, std::vector<ImageScan>& images) {
    for (std::size_t k = 0; k < read.frames.size(); ++k) {
        ImageScan& im = images[read.image[k]];
        if (im.first_frame == 0) im.first_frame = k + 1;
        ++im.frames_used;
    }
    for (std::size_t m = 0; m < images.size(); ++m) {
        auto& im = images[m];
        if (!im.strip) continue;
        bool backwards = !runs_forward(read, static_cast<std::uint32_t>(m));
        im.strip->reversed = backwards;
        if (backwards) {
            std::reverse(im.strip->frames.begin(), im.strip->frames.end());
            im.strip->track1_side_left = !im.strip->track1_side_left;
        }
        // Track 8 on top with the start at the left is the tape seen from its front (tape render).
        im.strip->mirrored = im.strip->track1_side_left;
    }
}

}  // namespace

ScanResult assemble(std::vector<ImageScan> images, std::vector<Piece> pieces, const ScanOptions& options) {
    ScanResult r;
    std::vector<std::uint64_t> gaps;
    Piece read = stitch(std::move(pieces), gaps);
    bool reverse = false;
    r.direction = direction_of(read, options, reverse);
    if (reverse) {
        read = reversed(std::move(read));
        for (auto& g : gaps) g = read.frames.size() - g;
        std::reverse(gaps.begin(), gaps.end());
    }
    for (auto g : gaps) r.gaps.push_back(ScanGap{g, images[read.image[g - 1]].name, images[read.image[g]].name});
    r.frames = read.frames;
    r.confidence = read.confidence;
    r.doubts = doubt_runs(read);
    place_images(read, images);
    r.images = std::move(images);
    return r;
}

}  // namespace tape::scan
