// A block through the interpreter: its statements (jumps and loops are not followed; calls are, in
// subprograms.cpp), then its words in the order a control runs them: modal codes, F/S/T, the events
// before motion, the motion, the events after it; then the call it made, if any.
#include "motion/machine.hpp"

#include <utility>

namespace tape {

using namespace motion;

MotionMachine::MotionMachine(MotionVisitor& out, const MotionOptions& options) : out_(out), opt_(options) {
    dialect(options.dialect == Dialect::automatic ? Dialect::gost : options.dialect);
}

void MotionMachine::dialect(Dialect d) {
    dialect_ = d;
    rules_.dialect = d;
    rules_.spec = opt_.spec;
    if (opt_.findings_only) {  // F, S, T and the rest make no finding: not read
        rules_.letters = 0;
        for (char c : std::string_view("IJKLPQRUVWXYZ")) rules_.letters |= 1u << (c - 'A');
    }
    fanuc_lathe_ = opt_.lathe && d == Dialect::fanuc;
    reset();
}

// Power on: ГОСТ 20999-83 §8.1's defaults (G17, G90, G94, mm; a lathe G18), the tool's place unknown.
void MotionMachine::reset() {
    st = ModalState{};
    st.plane = opt_.lathe ? Plane::zx : Plane::xy;
    // LinuxCNC starts in radius mode (G8) unless the machine's startup code says G7.
    st.diameter = opt_.lathe && opt_.diameter && dialect_ != Dialect::linuxcnc;
    // ГОСТ §8.1 recommends G01 at power on for contouring; Fanuc's parameter No. 3402#0 is 0 (G00) as
    // shipped; LinuxCNC has no motion mode until one is given.
    group01_ = dialect_ == Dialect::gost ? 1 : dialect_ == Dialect::fanuc ? 0 : -1;
    st.motion = group01_;
    cycle_ = lathe_cycle_ = -1;
    pos = Point{};
    known = 0;
    program_points_ = false;
    sub_depth_ = 0;
    tool_changed_ = end_seen_ = false;
    pending_tool_ = 0;
    local_ = Point{};
    transform_.clear();
    plane_set_ = false;
    scaled_ = 0;
    initial_known_ = cycle_r_ok_ = cycle_z_ok_ = false;
    expanded_ = 0;
    lathe_ = {};
    lathe_named_ = 0;
    corner_word_ = nullptr;
    corner_held_.reset();
}

void MotionMachine::program_start(const Program& header) {
    end();
    reset();
    calls_start(header);
    out_.program_start(header);
}

void MotionMachine::block(const Block& b) {
    block_ = &b;
    if (following_ && call_skips(b)) return;
    bool contour = lathe_.open && contour_before(b);  // a lathe cycle's P-Q contour (lathe_cycles.cpp)
    one_block(b);
    if (contour) contour_after(b);
}

void MotionMachine::end() {
    block_ = nullptr;    // the last block is gone: what is said here carries its own block
    if (corner_held_) {  // no move after the corner: the control stops
        Move held = std::move(*corner_held_);
        corner_held_.reset();
        if (!opt_.findings_only) out_.move(held);
        corner_note(held, "no move after it");
    }
    if (lathe_.open) contour_lost(true);
}

void MotionMachine::one_block(const Block& b) {
    calls_.pending.kind = PendingCall::Kind::none;
    if (statements(b)) return;
    if (b.skip && opt_.block_skip) return;
    if (b.damaged) {
        not_simulated("a bad frame in this block: what it commands is not known", all_axes);
        return;
    }
    run(b);
    if (calls_.pending.kind != PendingCall::Kind::none) follow();
}

// LinuxCNC o-words and Fanuc macro statements. True when the block is not run as a block: inside an
// o-sub definition (it runs when called). A jump or loop whose course the text does not fix is named.
bool MotionMachine::statements(const Block& b) {
    for (const auto& s : b.statements) {
        if (s.kind == Statement::Kind::o_word) {
            if (s.keyword.empty()) continue;  // "O0000 (NAME)": a program's number, nothing runs
            if (s.keyword == "sub") ++sub_depth_;
            if (s.keyword == "endsub" && sub_depth_ > 0) {
                --sub_depth_;
                return true;
            }
            if (sub_depth_ > 0 || o_word_call(s)) continue;
            if (s.keyword != "sub")
                not_simulated("o-word control flow (" + s.text +
                                  ") is not followed: which blocks run, and how often, "
                                  "is decided when the program runs",
                              all_axes);
            continue;
        }
        if (sub_depth_ > 0) continue;
        using K = Statement::Kind;
        if (s.kind == K::go_to || s.kind == K::if_goto || s.kind == K::while_do || s.kind == K::loop_end)
            not_simulated("a macro jump or loop (" + s.text +
                              ") is not followed: which blocks run, and how often, "
                              "is decided when the program runs",
                          all_axes);
    }
    return sub_depth_ > 0;
}

void MotionMachine::run(const Block& b) {
    // §3.1.4 reads words without a point by the program's other words; Fanuc and LinuxCNC do not.
    bool by_points = dialect_ != Dialect::fanuc && dialect_ != Dialect::linuxcnc;
    if (by_points && !program_points_ && block_has_points(b)) program_points_ = true;
    rules_.program_points = program_points_;
    rules_.inch = st.inch;
    read_words(b, rules_, w_);
    if (w_.odd_code) {
        std::string what =
            w_.odd_code->macro ? "a macro value, known only when the program runs" : "no code the interpreter reads";
        not_simulated(w_.odd_code->text + " is " + what + ": this block is not simulated", all_axes);
        return;
    }
    bool was_inch = st.inch;
    if (!g_codes()) return;
    if (st.inch != was_inch && dialect_ == Dialect::fanuc) {  // the least input increment follows G20/G21
        rules_.inch = st.inch;
        read_words(b, rules_, w_);
    }
    values();
    events_before();
    corner_begin(b);  // ",C" and ",R" (corners.cpp)
    motion_block();
    corner_end();
    events_after();
}

void MotionMachine::begin(MoveKind kind) {
    mv_.kind = kind;
    mv_.start = mv_.end = pos;
    mv_.known = mv_.end_known = known;
    mv_.centre = Point{};
    mv_.clockwise = false;
    mv_.turns = 0;
    mv_.radius = mv_.end_radius = 0;
    mv_.seconds = 0;
    mv_.code = 0;
    mv_.note.clear();
    mv_.block = block_ ? block_->ordinal : 0;
    if (block_) mv_.where = block_->where;
    mv_.last_frame.reset();
    mv_.depth = static_cast<int>(calls_.stack.size());
    st.motion = cycle_ >= 0 ? cycle_ : group01_;
    mv_.state = st;
}

void MotionMachine::emit() {
    mv_.known = mv_.known & mv_.end_known;
    if (lathe_.open && lathe_.open->drawing && contour_move()) return;
    if ((corner_word_ || corner_held_) && corner_move()) return;
    if (!opt_.findings_only) out_.move(mv_);
}

void MotionMachine::event(MoveKind kind, int code) {
    if (opt_.findings_only) return;
    begin(kind);
    mv_.code = code;
    emit();
}

// A move the interpreter does not simulate: said at its block; the axes in lost become unknown.
void MotionMachine::not_simulated(std::string note, unsigned lost) {
    begin(MoveKind::not_simulated);
    known &= ~lost;
    mv_.end_known = known;
    mv_.note = std::move(note);
    emit();
}

void MotionMachine::finding(std::string_view rule, std::string message) {
    out_.finding(program_finding(rule, block_->where, block_->ordinal, std::move(message)));
}

}  // namespace tape
