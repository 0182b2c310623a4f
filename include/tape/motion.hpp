// What a program does: its blocks interpreted into the tool's moves, in the program's work coordinates,
// one move at a time. The layer above the loader (tape/program.hpp): blocks in, canonical moves out.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "tape/dialect.hpp"
#include "tape/format_spec.hpp"
#include "tape/program.hpp"

namespace tape {

struct MachineProfile;

/// A point of the tool in the program's work coordinates, always in millimetres (an inch program's
/// values are converted, so programs in either unit compare). On a lathe x is the radius: a program
/// written in diameters has its X halved.
struct Point {
    double x = 0, y = 0, z = 0;
};

/// Which axes of a point are known: bits of axis_x, axis_y, axis_z. A program that moves an axis
/// incrementally before setting it absolutely leaves it unknown (the tool's place is not on the tape).
enum AxisBit : unsigned { axis_x = 1, axis_y = 2, axis_z = 4, all_axes = 7 };

/// The arc plane: G17 (XY, seen from +Z), G18 (ZX, seen from +Y), G19 (YZ, seen from +X).
enum class Plane : std::uint8_t { xy, zx, yz };

/// The modal state a move ran under.
struct ModalState {
    bool inch = false;            ///< G20/G70: the program's units are inches (values are still given in mm)
    bool incremental = false;     ///< G91 (ГОСТ, Fanuc M, LinuxCNC); a lathe's U/W words are incremental too
    bool arc_incremental = true;  ///< I/J/K from the start point (LinuxCNC G91.1; absolute with G90.1)
    bool diameter = false;        ///< lathe X in diameters (LinuxCNC G7; Fanuc lathes by default)
    Plane plane = Plane::xy;
    int motion = -1;                ///< the motion G code in force (0, 1, 2, 3, 33, 81..89, ...), -1 none yet
    int work_offset = 54;           ///< G54..G59 (work coordinates whose values live in the control, not on tape)
    bool feed_per_rev = false;      ///< G95 (Fanuc M, LinuxCNC) / G99 (Fanuc lathe): feed in mm per revolution
    double feed = 0;                ///< the programmed feed, mm/min (or mm/rev with feed_per_rev); 0 none yet
    double speed = 0;               ///< S as a value (rev/min, or m/min with constant surface speed)
    bool constant_surface = false;  ///< G96
    int spindle = 5;                ///< M3, M4 or M5
    int coolant = 9;                ///< M7, M8 or M9
    int tool = 0;                   ///< the tool in the spindle or turret (T, after M06 where the dialect needs it)
    bool retract_to_r = false;      ///< G99 on a mill: canned cycles return to R, not to the initial level (G98)
};

enum class MoveKind : std::uint8_t {
    rapid,          ///< G00
    linear,         ///< G01 at the feed
    arc,            ///< G02/G03: arc in its plane, with a helix when the third axis moves
    dwell,          ///< G04: seconds
    tool_change,    ///< code: the tool now in the spindle or turret
    spindle,        ///< code: 3, 4 or 5, at state.speed
    coolant,        ///< code: 7, 8 or 9
    stop,           ///< code: M00 or M01
    program_end,    ///< code: M02 or M30
    not_simulated,  ///< note says what, at its block: the interpreter does not know where the tool goes after it
};

/// One canonical move (or event) of the program, carrying the block it came from.
struct Move {
    MoveKind kind = MoveKind::rapid;
    Point start{}, end{};           ///< where the tool stood before and after (mm, work coordinates)
    unsigned known = all_axes;      ///< axes of start and end that are known (AxisBit)
    unsigned end_known = all_axes;  ///< axes of end that are known (an axis set absolutely from unknown)
    // Arcs:
    Point centre{};          ///< in the arc's plane; its third coordinate is start's
    bool clockwise = false;  ///< as seen from the positive end of the plane's normal axis
    int turns = 0;           ///< whole extra turns (a full circle by I/J is turns 1 with start == end)
    double radius = 0;       ///< from centre to start
    double end_radius = 0;   ///< from centre to end (differs from radius by what the control tolerates)
    // Other kinds:
    double seconds = 0;  ///< dwell
    int code = 0;        ///< tool, spindle, coolant, stop or end code
    std::string note;    ///< not_simulated: what is not simulated and why, in a machinist's words
    // Where it came from:
    std::uint64_t block = 0;                    ///< Block::ordinal of the block that made it
    Location where{};                           ///< the block's first character (frame when from a tape)
    std::optional<std::uint64_t> last_frame{};  ///< the block's last frame, when from a tape
    int depth = 0;                              ///< 0 in the program; 1.. inside a subprogram or an expanded cycle
    ModalState state{};                         ///< the modal state the move ran under

