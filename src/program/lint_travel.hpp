// Lint's travel check with a machine profile: the motion interpreter run alongside, the known end points
// of its moves held against the travel of the profile's axes.
//
// Lint sees the program's work coordinates, not the machine's: where the program's zero stands (G54,
// G92, the zero shift on the control's switches) and how long the tool is are the control's. What is
// certain is a difference: two points of one axis farther apart than the axis travels cannot both be
// inside its travel, wherever the zero is. Such a pair is compared only while nothing between them can
// have moved the zero or the tool's length (a work offset or coordinate setting, a tool, length or
// cutter compensation word); a block the interpreter does not simulate ends the check for the program.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "tape/lint.hpp"
#include "tape/machine.hpp"
#include "tape/motion.hpp"

namespace tape::lint_detail {

class TravelChecks : public MotionVisitor {
public:
    /// True when m gives an axis X, Y or Z both ends of its travel, its words in millimetres (words in
    /// pulses are the control's own reading, which the interpreter does not make).
    static bool applies(const MachineProfile& m);
    /// m must outlive the checks; findings go to sink.
    TravelChecks(const MachineProfile& m, Dialect dialect, std::function<void(Finding)> sink);
    void start(const Program& header);
    void next(const Block& b);

    void move(const Move& mv) override;

private:
    struct Seen {
        double at = 0;
        std::uint64_t block = 0;
    };
    struct Span {
        std::optional<Seen> low, high;
    };
    struct End {  // a move's end, held until its block is over
        Point at;
        unsigned known = 0, end_known = 0;
        std::uint64_t block = 0;
        Location where;
    };
    static MotionOptions options_for(const MachineProfile& m, Dialect dialect);
    void reset() {
        spans_ = {};
        stale_ = {true, true, true};
    }
    void take(const End& e);
    void note(int axis, double at, const End& e);

    const MachineProfile* m_;
    std::function<void(Finding)> sink_;
    std::array<const MachineAxis*, 3> axes_{};
    std::array<Span, 3> spans_{};
    // Since the last reset, not set by an absolute word: the interpreter's place for the axis is reckoned
    // from before (a new tool's tip stands elsewhere), so it is not held against the travel.
    std::array<bool, 3> stale_{true, true, true};
    std::vector<End> ends_;     // of the block being interpreted
    bool stopped_ = false;      // a block not simulated: positions after it are not followed
    bool compensated_ = false;  // G41/G42: the tool's centre is off the programmed path
    MotionOptions options_;
    Interpreter in_;
};

}  // namespace tape::lint_detail
