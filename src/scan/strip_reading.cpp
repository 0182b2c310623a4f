// One picture's strip read (scan_geometry.hpp, tape/scan.hpp): the longest straight chain of feed
// holes, its feed line, the tracks sampled and decided. What cannot be read is refused with what was
// seen; other strips in the picture are named, not read.
#include "scan/strip_reading.hpp"

#include <cmath>
#include <string>

namespace tape::scan {
namespace {

constexpr double max_bend_deg = 10;  // a tape lying flat turns less than this from end to end

std::string whole(double v) { return std::to_string(static_cast<long long>(std::lround(v))); }

std::string where(const Blob& b) { return "(" + whole(b.x) + ", " + whole(b.y) + ")"; }

std::string refusal_for(std::span<const FeedChain> chains, std::span<const Blob> blobs) {
    std::size_t feed = 0, longest = 0;
    for (const auto& c : chains)
        if (feed_like(c)) ++feed, longest = std::max(longest, c.frames());
    std::string seen = std::to_string(blobs.size()) + " round spots";
    if (chains.empty()) return "no strip of punched tape found: " + seen + ", no row of evenly spaced holes";
    if (feed == 0)
        return "no row of feed holes found: " + seen + ", " + std::to_string(chains.size()) +
               " rows of evenly spaced holes, none of holes the size of feed holes for " +
               std::to_string(min_strip_frames) + " frames or more";
    return "found " + std::to_string(feed) + " strip(s), none straight for more than " +
           std::to_string(min_strip_frames) + " frames (the longest row of feed holes: " + std::to_string(longest) +
           " frames)";
}

// The strip's frames, or a refusal in image.refusal.
std::optional<FeedLine> straight_line(std::span<const Blob> blobs, const FeedChain& chain, ImageScan& image) {
    FeedLine line = feed_line(blobs, chain);
    LineShape shape = line_shape(line, image.width, image.height);
    if (shape.bend_deg <= max_bend_deg) return line;
    auto [first, last] = straight_run(line, max_bend_deg);
    std::string bend = "the strip turns by " + whole(shape.bend_deg) + "° (coiled, folded or curled)";
    if (last - first < min_strip_frames) {
        image.refusal = bend + ": none of it straight for more than " + std::to_string(min_strip_frames) + " frames";
        return std::nullopt;
    }
    image.notes.push_back(bend + ": only its straight part is read, frames " + std::to_string(first + 1) + " to " +
                          std::to_string(last) + " of " + std::to_string(line.centre.size()) + " from the picture's " +
                          (std::abs(shape.skew_deg) < 45 ? "left" : "top"));
    return sub_line(line, first, last);
}

double hole_size(const FeedChain& c) { return c.hole_ratio * c.pitch; }

// True when chain lies within the strip of line (its code holes, read two frames apart, make chains too).
bool on_strip(const FeedChain& chain, std::span<const Blob> blobs, const FeedLine& line) {
    const Blob& b = blobs[chain.blobs[chain.blobs.size() / 2]];
    for (std::size_t i = 0; i < line.centre.size(); ++i)
        if (std::hypot(b.x - line.centre[i].x, b.y - line.centre[i].y) < 7 * line.pitch[i]) return true;
    return false;
}

// Other strips: rows of holes of the read strip's feed holes' size and spacing, elsewhere in the picture.
void describe_others(std::span<const FeedChain> chains, std::size_t read, std::span<const Blob> blobs,
                     const FeedLine& line, ImageScan& image) {
    auto alike = [&](double a, double b) { return a < 1.25 * b && b < 1.25 * a; };
    for (std::size_t i = 0; i < chains.size(); ++i) {
        const FeedChain& c = chains[i];
        if (i == read || !feed_like(c) || c.frames() < min_strip_frames || !alike(c.pitch, chains[read].pitch) ||
            !alike(hole_size(c), hole_size(chains[read])) || on_strip(c, blobs, line))
            continue;
        const Blob& b = blobs[c.blobs.front()];
        image.notes.push_back("another strip of " + std::to_string(c.frames()) + " frames starts at " + where(b) +
                              ": not read (one strip a picture; crop the picture to read it)");
    }
}

// The strip to read: the longest row of feed holes. Code holes are 1.56 times as wide as feed holes, and
// a row of them punched every other frame is spaced like feed holes: only rows of the smallest holes count.
std::size_t pick_strip(std::span<const FeedChain> chains) {
    double smallest = 0;
    for (const auto& c : chains)
        if (feed_like(c) && c.frames() >= min_strip_frames && (smallest == 0 || hole_size(c) < smallest))
            smallest = hole_size(c);
    std::size_t pick = chains.size();
    for (std::size_t i = 0; i < chains.size(); ++i)
        if (feed_like(chains[i]) && chains[i].frames() >= min_strip_frames && hole_size(chains[i]) <= 1.25 * smallest &&
            (pick == chains.size() || chains[i].frames() > chains[pick].frames()))
            pick = i;
    return pick;
}

// Ends where the paper goes on but its feed holes were lost: the frame there is doubtful, the rest unread.
void mark_unread_ends(const GreyView& picture, const FeedLine& line, std::vector<ScannedFrame>& frames,
                      ImageScan& image) {
    for (bool at_start : {true, false}) {
        if (frames.empty() || !strip_goes_on(picture, line, at_start)) continue;
        ScannedFrame& f = at_start ? frames.front() : frames.back();
        f.confidence = 0;
        f.doubt = "the strip goes on past this frame, its feed holes lost: the rest of it is not read";
        image.notes.push_back("the strip goes on past its " + std::string(at_start ? "first" : "last") +
                              " frame in the picture, at " +
                              where(Blob{static_cast<float>(f.feed.x), static_cast<float>(f.feed.y), 0}) +
                              ", where its feed holes are lost: not read");
        ++image.parts_unread;
    }
}

bool any_hole(std::span<const FrameSamples> samples) {
    for (const auto& s : samples)
        for (int o = 0; o < 5; ++o)
            if (read_hole(s.left[o]).punched || read_hole(s.right[o]).punched) return true;
    return false;
}

}  // namespace

std::optional<Piece> read_strip(const GreyView& picture, std::span<const Blob> blobs, std::span<const FeedChain> chains,
                                const ScanOptions& options, std::uint32_t image_number, ImageScan& image) {
    std::size_t pick = pick_strip(chains);
    if (pick == chains.size()) {
        image.refusal = refusal_for(chains, blobs);
        return std::nullopt;
    }
    std::vector<std::size_t> unjoined;
    FeedChain chain = join_parts(blobs, chains, pick, unjoined);
    for (auto k : unjoined) {
        const Blob& b = blobs[chains[k].blobs.front()];
        image.notes.push_back("a part of the strip (" + std::to_string(chains[k].frames()) + " frames, from " +
                              where(b) +
                              ") lies beyond a place where its feed holes are not seen, at no whole number of frames: "
                              "not read");
    }
    image.parts_unread = unjoined.size();
    auto line = straight_line(blobs, chain, image);
    if (!line) return std::nullopt;
    extend_line(picture, *line);
    describe_others(chains, pick, blobs, *line, image);
    StripScan strip;
    LineShape shape = line_shape(*line, image.width, image.height);
    double across = across_scale(blobs, *line);
    auto samples = sample_frames(picture, *line, across, blobs);
    TrackSide side = track_side(samples, options.tracks);
    if (!side.decided && any_hole(samples)) {
        image.refusal = "cannot tell which side of the feed line holds track 1: " + side.reason;
        return std::nullopt;
    }
    strip.frames = read_frames(*line, samples, options.tracks, side.track1_left, across);
    mark_unread_ends(picture, *line, strip.frames, image);
    strip.pitch_px = shape.pitch;
    strip.dpi = shape.pitch / 2.54 * 25.4;
    strip.skew_deg = shape.skew_deg;
    strip.bow_mm = shape.pitch > 0 ? shape.bow_px / shape.pitch * 2.54 : 0;
    strip.bend_deg = shape.bend_deg;
    strip.holes_dark = samples.empty() || samples[samples.size() / 2].paper > samples[samples.size() / 2].hole;
    strip.track1_side_left = side.track1_left;
    strip.track_order_basis = side.decided ? side.reason : "no holes: blank tape reads the same either way";
    strip.start_cut = shape.start_cut;
    strip.end_cut = shape.end_cut;
    if (options.dpi_hint > 0 && std::abs(strip.dpi / options.dpi_hint - 1) > 0.1)
        image.notes.push_back("the feed holes are " + whole(shape.pitch) + " px apart: " + whole(strip.dpi) +
                              " dpi, not the " + whole(options.dpi_hint) + " dpi given");
    Piece piece;
    for (std::size_t i = 0; i < strip.frames.size(); ++i) {
        const auto& f = strip.frames[i];
        piece.frames.push_back(f.frame);
        piece.confidence.push_back(f.confidence);
        piece.doubt.push_back(f.doubt);
        piece.image.push_back(image_number);
        piece.index.push_back(static_cast<std::uint32_t>(i));
    }
    piece.start_cut = strip.start_cut;
    piece.end_cut = strip.end_cut;
    image.strip = std::move(strip);
    return piece;
}

}  // namespace tape::scan
