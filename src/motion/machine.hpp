// The interpreter's state machine (tape/motion.hpp): the modal state and the tool's place, block by
// block. machine.cpp runs a block, modal.cpp reads its G and M codes, axes.cpp its end point,
// arcs.cpp and cycles.cpp make the moves of arcs and canned cycles.
#pragma once

#include <optional>
#include <string>

#include "motion/lathe_cycles.hpp"
#include "motion/subprograms.hpp"
#include "motion/words.hpp"
#include "tape/motion.hpp"

namespace tape {

namespace motion {

/// What a G code does, for the interpreter.
enum class GKind : std::uint8_t {
    unknown,       // not in the table: not simulated
    ignore,        // changes nothing the interpreter draws (exact stop, compensation, path mode)
    motion,        // G00-G03, threads (G32/G33): group 01
    cycle,         // canned drilling cycles
    cycle_cancel,  // G80
    dwell,
    plane,
    units,
    distance,
    arc_distance,  // LinuxCNC G90.1/G91.1
    diameter,      // LinuxCNC G7/G8
    work_offset,
    feed_mode,
    speed_mode,
    cycle_return,  // G98/G99 on a mill
    set_coords,    // G92 (G50 on a Fanuc lathe): the tool's place gets the values given
    local_coords,  // G52
    reset_coords,  // G92.1/G92.2/G92.3
    reference,     // G28/G30: to a place the control keeps
    machine,       // G53: a move in machine coordinates, this block only
    data_setting,  // G10
    lathe_cycle,   // Fanuc lathe G90/G92/G94 single cycles
    repetitive,    // Fanuc lathe G70-G73 (the P-Q contour) and G76 (a thread in passes): lathe_cycles.cpp
    not_drawn,     // known, but its moves are not simulated (lathe G74/G75 pecking and grooving, probing, splines)
    transform,     // polar coordinates, rotation, scaling, mirror: every move after it is not simulated
    transform_off,
};

GKind classify(int code10, Dialect dialect, bool lathe);

/// The G code as written: 10 → "G01"? no: "G1"; 901 → "G90.1".
std::string g_name(int code10);

}  // namespace motion

class MotionMachine {
public:
    MotionMachine(MotionVisitor& out, const MotionOptions& options);

    void dialect(Dialect d);
    void program_start(const Program& header);
    void block(const Block& b);
    void end();  ///< the text has ended
    std::string open_cycle() const { return lathe_.open ? lathe_.open->name : std::string(); }
    /// subprograms.cpp: the text called subprograms are looked up in; a block of a called body; true
    /// when the body running has returned (the rest of its blocks do not run).
    void subprograms(const SubprogramText* text);
    void called_block(const Block& b);
    bool call_over() const;

