// Two programs compared by what they cut (tape diff --motion): their moves reduced to geometry (collinear
// feeds merged into one line, an arc and its continuation about the same centre merged into one arc,
// moves of no length left out) and compared piece by piece within a tolerance. The text of the blocks,
// their numbers, the dialect and the units do not matter; rapid or feed does.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tape/motion.hpp"

namespace tape {

/// A piece of toolpath: a line (rapid or feed) or an arc, made of one or more moves.
struct PathPiece {
    MoveKind kind = MoveKind::linear;  ///< rapid, linear, arc, or not_simulated (where comparing stops)
    Point start{}, end{}, centre{};
    unsigned known = all_axes;
    Plane plane = Plane::xy;
    double sweep = 0;         ///< arcs: radians, counterclockwise positive seen from the plane's normal
    double radius = 0;        ///< arcs
    std::uint64_t moves = 1;  ///< how many moves it is made of
    Location where{};         ///< the first move's block
    std::uint64_t block = 0;
    std::string text{};  ///< that block as written (or the note of a move not simulated)
};

/// Collects a program's pieces. Events (spindle, coolant, tool change, dwell) are not compared.
class MotionPieces : public MotionVisitor {
public:
    explicit MotionPieces(double tolerance_mm = 0.001) : tolerance_(tolerance_mm) {}
    void move(const Move& move) override;
    /// The block the interpreter is about to be given (its text is kept for the pieces it starts).
    void note_block(const Block& block);
    void subprogram_block(const Block& block) override { note_block(block); }
    const std::vector<PathPiece>& pieces() const { return pieces_; }

private:
    bool merge(const Move& move);

    double tolerance_;
    std::vector<PathPiece> pieces_;
    std::uint64_t source_block_ = 0;
    std::string source_;
};

struct MotionDifference {
    bool same = true;
    std::size_t index = 0;                       ///< the first piece that differs (0-based)
    std::optional<PathPiece> first{}, second{};  ///< that piece in each; none when a program has ended
    std::string what;                            ///< how they differ, in words
    bool cannot_tell = false;                    ///< a move not simulated stops the comparison: no answer past it
};

/// The first difference of a and b within tolerance_mm (ends, centres, sweeps times radius).
MotionDifference compare_motion(const std::vector<PathPiece>& a, const std::vector<PathPiece>& b, double tolerance_mm);

/// "arc XY clockwise to X70.000 Y30.000 Z-5.000 about X50.000 Y30.000, 90.000 degrees" and the like.
std::string piece_text(const PathPiece& piece);

}  // namespace tape
