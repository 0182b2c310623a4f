// Strokes gathered for a plan, cut down as they come: a point under half a unit from the last is dropped,
// a point in line with the last two moves the last instead of adding one, and a segment or arc already
// drawn in its style (a pass over the same place at another depth) is not drawn again. Each layer keeps
// its strokes apart, so that rapids are drawn under feeds and doubt over both.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <unordered_set>
#include <vector>

#include "plot/page.hpp"
#include "tape/toolpath.hpp"

namespace tape::plot {

enum class Layer : std::uint8_t { rapid, feed, doubt };

class Strokes {
public:
    /// split_blocks: a polyline ends where the block changes, so that each stroke is one block's (for
    /// the HTML page's hover); blocks: the moves' blocks (Toolpath::moves()).
    Strokes(PlotPlan& plan, const std::vector<PathMove>& moves, bool split_blocks)
        : plan_(plan), moves_(moves), split_(split_blocks) {}

    /// The index of style in the plan (added the first time).
    std::uint16_t style(Layer layer, const PlotStyle& style);
    /// A straight segment of move.
    void line(std::uint16_t style, std::uint32_t move, Xy a, Xy b);
    /// An arc of move: centre, radius, page angles from a0 to a1.
    void arc(std::uint16_t style, std::uint32_t move, Xy c, double r, double a0, double a1);
    /// Ends the open polylines and puts the layers' strokes into the plan, rapids first.
    void finish();

private:
    struct Open {
        PlotStroke stroke;
        std::vector<float> points;
        bool open = false;
        Xy end;                       // the last point given, drawn or not
        bool pending = false;         // end is under half a unit from the last point drawn, not drawn yet
        double dir_x = 0, dir_y = 0;  // the direction of the last segment, once over 2 units long
        bool has_dir = false;
    };
    struct Built {
        std::vector<PlotStroke> strokes;
        std::vector<float> points;
    };
    struct KeyHash {
        std::size_t operator()(const std::array<std::int32_t, 6>& k) const;
    };

    void close(Open& o, Built& into);
    void start(Open& o, std::uint16_t style, std::uint32_t move, Xy a);
    void add_point(Open& o, Xy b);
    bool seen(std::uint16_t style, Xy a, Xy b);
    void count(std::uint32_t move);

    PlotPlan& plan_;
    const std::vector<PathMove>& moves_;
    bool split_;
    std::map<std::pair<std::uint8_t, std::uint32_t>, std::uint16_t> style_index_;
    std::vector<Layer> layer_of_;  // by style
    std::vector<Open> open_;       // by style: its polyline being drawn
    std::array<Built, 3> built_;   // by layer
    std::unordered_set<std::array<std::int32_t, 6>, KeyHash> drawn_;
    std::uint64_t last_counted_ = UINT64_MAX;
};

}  // namespace tape::plot
