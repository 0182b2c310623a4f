// The tape drawn to scale as SVG: 25.4 mm wide, frames 2.54 mm apart, code holes 1.83 mm and feed
// holes 1.17 mm across, the feed holes between tracks 3 and 4 (ECMA-10, ГОСТ 13052-74).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/code.hpp"
#include "tape/frame.hpp"
#include "tape/picture.hpp"

namespace tape {

/// Why a frame is highlighted; each kind has its colour in the legend.
enum class MarkKind : std::uint8_t {
    parity,    ///< the frame fails the code's parity rule or is no character of it (found by the renderer)
    restored,  ///< a restoration decided it (a vote or a repair): now right
    doubtful,  ///< a restoration could not decide it: written as read or as the reference had it
};
/// "parity error", "restored", "doubtful": the legend's words.
std::string_view mark_name(MarkKind kind);

/// s with & < > " as entities: for text and attribute values in SVG and the HTML pages around it.
std::string xml_escaped(std::string_view s);

/// A frame to highlight, besides the bad frames the renderer finds itself.
struct FrameMark {
    std::uint64_t frame = 0;  ///< 1-based
    MarkKind kind = MarkKind::restored;
    std::string note{};  ///< shown as the mark's tooltip (an SVG <title>)
    std::string link{};  ///< when set, the mark links there (a page's "#p12")
};

struct RenderOptions {
    const FrameCode* code = nullptr;  ///< for the character beside each frame and the bad frames; nullptr: none
    std::uint64_t from = 1;           ///< first frame drawn, 1-based
    std::uint64_t to = 0;             ///< last frame drawn; 0: the end of the tape
    double strip_mm = 254;            ///< tape drawn in strips of this length, one under the other
    bool mirror = false;              ///< seen from the other side: track 1 on top instead of track 8
    std::vector<FrameMark> marks{};   ///< in any order
    /// Frames (any order) given an id "fN" for links even when not marked: an empty outline of the frame.
    std::vector<std::uint64_t> anchors{};
    /// A leader label's frames (tape/label.hpp; first 1-based, 0: none): drawn with no character and
    /// never shaded as bad frames, since their holes are letters.
    std::uint64_t label_first = 0, label_frames = 0;
};

/// Geometry shared by the drawing and its tests, in hundredths of a millimetre (the SVG's user unit).
namespace svg_geometry {
inline constexpr int pitch = 254;        ///< between frames and between tracks
inline constexpr int tape_width = 2540;  ///< 25.4 mm
inline constexpr int left = 600;         ///< from the picture's left edge to a strip's first frame
inline constexpr int legend = 700;       ///< the legend's band at the top
inline constexpr int numbers = 450;      ///< the band of frame numbers above each strip
inline constexpr int characters = 450;   ///< the band of characters below each strip
inline constexpr int gap = 300;          ///< between strips
inline constexpr int strip_pitch = numbers + tape_width + characters + gap;
/// Frames in one strip of length strip_mm (at least one).
std::uint64_t frames_per_strip(double strip_mm);
/// Centre of the hole of frame number n (0-based among the frames drawn) on track (1..8; 0: feed hole).
struct Point {
    std::int64_t x, y;
};
Point hole_centre(std::uint64_t n, int track, std::uint64_t per_strip, bool mirror);
}  // namespace svg_geometry

/// The frames' picture as a whole SVG document, the same bytes for the same input. Bad frames (of
/// options.code, where options.marks has no mark for them) and options.marks are shaded in the legend's colours, each
/// with an id "fN" (N the frame number) for links. Throws Error(Errc::usage) for from after to, or a range past the
/// end.
std::string render_svg(std::span<const Frame> frames, const RenderOptions& options);
/// The same document given to sink a strip at a time (a header, then each strip, then the end): memory
/// that of one strip, however long the tape. Throws as above before anything reaches sink.
void render_svg(std::span<const Frame> frames, const RenderOptions& options,
                const std::function<void(std::string_view)>& sink);

/// How a tape is drawn as pixels: to scale at a resolution, as a scanner or a camera would see it.
struct RasterOptions {
    double dpi = 300;                  ///< pixels per inch: the tape is drawn at its true size
    double strip_mm = 0;               ///< strips of this length one under the other; 0: the whole tape in one strip
    bool mirror = false;               ///< seen from the back: track 1 on top
    int tracks = 8;                    ///< 8 (25.4 mm tape) or 5 (17.46 mm, frames' tracks 1-5 only)
    double margin_mm = 6;              ///< backing shown around the strips
    std::uint32_t paper = 0xF3E6BF;    ///< paper colour, 0xRRGGBB
    std::uint32_t backing = 0x1B1B1B;  ///< what lies under the tape and shows through its holes
    double skew_deg = 0;               ///< the strip turned by this much
    double bow_mm = 0;                 ///< and bent: its middle this far off the line through its ends
    /// Stains on the paper: translucent blotches a few millimetres across (count), and their seed.
    int stains = 0;
    std::uint64_t seed = 1;
};

/// Throws Error(Errc::usage) for options out of range or a picture of more than max_picture_pixels.
Picture render_picture(std::span<const Frame> frames, const RasterOptions& options);
inline constexpr std::uint64_t max_picture_pixels = 1ULL << 30;

/// What a scanner or camera adds to the picture, for testing tape scan on pictures like real ones.
struct PictureEffects {
    double light = 0;      ///< uneven light: the darkest corner this much darker (0..0.9)
    int dust = 0;          ///< specks of dust, each smaller than a feed hole (at most 1 mm across)
    double blur_px = 0;    ///< Gaussian blur, sigma in pixels
    double noise = 0;      ///< Gaussian noise, sigma in grey levels
    int jpeg_quality = 0;  ///< 1..100: saved as JPEG and read back; 0: not
    std::uint64_t seed = 1;
};
/// Applies the effects in the order a picture gets them: light, dust on the glass, blur, noise, JPEG.
/// dpi: the picture's, for the size of the dust. JPEG needs OpenCV (tape/picture.hpp).
void apply_effects(Picture& picture, const PictureEffects& effects, double dpi);

/// Effects written as KEY=VALUE,... : skew=DEG, bow=MM, stains=N, paper=RRGGBB, backing=RRGGBB (the
/// drawing), light=0..0.9, dust=N, blur=PX, noise=LEVELS, jpeg=QUALITY, seed=N (the picture). Throws
/// Error(Errc::usage) naming a key or value it does not take.
void parse_picture_effects(std::string_view spec, RasterOptions& raster, PictureEffects& effects);

}  // namespace tape
