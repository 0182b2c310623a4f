// The stages of reading a tape from a picture (tape/scan.hpp), each on plain data so that each can be
// tested and fuzzed alone: round blobs -> chains of feed holes -> the feed line, one place per frame ->
// the tracks sampled at each place -> frames with their confidence.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tape/scan.hpp"

namespace tape::scan {

/// Grey pixels held by someone else: row-major, 8 bits, stride in bytes.
struct GreyView {
    const std::uint8_t* pixels = nullptr;
    int width = 0, height = 0;
    std::ptrdiff_t stride = 0;

    /// The level at (x, y), interpolated between the four nearest pixels; outside, the nearest edge pixel.
    float at(double x, double y) const;
};

/// A round spot darker or lighter than what surrounds it: a hole, dust, a speck of noise.
struct Blob {
    float x = 0, y = 0;  ///< centroid
    float diameter = 0;  ///< of the circle of the same area
};

/// Feed holes followed along a strip: blob indices in order, and where holes were not seen between them.
struct FeedChain {
    std::vector<std::uint32_t> blobs;
    std::vector<std::uint8_t> missing_before;  ///< per blob: feed holes not seen between it and the one before
    double pitch = 0;                          ///< median distance between neighbouring feed holes
    double hole_ratio = 0;                     ///< mean blob diameter / pitch: 0.46 for feed holes, 0.72 for code holes
    double between = 0;  ///< share of its steps with a blob of its size half-way: a row of code holes every other frame
    double beside = 0;   ///< share of its blobs with one of their size a step away across: code holes, not feed holes
    std::size_t frames() const;  ///< blobs plus the holes missing between them
};

/// The chains of equally spaced blobs of one size that the blobs hold, longest first, each at least
/// min_frames long. Bounded work: at most max_blobs blobs are looked at (the largest-count case is noise).
std::vector<FeedChain> follow_chains(std::span<const Blob> blobs, std::size_t min_frames);
inline constexpr std::size_t max_blobs = 200000;

/// chains[pick] with the other parts of its row joined, where the holes were not seen over a few frames
/// and the part lies a whole number of frames on. unjoined: parts on the row at no whole number of frames.
FeedChain join_parts(std::span<const Blob> blobs, std::span<const FeedChain> chains, std::size_t pick,
                     std::vector<std::size_t>& unjoined);

/// True for a chain whose holes are feed holes (small against their spacing), not a row of code holes.
bool feed_like(const FeedChain& chain);

/// A strip's frames: one place per frame, along the feed line.
struct FeedLine {
    std::vector<ScanPoint> centre;  ///< feed hole centres, in the image's natural order
    std::vector<bool> seen;         ///< false where the hole was placed between its neighbours
    std::vector<ScanPoint> along;   ///< unit vector along the tape at each frame
    std::vector<double> pitch;      ///< local distance between frames, px
};

/// The feed line of a chain, ordered left to right (or top to bottom for a strip nearer upright).
FeedLine feed_line(std::span<const Blob> blobs, const FeedChain& chain);

/// along and pitch of a line from its centres.
void set_directions(FeedLine& line);

/// The line followed on past both ends through the picture, where feed holes too faint to be blobs are
/// still darker (or lighter) than the paper round them; stops after 3 places in a row without one.
void extend_line(const GreyView& picture, FeedLine& line);

/// True when the paper goes on past the line's last frame (its first when at_start) inside the picture:
/// the strip is longer than what was read, its feed holes lost there.
bool strip_goes_on(const GreyView& picture, const FeedLine& line, bool at_start);

/// Skew, bow and bend of a feed line, and whether it runs off a picture of width x height.
struct LineShape {
    double skew_deg = 0, bow_px = 0, bend_deg = 0, pitch = 0;
    bool start_cut = false, end_cut = false;
};
LineShape line_shape(const FeedLine& line, int width, int height);

/// The longest run of frames [first, last) over which the line turns by at most max_bend_deg.
std::pair<std::size_t, std::size_t> straight_run(const FeedLine& line, double max_bend_deg);
/// The frames [first, last) of a line.
FeedLine sub_line(const FeedLine& line, std::size_t first, std::size_t last);

/// How much a place looks like a hole: 0 paper, 1 as the feed holes look; at the centre and on a ring
/// inside the code hole's edge (a speck of dust darkens the centre only).
struct HoleLevel {
    float core = 0, ring = 0;
    float shift = 0;       ///< how far the hole found lies from its place on the grid, in pitches
    bool on_paper = true;  ///< false where the paper around the place is missing (a cut corner, a tear)
};

/// Everything sampled at one frame: the levels at offsets 1..5 on each side of the feed line.
struct FrameSamples {
    float paper = 0, hole = 0;  ///< grey levels of the paper around and of the feed holes near this frame
    bool feed_seen = false;     ///< a feed hole is here: found as a blob, or by its level where the blobs missed it
    HoleLevel left[5], right[5];
    float left_edge = 0, right_edge = 0;  ///< where the paper ends on each side, in pitches (0: not seen)
};

/// Samples every frame of line in picture. across_scale: distance between tracks / distance between frames.
/// A code hole's place moves onto a blob of a code hole's size found near it (blobs: those the line was found among).
std::vector<FrameSamples> sample_frames(const GreyView& picture, const FeedLine& line, double across_scale,
                                        std::span<const Blob> blobs);

/// The distance between tracks against the distance between frames, from the blobs near the line (1 when
/// the blobs do not tell): photos taken at a slant foreshorten one of them.
double across_scale(std::span<const Blob> blobs, const FeedLine& line);

/// Which side of the feed line holds tracks 1-3 (5-track: 1-2), from the paper's edges or the holes.
struct TrackSide {
    bool decided = false;
    bool track1_left = true;  ///< left of the line looking from its first frame to its last
    std::string reason;
};
TrackSide track_side(std::span<const FrameSamples> samples, int tracks);

/// The frames, each hole decided and given a confidence; doubtful frames say why.
std::vector<ScannedFrame> read_frames(const FeedLine& line, std::span<const FrameSamples> samples, int tracks,
                                      bool track1_left, double across_scale);
/// The place of the hole `rows` rows from the feed line (positive: left, looking along the line) at frame i.
ScanPoint hole_place(const FeedLine& line, std::size_t i, double rows, double across_scale);

/// A hole's reading from its levels.
struct HoleReading {
    bool punched = false;
    float confidence = 0;  ///< 0..1; below doubt_below the hole is doubtful
};
HoleReading read_hole(HoleLevel level);
inline constexpr float doubt_below = 0.5F;

/// The reading direction of frames read in the image's natural order: reverse or not, and why.
struct DirectionEvidence {
    bool start_cut = false, end_cut = false;  ///< the first / last frame is at the picture's edge
};
DirectionChoice decide_direction(std::span<const Frame> frames, const DirectionEvidence& evidence, bool& reverse);

/// One piece to stitch: the frames of one strip in the order read, with their confidence and doubts.
struct Piece {
    std::vector<Frame> frames;
    std::vector<float> confidence;
    std::vector<std::string> doubt;    ///< per frame; empty: sure
    std::vector<std::uint32_t> image;  ///< per frame: the image it came from
    std::vector<std::uint32_t> index;  ///< per frame: its place in that image's strip, in the image's order
    bool start_cut = false, end_cut = false;
};
/// The pieces joined where they overlap (in either direction), then the rest in the order given with a
/// gap between them. gaps: the frame (1-based) after which each gap lies.
Piece stitch(std::vector<Piece> pieces, std::vector<std::uint64_t>& gaps);
/// The piece turned end for end.
Piece reversed(Piece p);

}  // namespace tape::scan
