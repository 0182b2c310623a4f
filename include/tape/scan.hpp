// Scans and photos of punched tape read as frames (`tape scan`). The geometry comes from the tape
// itself: the strip's feed (sprocket) holes are found and followed, their spacing (2.54 mm) gives the
// scale, their line the skew and bow, and the side of the line that holds three tracks (8-track tape;
// two on 5-track tape) the track order. Each track is sampled at each feed hole, against the paper
// around it and the backing seen through the feed hole itself, so that uneven light, tinted or stained
// paper and dark or light backing all read alike. Every hole gets a confidence; a frame with a hole
// that is not clearly punched or clearly blank is doubtful, never guessed. Several images of one tape
// are stitched by aligning their frames (tape/align.hpp); a gap between images that do not overlap is
// reported with its place. The reading direction is decided by the tape's leader label, its code or
// its leader, and the result says which decided.
//
// Reading images needs OpenCV (core, imgproc, imgcodecs). A build without it has the same functions:
// scan_available() is false and scan_images() throws Error(Errc::io) saying so.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/device.hpp"
#include "tape/frame.hpp"

namespace tape {

/// False in a build without OpenCV: then scan_images() refuses, and so does rendering to PNG.
bool scan_available();
/// What a build without OpenCV says, naming the packages to install.
std::string_view scan_unavailable_message();

/// Which side of the first image the tape's start is at, when the user knows better than the tape.
enum class TapeStart : std::uint8_t { automatic, left, right, top, bottom };
/// "auto", "left", ...; parse_tape_start returns nullopt for other words.
std::string_view tape_start_name(TapeStart s);
std::optional<TapeStart> parse_tape_start(std::string_view word);

struct ScanOptions {
    int tracks = 8;       ///< 8 (feed holes between tracks 3 and 4) or 5 (between tracks 2 and 3)
    double dpi_hint = 0;  ///< the scan's resolution when known: only checked against what the tape shows
    TapeStart start = TapeStart::automatic;
};

/// A point in an image, in pixels (x right, y down; pixel centres at whole numbers).
struct ScanPoint {
    double x = 0, y = 0;
};

/// One frame as the picture shows it: where its feed hole is and how sure each track is.
struct ScannedFrame {
    Frame frame = blank_frame;
    ScanPoint feed{};            ///< the feed hole's centre (measured, or placed between its neighbours)
    bool feed_seen = true;       ///< false: no feed hole was found here; its place was interpolated
    float confidence = 1;        ///< 0..1: the least sure of its holes
    float hole_confidence[8]{};  ///< per track (index 0 = track 1), 0..1
    ScanPoint hole[8]{};         ///< where each track was sampled (5-track tape: the first five)
    std::string doubt{};         ///< why the frame is doubtful; empty for a sure frame
};

/// How the reading direction was decided.
enum class DirectionBasis : std::uint8_t {
    label,   ///< a leader label reads in one direction only
    code,    ///< the characters (line ends, block starts, words) read forwards one way only
    leader,  ///< the blank leader is at one end (the other end has data or a shorter blank run)
    user,    ///< --start said
    none,    ///< nothing decided: read as the image lies, left to right (or top to bottom)
};
std::string_view direction_basis_name(DirectionBasis b);

struct DirectionChoice {
    DirectionBasis basis = DirectionBasis::none;
    bool weak = false;   ///< decided, but by a small margin: the report says so
    std::string reason;  ///< the evidence, in words
};

/// What was seen of one tape strip in one image.
struct StripScan {
    std::vector<ScannedFrame> frames;  ///< in the order read (the tape's order once the direction is decided)
    double pitch_px = 0;               ///< median distance between feed holes
    double dpi = 0;                    ///< from the pitch: 2.54 mm a frame
    double skew_deg = 0;               ///< the feed line against the image's nearest axis
    double bow_mm = 0;                 ///< largest distance of a feed hole from the straight line through them
    double bend_deg = 0;               ///< how much the feed line turns from one end to the other
    bool holes_dark = true;            ///< holes darker than the paper (a dark backing)
    bool track1_side_left = true;      ///< tracks 1-3 (5-track: 1-2) lie left of the feed line, looking along the read
    std::string track_order_basis;     ///< what told the side of track 1: the paper's edges, or the holes
    bool mirrored = false;             ///< seen from the back: track 1 on top when the start is at the left
    bool reversed = false;             ///< read against the image's natural order (right to left, bottom to top)
    bool start_cut = false, end_cut = false;  ///< the strip runs off the picture at its first / last frame
};

/// One image's part in a scan.
struct ImageScan {
    std::string name;                ///< as given
    int width = 0, height = 0;       ///< in pixels
    std::optional<StripScan> strip;  ///< the strip read; none when the image was refused
    std::string refusal;             ///< why nothing was read (empty when read)
    std::vector<std::string> notes;  ///< what else was seen: other strips, a dpi unlike the hint
    std::size_t parts_unread = 0;    ///< parts of the strip read that could not be joined to it (in notes)
    std::uint64_t first_frame = 0;   ///< where its frames start in the whole read (1-based; 0: not used)
    std::uint64_t frames_used = 0;   ///< frames it gave the whole read (others lay in an overlap)
    std::vector<ScanPoint> blobs;    ///< every round blob looked at (for the debug picture)
};

/// A place where the images read do not join: frames are missing there, how many is unknown.
struct ScanGap {
    std::uint64_t after = 0;  ///< the frame of the read before the gap (1-based)
    std::string before_image, after_image;
};

struct ScanResult {
    std::vector<Frame> frames;      ///< the read
    std::vector<float> confidence;  ///< per frame, 0..1
    FrameDoubts doubts;             ///< the doubtful frames, as a reader's flagged rows
    std::vector<ImageScan> images;  ///< in the order given
    std::vector<ScanGap> gaps;      ///< images that join no other image
    DirectionChoice direction;
    /// True when every image was read, none leaves a gap and no frame is doubtful.
    bool complete() const;
};

/// Reads the images (PNG, JPEG, TIFF, anything OpenCV's imgcodecs reads) as one tape. An image with
/// no readable strip is refused in its ImageScan (the others are still read). Throws Error(Errc::io)
/// for a file that cannot be read or decoded, Error(Errc::bad_image) when no image gives a strip (its
/// message says what was seen), Error(Errc::usage) for options out of range.
ScanResult scan_images(std::span<const std::string> paths, const ScanOptions& options = {});

/// The image with what was found drawn over it, as SVG: the feed line, every feed hole, each track's
/// place coloured by its reading (punched, blank, doubtful), the blobs looked at. image_href is what the
/// SVG links the picture by (a path relative to the SVG, or a file URI).
std::string scan_debug_svg(const ImageScan& image, std::string_view image_href);

}  // namespace tape
