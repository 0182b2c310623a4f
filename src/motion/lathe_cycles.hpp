// A Fanuc (and Haas) lathe's multiple repetitive cycles, kept from block to block: G70-G73 draw the
// finishing contour of blocks N(P)..N(Q), G76 cuts a thread in passes. The state lives in the
// MotionMachine (lathe_cycles.cpp); the pass depths of a thread are a function of their own, for tests.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tape/motion.hpp"

namespace tape::motion {

/// The moves of a contour N(P)..N(Q) as its blocks made them, for a G70 that finishes it later.
struct Contour {
    long long p = -1, q = -1;
    std::vector<Move> moves;
};

/// A G70-G73 whose contour blocks are still to come (waiting) or being drawn.
struct OpenContour {
    int code = 0;              ///< 70..73
    long long p = -1, q = -1;  ///< the sequence numbers of the contour's first and last blocks
    Point start{};             ///< where the tool stood at the cycle: it returns there
    unsigned start_known = 0;  ///< AxisBit
    Point shift{};             ///< a roughing cycle's finishing allowance: the contour drawn where it leaves it
    Point at{};                ///< the drawn contour's last point
    ModalState state{};        ///< the modal state at the cycle, back in force after it
    int group01 = -1;          ///< the motion mode at the cycle
    std::uint64_t block = 0;   ///< the cycle's block, where what goes wrong is said
    Location where{};
    std::string name;  ///< "G71 P10 Q20", as the machinist reads it
    bool drawing = false, first = true;
    Contour recorded;
};

/// The lathe cycles' state of one program.
struct LatheCycles {
    std::optional<OpenContour> open;
    std::vector<Contour> done;  ///< the contours drawn so far (bounded: max_contours, max_moves)
    std::size_t recorded_moves = 0;
    // G76's first block (two-block form): finishing passes, minimum cut, finishing allowance (mm).
    int finish_passes = 1;
    double min_cut = 0, allowance = 0;
    static constexpr std::size_t max_contours = 64, max_moves = 100000;
};

/// A thread's passes: the depth of each from the crest (mm). The first cut is first, the n-th
/// first·√n (the same chip area each pass, Fanuc G76 and Haas G76 P1), at least min_cut deeper than the
/// one before, down to height − allowance; then finish_passes at the full height (the one-block form
/// has none: its last cut reaches the height). Empty when the values make no thread or more than
/// max_passes.
std::vector<double> thread_depths(double height, double first, double min_cut, double allowance, int finish_passes,
                                  std::size_t max_passes = 10000);

}  // namespace tape::motion
