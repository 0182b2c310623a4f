#include "motion_stats_report.hpp"

#include <cstdio>
#include <tuple>

#include "cli/globals.hpp"
#include "cli/json.hpp"
#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "tape/motion_stats.hpp"

namespace cli {
namespace {

Json point_value(const tape::Point& p, unsigned axes) {
    auto one = [axes](unsigned bit, double v) { return axes & bit ? Json(v) : Json(nullptr); };
    return Json{{"x", one(tape::axis_x, p.x)}, {"y", one(tape::axis_y, p.y)}, {"z", one(tape::axis_z, p.z)}};
}

Json tool_value(const tape::ToolFigures& t, bool rapid_known) {
    Json v{{"tool", t.tool == -1 ? Json(nullptr) : Json(t.tool)},
           {"moves", t.moves},
           {"min", t.any ? point_value(t.min, t.axes) : Json(nullptr)},
           {"max", t.any ? point_value(t.max, t.axes) : Json(nullptr)},
           {"cutting_mm", t.cutting_mm},
           {"rapid_mm", t.rapid_mm},
           {"cutting_min", t.cutting_min},
           {"rapid_min", rapid_known ? Json(t.rapid_min) : Json(nullptr)},
           {"dwell_min", t.dwell_min},
           {"untimed_feeds", t.untimed}};
    return v;
}

std::string tool_text(const tape::ToolFigures& t, bool rapid_known) {
    char buf[512];
    std::string head = t.tool == -1 ? "all tools" : "T" + std::to_string(t.tool);
    std::string out = head + ": " + std::to_string(t.moves) + " moves\n";
    if (t.any) {
        out += " ";
        for (auto [bit, letter, lo, hi] :
             {std::tuple{tape::axis_x, 'X', t.min.x, t.max.x}, std::tuple{tape::axis_y, 'Y', t.min.y, t.max.y},
              std::tuple{tape::axis_z, 'Z', t.min.z, t.max.z}})
            if (t.axes & bit) {
                std::snprintf(buf, sizeof buf, " %c %.3f .. %.3f", letter, lo, hi);
                out += buf;
            }
        out += " mm\n";
    }
    std::snprintf(buf, sizeof buf, "  cutting %.3f mm in %.2f min, rapid %.3f mm", t.cutting_mm, t.cutting_min,
                  t.rapid_mm);
    out += buf;
    if (rapid_known) {
        std::snprintf(buf, sizeof buf, " in %.2f min", t.rapid_min);
        out += buf;
    }
    if (t.dwell_min > 0) {
        std::snprintf(buf, sizeof buf, ", dwell %.2f min", t.dwell_min);
        out += buf;
    }
    out += "\n";
    if (t.untimed) out += "  " + std::to_string(t.untimed) + " feed move(s) not timed (no feed known)\n";
    return out;
}

}  // namespace

void run_motion_stats(const std::string& input, const ProgramSource& source, const MotionArgs& motion,
                      const StatsArgs& args) {
    double rapid = args.rapid_mm_per_min;
    // Without --rapid, the machine's slowest axis: the cycle time is not understated.
    if (const tape::MachineProfile* m = motion_machine(motion); rapid <= 0 && m)
        for (const auto& [axis, rate] : m->rapid_mm_per_min)
            if (rate > 0 && (rapid <= 0 || rate < rapid)) rapid = rate;
    tape::MotionStats stats(rapid);
    MotionRead read = read_motion(input, source, motion, stats);
    const tape::MotionFigures& f = stats.figures();
    bool rapid_known = rapid > 0;
    std::string out;
    if (args.json) {
        Json tools = Json::array();
        for (const auto& t : f.tools) tools.push_back(tool_value(t, rapid_known));
        out = json_text(Json{{"tools", tools},
                             {"total", tool_value(f.total, rapid_known)},
                             {"not_simulated", f.not_simulated},
                             {"unknown_place", f.unknown}}) +
              "\n";
    } else {
        for (const auto& t : f.tools) out += tool_text(t, rapid_known);
        if (f.tools.size() > 1) out += tool_text(f.total, rapid_known);
        if (!rapid_known) out += "rapid time: give the machine's rapid rate with --rapid MM/MIN\n";
    }
    write_output("-", out, false, false);
    if (f.not_simulated)
        say(read.name,
            std::to_string(f.not_simulated) + " block(s) not simulated: the figures leave out what the tool did there");
    if (f.unknown && globals().verbosity > 0)
        say(read.name, std::to_string(f.unknown) +
                           " move(s) from a place not known (the first, or after a move not simulated): "
                           "not in the figures");
    end_motion(read);
}

}  // namespace cli
