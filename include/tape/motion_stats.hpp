// Figures of a program (tape info --motion): per tool, where the tool goes (the least and most of each
// axis), how far it cuts and moves at rapid, and how long that takes at the programmed feeds.
#pragma once

#include <cstdint>
#include <vector>

#include "tape/motion.hpp"

namespace tape {

struct ToolFigures {
    int tool = 0;
    Point min{}, max{};  ///< over every move of the tool with its axes known (arcs by their extremes)
    unsigned axes = 0;   ///< the axes min and max hold (AxisBit)
    bool any = false;    ///< min and max hold a point
    double cutting_mm = 0, rapid_mm = 0;
    double cutting_min = 0, rapid_min = 0, dwell_min = 0;
    std::uint64_t moves = 0;
    /// Feeds whose time is not known: no feed programmed yet, feed per revolution without a speed, or
    /// constant surface speed on the spindle axis.
    std::uint64_t untimed = 0;
};

struct MotionFigures {
    std::vector<ToolFigures> tools;  ///< in the order the tools are first used
    ToolFigures total;               ///< all tools (tool -1)
    std::uint64_t not_simulated = 0;
    std::uint64_t unknown = 0;  ///< moves with an axis not known: not in min and max
};

/// Adds up the moves it is given.
class MotionStats : public MotionVisitor {
public:
    /// rapid_mm_per_min: the machine's rapid rate (0: rapid time not known, left 0).
    explicit MotionStats(double rapid_mm_per_min = 0) : rapid_(rapid_mm_per_min) {}
    void move(const Move& move) override;
    const MotionFigures& figures() const { return f_; }

private:
    ToolFigures& of(int tool);
    double rapid_;
    MotionFigures f_;
    unsigned ever_known_ = 0;  // axes known in any move so far
};

}  // namespace tape
