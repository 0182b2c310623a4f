#include "motion_diff_report.hpp"

#include <cstdio>

#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "tape/motion_diff.hpp"

namespace cli {
namespace {

struct Side {
    MotionRead read;
    std::vector<tape::PathPiece> pieces;
};

Side interpret(const std::string& path, const ProgramSource& source, const MotionArgs& motion, double tolerance) {
    tape::MotionPieces pieces(tolerance);
    Side s{read_motion(path, source, motion, pieces, [&pieces](const tape::Block& b) { pieces.note_block(b); }), {}};
    s.pieces = pieces.pieces();
    return s;
}

// "  A.nc line 14: N70 G02 X70. Y30. I0 J20.\n    arc XY clockwise ..." or that the program has ended.
std::string side_text(const Side& s, const std::optional<tape::PathPiece>& p) {
    if (!p) return "  " + s.read.name + ": (the program has ended)\n";
    std::string where = position_text(p->where, s.read.from_tape);
    std::string block = p->kind == tape::MoveKind::not_simulated ? "" : ": " + p->text;
    return "  " + s.read.name + " " + where + block + "\n    " + tape::piece_text(*p) + "\n";
}

}  // namespace

void run_motion_diff(const std::string& first, const std::string& second, const ProgramSource& source,
                     const MotionArgs& motion, double tolerance_mm) {
    Side a = interpret(first, source, motion, tolerance_mm), b = interpret(second, source, motion, tolerance_mm);
    tape::MotionDifference d = tape::compare_motion(a.pieces, b.pieces, tolerance_mm);
    char tol[64];
    std::snprintf(tol, sizeof tol, "%g mm", tolerance_mm);
    std::string out;
    if (d.same) {
        out = "same toolpath: " + std::to_string(a.pieces.size()) + " pieces (lines and arcs) within " + tol + "\n";
    } else {
        out = std::string(d.cannot_tell ? "cannot tell" : "toolpaths differ") + " at piece " +
              std::to_string(d.index + 1) + " (within " + tol + "): " + d.what + "\n" + side_text(a, d.first) +
              side_text(b, d.second);
    }
    write_output("-", out, false, false);
    bool bad_frames = !a.read.bad_frames.empty() || !b.read.bad_frames.empty();
    if (bad_frames) {
        for (const Side* s : {&a, &b})
            if (!s->read.bad_frames.empty())
                say(s->read.name, std::to_string(s->read.bad_frames.size()) +
                                      " bad frame(s) read past: the comparison is of the tape as read");
    }
    if (!d.same || bad_frames) throw Exit{bad_data};
}

}  // namespace cli