    /// Length of the tool's path in mm (arcs and helices along the curve; 0 for events).
    double length() const;
    /// An arc's angle from start to end in radians, positive, whole turns included (0 for other kinds).
    double sweep() const;
};

/// Receives the moves in program order. The Move passed is reused: copy what you keep.
class MotionVisitor {
public:
    virtual ~MotionVisitor() = default;
    virtual void move(const Move& move) = 0;
    /// A finding of the interpreter (an arc off its circle, an R arc shorter than half its chord, ...),
    /// with a rule id of tape/rules.hpp.
    virtual void finding(const Finding& finding) { (void)finding; }
    /// A new program starts (its moves follow); the position is unknown again.
    virtual void program_start(const Program& header) { (void)header; }
    /// A block of a called subprogram is about to run (its moves follow). The program's own blocks come
    /// from the loader; these come from the text again, each time the subprogram is called.
    virtual void subprogram_block(const Block& block) { (void)block; }
};

/// How a program is interpreted: what the tape does not say about the control.
struct MotionOptions {
    Dialect dialect = Dialect::automatic;
    bool lathe = false;                 ///< X-Z turning: X is a radius or (diameter) a diameter
    bool diameter = true;               ///< on a lathe: X written as a diameter unless the program says (G8)
    const FormatSpec* spec = nullptr;   ///< the control's word formats: the implied point of words without one
    double arc_tolerance_mm = 0.001;    ///< an arc's end may be this far off its circle (the seeds' micron)
    double arc_tolerance_relative = 0;  ///< plus this fraction of the radius (LinuxCNC: 0.001)
    bool follow_subprograms = true;     ///< M98/M97/o-call into a program in the same text (SubprogramText)
    /// LinuxCNC's rule (interp_arc.cc, arc_data_ijk): an arc is off when the radii differ by more than
    /// arc_tolerance_mm AND by more than arc_tolerance_relative of the larger radius, or by more than 100
    /// times arc_tolerance_mm. false: off when they differ by more than the two added.
    bool arc_tolerance_linuxcnc = false;
    bool block_skip = false;  ///< the block-skip switch is on: '/' blocks do not run
    /// Not known whether the program is for a lathe (lint): a ZX-plane arc is checked with X read as a
    /// radius and as a diameter, and is a finding only when neither reading puts its end on the circle.
    bool lathe_unknown = false;
    /// Only findings are wanted (lint): no moves are passed to the visitor, which saves their making.
    bool findings_only = false;
};

/// The options with the arc tolerance of dialect's controls: ГОСТ and none, the seeds' controller
/// (1 µm, alarm 7.56); LinuxCNC, its defaults (0.0283 mm or 0.1 % of the radius, either limit passed
/// is an error; its inch limit, 0.0028 in, is not used: the millimetre rule stands for both); Fanuc,
/// 0.02 mm (parameter No. 3410 is set per machine: give yours).
MotionOptions motion_options(Dialect dialect);

/// The options for machine m's programs read in dialect d: the dialect's, with the machine's kind (a
/// lathe, X in diameters), its word format (when it has one) and its arc tolerance (when it gives one).
/// The options point into m: m must outlive them.
MotionOptions motion_options(const MachineProfile& m, Dialect d);

class SubprogramIndex;  // src/motion/subprograms.hpp

/// The text a program's subprograms are looked up in when a block calls one (Fanuc/Haas M98 P, Haas
/// M97 P, LinuxCNC o-call): the whole text being interpreted, kept by reference (text and frame_of must
/// outlive it). A text that holds a call is indexed once, when first needed, by the offsets of its
/// programs, o-subs and numbered blocks; a subprogram is loaded again from its offset each time it is
/// called, so no block is kept.
class SubprogramText {
public:
    explicit SubprogramText(std::string_view text, std::span<const std::uint64_t> frame_of = {});
    ~SubprogramText();
    SubprogramText(const SubprogramText&) = delete;
    SubprogramText& operator=(const SubprogramText&) = delete;

    /// True when the text writes a call (M97, M98, an o-word "call"; comments included): only then is
    /// it indexed.
    bool has_calls() const { return has_calls_; }
    std::string_view text() const { return text_; }
    std::span<const std::uint64_t> frame_of() const { return frame_of_; }
    /// The index, built on first use in dialect (the dialect the text is loaded in).
    const SubprogramIndex& index(Dialect dialect) const;

private:
    std::string_view text_;
    std::span<const std::uint64_t> frame_of_;
    bool has_calls_ = false;
    mutable std::unique_ptr<SubprogramIndex> index_;
};

/// The interpreter fed by the loader (ProgramLoader, load_each): blocks in, moves out, in bounded memory.
/// Subprograms are followed where the text they are in is given (subprograms()); a call to one that is
/// not there is named as not simulated at its block.
class Interpreter : public ProgramVisitor {
public:
    Interpreter(MotionVisitor& out, const MotionOptions& options = {});
    ~Interpreter() override;
    Interpreter(const Interpreter&) = delete;
    Interpreter& operator=(const Interpreter&) = delete;

    void dialect(const DialectChoice& choice) override;
    void program_start(const Program& header) override;
    void block(const Block& block) override;
    void end(const Location& where) override;

    /// The text the loader reads, where called subprograms are looked up (nullptr: calls are not
    /// followed). It must outlive the interpreter's use.
    void subprograms(const SubprogramText* text);

    /// The tool's place after the last block, and which axes of it are known.
    Point position() const;
    unsigned known() const;
    const ModalState& state() const;
    /// The lathe cycle whose P-Q contour is awaited or being drawn ("G71 P40 Q70"), or empty.
    std::string open_cycle() const;

private:
    std::unique_ptr<class MotionMachine> machine_;
};

/// Interprets a text (or a decoded tape with frame_of) in one pass: load_each into an Interpreter, its
/// subprograms followed in the same text (unless options.follow_subprograms is false).
void interpret_each(std::string_view text, std::span<const std::uint64_t> frame_of, MotionVisitor& out,
                    const MotionOptions& options = {});

}  // namespace tape