    Point pos{};
    unsigned known = 0;
    ModalState st{};

private:
    // machine.cpp
    void reset();
    void one_block(const Block& b);
    bool statements(const Block& b);
    void run(const Block& b);
    void begin(MoveKind kind);
    void emit();
    void event(MoveKind kind, int code);
    void not_simulated(std::string note, unsigned lost);
    void finding(std::string_view rule, std::string message);
    // modal.cpp
    bool g_codes();
    void apply_g(int code, motion::GKind kind);
    bool set_mode(int code, motion::GKind kind);  ///< plain modal state; false for codes that move
    void values();
    void events_before();
    void events_after();
    // axes.cpp
    bool target(Point& end, unsigned& end_known, unsigned& named);
    double scale() const { return st.inch ? 25.4 : 1.0; }
    void straight(MoveKind kind, const Point& end, unsigned end_known);
    void coordinates(motion::GKind kind, const Point& end, unsigned end_known, unsigned named);
    void reference(motion::GKind kind, const Point& end, unsigned end_known, unsigned named);
    void motion_block();
    // corners.cpp
    void corner_begin(const Block& b);
    void corner_end();
    bool corner_move();  ///< emit()'s hook: true when it took the move (held till the next one)
    bool corner_join(const Move& held, Move& next);
    void corner_note(const Move& at, const std::string& why);
    // arcs.cpp
    void arc(const Point& end, unsigned end_known);
    bool arc_defined(bool by_r, char cu, char cv, const Point& end, unsigned end_known);
    void centre_by_r(double r, double half, double su, double sv, double eu, double ev, bool v_is_x, bool cw,
                     unsigned plane_bits, double& cu, double& cv);
    void full_circle_by_r(double r);
    void note_iso_centre(bool by_r, char cu_word);
    // arc_check.cpp
    void check_arc(int u, int v);
    /// A ГОСТ arc in Z-X with I and no K: the seeds' controller reads I along Z, ISO 6983 along X. The
    /// centre of the ISO reading, for the arc check to find an arc off its circle only when both are.
    std::optional<Point> iso_centre_{};
    bool checkable_arc(unsigned plane_bits, char cu, char cv) const;
    bool arc_off(double r1, double r2) const;
    // subprograms.cpp
    void calls_start(const Program& header);
    bool call_skips(const Block& b);
    bool o_word_call(const Statement& s);
    bool call_m(int m);
    void return_to_block();
    std::optional<motion::Body> call_body(motion::PendingCall& c, std::string& name);
    bool call_allowed(const motion::Body& body, const std::string& name, const motion::PendingCall& c);
    void follow();
    void replay(const motion::Body& body);
    bool over_budget();
    // cycles.cpp
    void drill_cycle(const Point& end, unsigned end_known, unsigned named);
    void drill_hole(Point at, double r_level, double bottom, unsigned zbit, int pecks);
    double peck_count(double r_level, double bottom) const;
    bool expansion_allowed(double moves);
    void lathe_cycle(int code, Point end, unsigned end_known, unsigned named);
    void leg(MoveKind kind, const Point& to, unsigned to_known);
    bool cycle_value(char letter, double& value);
    // lathe_cycles.cpp
    void repetitive_cycle();
    void contour_cycle();
    void contour_replay(const motion::Contour& c);
    bool contour_before(const Block& b);  ///< true: b is a block of the contour being drawn
    void contour_after(const Block& b);
    bool contour_move();  ///< emit()'s hook while a contour is drawn: true when it took the move
    void contour_lost(bool ended);
    void thread_cycle();
    void thread_passes(const Point& end, unsigned end_known, const std::vector<double>& depths, double height,
                       double taper);
    bool lathe_word(char letter, double& value, bool increment);

    MotionVisitor& out_;
    MotionOptions opt_;
    Dialect dialect_ = Dialect::gost;
    bool fanuc_lathe_ = false;
    motion::NumberRules rules_{};
    motion::BlockWords w_{};
    Move mv_{};
    const Block* block_ = nullptr;
    int group01_ = -1;  // the motion G code of group 01 in force
    int cycle_ = -1;    // the canned cycle in force, -1 none
    int once_ = -1;     // a one-block G code with its own axis words (G28, G53, G92, G10, G52, G04)
    motion::GKind once_kind_ = motion::GKind::ignore;
    int lathe_cycle_ = -1;         // Fanuc lathe G90/G92/G94 in force
    motion::LatheCycles lathe_{};  // G70-G73's contours, G76's first block
    Point lathe_end_{};            // G90/G92/G94's X and Z, kept for the blocks that give one of them
    unsigned lathe_end_known_ = 0, lathe_named_ = 0;
    const Word* corner_word_ = nullptr;  // ",C"/",R" of the block being run
    std::optional<Move> corner_held_{};  // a G01 with a corner, held till the next move shows the corner
    std::string corner_text_;
    bool program_points_ = false;
    int sub_depth_ = 0;  // inside LinuxCNC o-sub definitions: not run where written
    bool tool_changed_ = false, end_seen_ = false;
    int pending_tool_ = 0;
    // Canned cycles: the level the tool came from, and R, Z, Q, P kept from block to block.
    double initial_z_ = 0, cycle_r_ = 0, cycle_z_ = 0, cycle_q_ = 0, cycle_p_ = 0;
    bool initial_known_ = false, cycle_r_ok_ = false, cycle_z_ok_ = false;
    double expanded_ = 0;     // moves drawn from cycles in this program (bounded: expansion_allowed)
    Point local_{};           // G52's shift from the work offset's zero
    std::string transform_;   // the G code of a coordinate transformation in force ("G68"), or empty
    bool plane_set_ = false;  // the program chose its plane (G17/G18/G19)
    const SubprogramText* subs_ = nullptr;
    bool following_ = false;  // subprogram calls are followed in subs_
    motion::CallState calls_{};
    unsigned scaled_ = 0,
             scaled_start_ = 0;  // axes whose place came from a Fanuc value without a point (least increment)
};

}  // namespace tape
