// A program's toolpath drawn (tape plot): the interpreter's moves (tape/motion.hpp) kept in a compact form,
// seen from one side, cut down to what shows at the picture's resolution (moves under a pixel dropped,
// collinear segments merged, a segment drawn over again drawn once), and drawn with cairo as SVG, PNG
// or PDF, or as an HTML page whose moves name their blocks on hover.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/motion.hpp"

namespace tape {

/// One move of the toolpath as drawn: a rapid, a feed or an arc, where it came from, and whether the
/// frames it was read from are in doubt.
struct PathMove {
    Point start{}, end{}, centre{};
    /// rapid, linear or arc; or not_simulated: a block the interpreter could not follow (a bad frame, a
    /// macro value), marked at the place the tool last stood (start == end)
    MoveKind kind = MoveKind::linear;
    Plane plane = Plane::xy;  ///< arcs
    bool clockwise = false;   ///< arcs, seen from the plane's normal axis
    bool doubt = false;       ///< read from a frame that failed parity, was in doubt or guessed
    int turns = 0;            ///< arcs: whole extra turns
    int tool = 0;
    unsigned known = all_axes;                  ///< axes known (AxisBit): a view needs its two
    std::uint64_t block = 0;                    ///< Block::ordinal
    std::uint64_t line = 0;                     ///< of the block's first character
    std::optional<std::uint64_t> frame{};       ///< the block's first frame, from a tape
    std::optional<std::uint64_t> last_frame{};  ///< and its last
};

/// The moves of a program kept for drawing; events (tool changes, spindle, ...) are not kept, their
/// effect is in each move's tool. A move with no axis known (the first, from where the tool stood before
/// the program) is counted, not kept; a view draws the moves whose two axes are known.
class Toolpath : public MotionVisitor {
public:
    /// keep_blocks: each move's block text is kept too (for the HTML page's hover).
    explicit Toolpath(bool keep_blocks = false) : keep_blocks_(keep_blocks) {}

    void move(const Move& move) override;
    void program_start(const Program& header) override;
    /// A block of a called subprogram: its text kept for its moves (its frames were noted in text order).
    void subprogram_block(const Block& block) override;
    /// Moves read from any of frames (1-based, any order) are in doubt: drawn in the doubt colour.
    void mark_doubtful(std::vector<std::uint64_t> frames);
    /// The block the interpreter is about to be given: where its frames start (for mark_doubtful), and
    /// with keep_blocks its text, kept for its moves.
    void note_block(const Block& block);

    const std::vector<PathMove>& moves() const { return moves_; }
    /// The block text of moves()[i] (keep_blocks), else empty.
    std::string_view block_text(std::size_t i) const;
    /// Moves not kept because no axis of the tool's place was known (a program's first move).
    std::uint64_t unknown_moves() const { return unknown_; }
    /// The moves not simulated, in program order (at most 100 kept): their notes, at their blocks.
    const std::vector<Move>& not_simulated() const { return not_simulated_; }
    std::uint64_t not_simulated_count() const { return not_simulated_count_; }

private:
    void keep(const Move& move);
    std::uint64_t last_frame_of(const PathMove& move) const;

    std::vector<PathMove> moves_;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> block_frames_;  // block ordinal, its first frame
    bool keep_blocks_;
    std::string texts_;                   // block texts, one after the other (keep_blocks)
    std::vector<std::uint32_t> text_at_;  // where each move's block text starts in texts_
    std::uint64_t last_block_ = 0, source_block_ = 0;
    std::string source_;
    std::uint64_t unknown_ = 0, not_simulated_count_ = 0;
    std::vector<Move> not_simulated_;
    Point last_end_{};
    unsigned last_known_ = all_axes;
    bool has_last_ = false;  // last_end_ is where the tool stands
};

/// Which side the toolpath is seen from.
enum class PlotView : std::uint8_t {
    xy,     ///< a mill from above (+Z): X across, Y up
    xz,     ///< a mill from the front (-Y): X across, Z up
    yz,     ///< a mill from the side (+X): Y across, Z up
    lathe,  ///< a lathe's half profile: Z across, X up (back tool post) or down (front tool post)
};

struct PlotOptions {
    PlotView view = PlotView::xy;
    bool front_post = false;  ///< lathe: the tool in front of the spindle axis, +X down on the page
    bool diameter = false;    ///< lathe: X drawn as the diameter (the profile stretched twice across)
    int width = 1200;         ///< the picture's size in pixels (PNG) or points (SVG, PDF)
    int height = 900;
    std::string title{};     ///< written in the picture's corner
    bool per_block = false;  ///< each stroke one block's moves (for the HTML page's hover)
};

/// What a picture is made of: strokes (polylines and arcs) in one style each, and text, in page
/// units (pixels, points), y down. Made by plan_plot, drawn by the plot module.
struct PlotStyle {
    std::uint32_t rgb = 0;  ///< 0xRRGGBB
    float width = 1;
    bool dashed = false;
};

struct PlotStroke {
    std::uint16_t style = 0;  ///< index in PlotPlan::styles
    bool arc = false;  ///< an arc: cx, cy, r, from a0 to a1 (radians, y down, increasing = clockwise on the page)
    double cx = 0, cy = 0, r = 0, a0 = 0, a1 = 0;
    std::uint32_t first = 0, count = 0;     ///< a polyline: points[first .. first+count)
    std::uint32_t move = 0, last_move = 0;  ///< the moves (Toolpath::moves() indices) it draws
};

struct PlotText {
    double x = 0, y = 0, size = 12;
    std::uint32_t rgb = 0;
    std::string text;
};

struct PlotPlan {
    int width = 0, height = 0;
    std::vector<PlotStyle> styles;
    std::vector<PlotStroke> strokes;  ///< in drawing order (rapids first, then feeds, then doubt)
    std::vector<float> points;        ///< x, y pairs of the polylines
    std::vector<PlotText> texts;
    std::vector<std::pair<float, float>> scale_bar;  ///< the bar's two ends (drawn as a line with ticks)
    /// Where the part is: a point (u, v) in mm on the view's axes (u across, v up) is at page x = x0 + u *
    /// scale, y = y0 - v * scale.
    double x0 = 0, y0 = 0, scale = 1;
    std::uint64_t moves_drawn = 0;  ///< moves that became at least part of a stroke
    std::uint64_t unplaced = 0;     ///< moves not drawn: an axis of the view not known
};

/// The toolpath seen from options.view, fitted to the page, cut down to its resolution. Throws
/// Error(Errc::bad_program) when there is nothing to draw (no move with the view's axes known).
PlotPlan plan_plot(const Toolpath& path, const PlotOptions& options);

/// "svg", "png", "pdf" or "html" for a file name's extension; empty for another.
std::string_view plot_format_for_path(std::string_view path);

/// The plan drawn by the plot module (cairo) as "svg", "png" or "pdf". Throws Error(Errc::io) when this
/// build has no cairo or the module does not load; plot_available() says before.
std::vector<std::uint8_t> draw_plot(const PlotPlan& plan, std::string_view format);
bool plot_available();
std::string_view plot_unavailable_message();

/// An HTML page: the picture (drawn by the module as SVG) with, over it, each stroke naming its blocks on
/// hover (path kept its blocks), and linking to link(frame) when a move came from a tape and
/// link gives a target; appendix (HTML: the tape's picture) follows. Throws as draw_plot.
std::string plot_html(const PlotPlan& plan, const Toolpath& path, const std::string& title,
                      const std::function<std::string(std::uint64_t frame)>& link = {}, std::string_view appendix = {});

}  // namespace tape
