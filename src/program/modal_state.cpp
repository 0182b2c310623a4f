// Restart after a tool break (tape/restart.hpp). The loader reads the program; the blocks before the
// restart block are walked for the modal state in force, and for whatever makes that state unknowable
// from the text (jumps, loops, calls, coordinates set from where the tool stood).
#include <algorithm>
#include <optional>

#include "motion/restart_approach.hpp"
#include "program/restart_calls.hpp"
#include "tape/error.hpp"
#include "tape/program.hpp"
#include "tape/restart.hpp"

namespace tape {
namespace {

enum class Group {
    none,  // one-block or unknown here: dwell, reference return, data setting
    motion,
    thread,
    cycle,
    cycle_cancel,
    plane,
    distance,
    feed_mode,
    units,
    work_offset,
    tool_length,
    cutter,
    speed_mode,
    macro_call,
    sets_coordinates,
};

struct GCode {
    std::string_view code;  // without leading zeros: "1", "54.1"
    Group group;
    std::string_view dialects;  // "gfl": ГОСТ, Fanuc, LinuxCNC
};

// Fanuc's groups (01 motion, 09 canned cycles, 02 plane, 03 abs/inc, 05 feed, 06 units, 14 work offset,
// 08 tool length, 07 cutter, 13 surface speed, 12 macro call); ГОСТ 20999-83 table 4 where it differs.
constexpr GCode g_codes[] = {
    {"0", Group::motion, "gfl"},
    {"1", Group::motion, "gfl"},
    {"2", Group::motion, "gfl"},
    {"3", Group::motion, "gfl"},
    {"6", Group::motion, "g"},
    {"32", Group::thread, "f"},
    {"33", Group::thread, "gfl"},
    {"34", Group::thread, "g"},
    {"35", Group::thread, "g"},
    {"76", Group::thread, "l"},
    {"73", Group::cycle, "fl"},
    {"74", Group::cycle, "f"},
    {"76", Group::cycle, "f"},
    {"80", Group::cycle_cancel, "gfl"},
    {"81", Group::cycle, "gfl"},
    {"82", Group::cycle, "gfl"},
    {"83", Group::cycle, "gfl"},
    {"84", Group::cycle, "gfl"},
    {"85", Group::cycle, "gfl"},
    {"86", Group::cycle, "gfl"},
    {"87", Group::cycle, "gfl"},
    {"88", Group::cycle, "gfl"},
    {"89", Group::cycle, "gfl"},
    {"17", Group::plane, "gfl"},
    {"18", Group::plane, "gfl"},
    {"19", Group::plane, "gfl"},
    {"90", Group::distance, "gfl"},
    {"91", Group::distance, "gfl"},
    {"93", Group::feed_mode, "gfl"},
    {"94", Group::feed_mode, "gfl"},
    {"95", Group::feed_mode, "gfl"},
    {"20", Group::units, "fl"},
    {"21", Group::units, "fl"},
    {"70", Group::units, "g"},
    {"71", Group::units, "g"},
    {"53", Group::work_offset, "g"},
    {"54", Group::work_offset, "gfl"},
    {"55", Group::work_offset, "gfl"},
    {"56", Group::work_offset, "gfl"},
    {"57", Group::work_offset, "gfl"},
    {"58", Group::work_offset, "gfl"},
    {"59", Group::work_offset, "gfl"},
    {"54.1", Group::work_offset, "f"},
    {"59.1", Group::work_offset, "l"},
    {"59.2", Group::work_offset, "l"},
    {"59.3", Group::work_offset, "l"},
    {"43", Group::tool_length, "gfl"},
    {"44", Group::tool_length, "gf"},
    {"49", Group::tool_length, "fl"},
    {"40", Group::cutter, "gfl"},
    {"41", Group::cutter, "gfl"},
    {"42", Group::cutter, "gfl"},
    {"96", Group::speed_mode, "gfl"},
    {"97", Group::speed_mode, "gfl"},
    {"65", Group::macro_call, "f"},
    {"66", Group::macro_call, "f"},
    {"66.1", Group::macro_call, "f"},
    {"92", Group::sets_coordinates, "gfl"},
    {"52", Group::sets_coordinates, "fl"},
};

char dialect_letter(Dialect d) { return d == Dialect::fanuc ? 'f' : d == Dialect::linuxcnc ? 'l' : 'g'; }

// "G01" -> "1", "G054.1" -> "54.1".
std::string g_code(const Word& w) {
    std::string code = w.text.substr(1);
    std::size_t zeros = 0;
    while (zeros + 1 < code.size() && code[zeros] == '0' && code[zeros + 1] != '.') ++zeros;
    return code.substr(zeros);
}

Group g_group(const Word& w, Dialect d) {
    std::string code = g_code(w);
    for (const auto& g : g_codes)
        if (g.code == code && g.dialects.find(dialect_letter(d)) != std::string_view::npos) return g.group;
    return Group::none;
}

const Word* word_at(const Block& b, char address) {
    for (const auto& w : b.words)
        if (w.address == address) return &w;
    return nullptr;
}

// "G43 H5": a G word with the word that goes with it in the same block, when there is one.
std::string with_word(const Word& g, const Block& b, char address) {
    const Word* w = word_at(b, address);
    return w ? g.text + " " + w->text : g.text;
}

struct ModalState {
    std::string motion, thread, cycle, plane, distance, feed_mode, units, work_offset, tool_length, cutter, speed_mode;
    std::string feed, speed, spindle;
    std::string next_tool, changed_tool;  // the last T word; the T an M06 last put in the spindle
    std::optional<bool> mist, flood{};    // M07, M08; M09 turns both off

    std::vector<std::string> blocks() const;
};

void join(std::string& into, const std::string& word) {
    if (word.empty()) return;
    if (!into.empty()) into += ' ';
    into += word;
}

std::vector<std::string> ModalState::blocks() const {
    std::vector<std::string> out;
    auto add = [&out](std::initializer_list<std::string> words) {
        std::string b;
        for (const auto& w : words) join(b, w);
        if (!b.empty()) out.push_back(b);
    };
    add({units, plane, distance, feed_mode, work_offset});
    if (!changed_tool.empty()) add({changed_tool, "M06"});
    if (next_tool != changed_tool) add({next_tool});  // a lathe's T, or the next tool made ready
    std::string coolant;
    if (mist.value_or(false)) join(coolant, "M07");
    if (flood.value_or(false)) join(coolant, "M08");
    if (coolant.empty() && (mist || flood)) coolant = "M09";
    add({speed_mode, speed, spindle});
    add({coolant});
    add({tool_length});
    add({cutter});
    add({motion, feed});
    return out;
}

[[noreturn]] void refuse(const Location& where, const std::string& why) {
    throw Error(Errc::usage, where.position(), "line " + std::to_string(where.line) + ": " + why);
}

std::string line_text(const Location& where) { return "line " + std::to_string(where.line); }

// A call before the restart block: the interpreter follows it, but the modal blocks are rebuilt from the
// program's own blocks, so what the subprogram leaves in force would be missing from them.
constexpr const char* not_rebuilt =
    ": the modal state the subprogram leaves is not rebuilt from its blocks; restart before the call";

// The blocks before the restart block, in order: the state they leave, and the reasons to refuse.
class Walk {
public:
    explicit Walk(Dialect d) : dialect_(d) {}

    void block(const Block& b) {
        statements(b);
        if (in_definition_) return;  // a subprogram's definition runs only when called
        if (b.damaged) refuse(b.where, "a bad frame before the restart block: the state it leaves is not known");
        if (b.skip && (!b.words.empty() || !b.statements.empty()))
            refuse(b.where, "an optional block (/): whether it ran is up to the block-skip switch");
        for (const auto& w : b.words)
            if (w.address != 'M') word(w, b);
        for (const auto& w : b.words)
            if (w.address == 'M') m_word(w, b);
    }

    // At the restart block: what makes the state at it unknowable.
    void check_at(const Block& target) const {
        if (!open_scopes_.empty())
            refuse(target.where, "inside a macro loop or conditional (" + open_scopes_.back().first + " at " +
                                     line_text(open_scopes_.back().second) + "): restart where it begins");
        if (in_definition_)
            refuse(target.where, "inside a subprogram's definition (" + line_text(*in_definition_) + ")");
        if (loop_ran_)
            refuse(target.where, "a macro loop runs before it (" + line_text(*loop_ran_) +
                                     "): the variables it leaves are not rebuilt");
        if (!state_.cycle.empty())
            refuse(target.where,
                   "a canned cycle (" + state_.cycle + ") is in force: restart at the block that starts the cycle");
        if (!state_.thread.empty())
            refuse(target.where,
                   "thread cutting (" + state_.thread + ") is in force: restart before the thread begins");
    }

    const ModalState& state() const { return state_; }
    const std::vector<std::string>& assignments() const { return assignments_; }

private:
    Dialect dialect_;
    ModalState state_;
    std::vector<std::string> assignments_;
    std::vector<std::pair<std::string, Location>> open_scopes_;  // DO/WHILE, o-word if/while/do/repeat
    std::optional<Location> in_definition_, loop_ran_;

    void statements(const Block& b) {
        for (const auto& s : b.statements) {
            if (s.kind == Statement::Kind::o_word) {
                o_word(s);
                continue;
            }
            if (in_definition_) continue;
            switch (s.kind) {
                case Statement::Kind::assignment:
                case Statement::Kind::if_then:
                    assignments_.push_back(s.text);
                    break;
                case Statement::Kind::go_to:
                case Statement::Kind::if_goto:
                    refuse(s.where, "a jump (" + s.text +
                                        ") runs before the restart block: which blocks ran is "
                                        "not known from the text");
                case Statement::Kind::while_do:
                case Statement::Kind::loop_do:
                    open_scopes_.emplace_back(s.text, s.where);
                    break;
                case Statement::Kind::loop_end:
                    if (!open_scopes_.empty()) open_scopes_.pop_back();
                    loop_ran_ = s.where;
                    break;
                default:
                    break;
            }
        }
    }

    void o_word(const Statement& s) {
        const std::string& k = s.keyword;
        if (k == "sub") in_definition_ = s.where;
        if (k == "endsub") in_definition_.reset();
        if (in_definition_ || k == "endsub") return;
        if (k == "call") refuse(s.where, "a subroutine call (" + s.text + ")" + not_rebuilt);
        if (k == "return" || k == "break" || k == "continue")
            refuse(s.where, "a jump (" + s.text + ") runs before the restart block");
        bool closes_do =
            k == "while" && !open_scopes_.empty() && open_scopes_.back().first.starts_with("o" + s.label + " do");
        if (k == "endwhile" || k == "endrepeat" || k == "endif" || closes_do) {
            if (!open_scopes_.empty()) open_scopes_.pop_back();
            loop_ran_ = s.where;
            return;
        }
        if (k == "if" || k == "while" || k == "do" || k == "repeat")
            open_scopes_.emplace_back("o" + s.label + " " + k, s.where);
    }

    void word(const Word& w, const Block& b) {
        if (w.macro && std::string_view("GFSTHDP").find(w.address) != std::string_view::npos)
            refuse(w.where, "a modal value given by a macro expression (" + w.text + ") is not rebuilt");
        switch (w.address) {
            case 'F':
                state_.feed = w.text;
                return;
            case 'S':
                state_.speed = w.text;
                return;
            case 'T':
                state_.next_tool = w.text;
                return;
            case 'G':
                g_word(w, b);
                return;
            default:
                return;
        }
    }

    void g_word(const Word& w, const Block& b) {
        ModalState& s = state_;
        switch (g_group(w, dialect_)) {
            case Group::motion:
                s.motion = w.text;
                s.cycle.clear();
                s.thread.clear();
                return;
            case Group::thread:
                s.motion = s.thread = w.text;
                return;
            case Group::cycle:
                s.cycle = w.text;
                return;
            case Group::cycle_cancel:
                s.cycle.clear();
                return;
            case Group::plane:
                s.plane = w.text;
                return;
            case Group::distance:
                s.distance = w.text;
                return;
            case Group::feed_mode:
                s.feed_mode = w.text;
                return;
            case Group::units:
                s.units = w.text;
                return;
            case Group::work_offset:
                s.work_offset = g_code(w) == "54.1" ? with_word(w, b, 'P') : w.text;
                return;
            default:
                g_word_more(w, b);
        }
    }

    void g_word_more(const Word& w, const Block& b) {
        ModalState& s = state_;
        switch (g_group(w, dialect_)) {
            case Group::tool_length:
                s.tool_length = with_word(w, b, 'H');
                return;
            case Group::cutter:
                s.cutter = with_word(w, b, 'D');
                return;
            case Group::speed_mode:
                s.speed_mode = w.text;
                return;
            case Group::macro_call:
                refuse(w.where, "a macro call (" + w.text + "): the state it leaves is not in this text");
            case Group::sets_coordinates:
                refuse(w.where, w.text + " sets coordinates from where the tool stood: they cannot be rebuilt");
            default:
                return;
        }
    }

    void m_word(const Word& w, const Block&) {
        if (w.macro) refuse(w.where, "an M code given by a macro expression (" + w.text + ") is not rebuilt");
        auto code = w.integer();
        if (!code) return;
        ModalState& s = state_;
        bool gost = dialect_ == Dialect::gost;
        if (*code == 3 || *code == 4 || *code == 5) s.spindle = w.text;
        if (*code == 6) s.changed_tool = s.next_tool;
        if (*code == 7) s.mist = true;
        if (*code == 8) s.flood = true;
        if (*code == 9) s.mist = s.flood = false;
        if (gost && (*code == 13 || *code == 14)) {  // ГОСТ 20999-83 table 7: spindle and coolant no. 1 on
            s.spindle = *code == 13 ? "M03" : "M04";
            s.flood = true;
        }
        if (dialect_ != Dialect::linuxcnc && (*code == 98 || *code == 198))
            refuse(w.where, "a subprogram call (" + w.text + ")" + not_rebuilt);
    }
};

// "N50", "n050", "50" or ":50" -> 50.
long long wanted_number(std::string_view block) {
    std::string_view digits = block;
    if (!digits.empty() && (digits[0] == 'N' || digits[0] == 'n' || digits[0] == ':')) digits.remove_prefix(1);
    bool ok = !digits.empty() && digits.size() <= 9 &&
              std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!ok)
        throw Error(Errc::usage, "'" + std::string(block) + "' is no block number: give N and digits, such as N50");
    return std::stoll(std::string(digits));
}

struct Found {
    const Program* program = nullptr;
    std::size_t index = 0;
};

Found find_block(const LoadedTape& tape, std::string_view block) {
    long long number = wanted_number(block);
    std::vector<Found> found;
    for (const auto& p : tape.programs)
        for (std::size_t i = 0; i < p.blocks.size(); ++i) {
            const auto& n = p.blocks[i].number;
            if (n && n->integer() == number) found.push_back({&p, i});
        }
    if (found.empty())
        throw Error(Errc::usage, "no block " + std::string(block) + " in the program: nothing to restart at");
    if (found.size() > 1) {
        const Block& a = found[0].program->blocks[found[0].index];
        const Block& b = found[1].program->blocks[found[1].index];
        refuse(b.where, a.number_text() + " occurs twice (" + line_text(a.where) + " and " + line_text(b.where) +
                            "): which one to restart at is not known");
    }
    return found[0];
}

// The line of text holding offset, with its LF.
std::string line_at(std::string_view text, std::uint64_t offset) {
    auto from = text.rfind('\n', offset == 0 ? 0 : offset - 1);
    from = offset == 0 || from == std::string_view::npos ? 0 : from + 1;
    auto to = text.find('\n', offset);
    return std::string(text.substr(from, to == std::string_view::npos ? text.size() - from : to + 1 - from));
}

std::string program_start(const LoadedTape& tape, const Program& p, std::size_t target) {
    std::string start;
    if (p.percent) start = line_at(tape.text, p.start.offset);
    if (p.numbered_by_block && target > 0 && p.number && p.blocks[0].source.starts_with(*p.number))
        start += line_at(tape.text, p.blocks[0].where.offset);
    if (!start.empty() && start.back() != '\n') start += '\n';
    return start;
}

// The restart block and everything to the next program's start (to the text's end where the rest
// calls a program written after it: restart_calls.cpp).
std::string rest_of_program(const LoadedTape& tape, const Program& p, std::size_t index) {
    auto from = p.blocks[index].where.offset;
    return tape.text.substr(from, rest_end(tape, p, index) - from);
}

void end_line(std::string& s) {
    if (!s.empty() && s.back() != '\n') s += '\n';
}

}  // namespace

std::string RestartPlan::header() const {
    std::string out = start + marker + line_end;
    for (const auto& b : modal) out += b + line_end;
    for (const auto& b : approach) out += b + line_end;
    return out;
}

std::string RestartPlan::text() const {
    std::string out = header() + rest;
    end_line(out);
    return out;
}

namespace {

// The approach (src/motion/restart_approach.cpp, the interpreter's layer: only it knows where the tool
// goes), then the distance mode and motion mode of the block again: the approach left G90 and G00/G01.
std::vector<std::string> approach(const Program& p, std::size_t index, Dialect dialect, bool lathe, const Walk& walk,
                                  const Block& target) {
    const auto& s = walk.state();
    if (!s.cutter.empty() && !s.cutter.starts_with("G40") && !s.cutter.starts_with("G040"))
        refuse(target.where, "cutter compensation (" + s.cutter +
                                 ") is in force: the tool stands off the programmed path; restart where it starts");
    ApproachInput in{&p, index, dialect, lathe, s.feed, s.feed_mode == "G93"};
    auto out = restart_approach(in);
    std::string again;
    if (s.distance == "G91") join(again, s.distance);
    join(again, s.motion);
    join(again, s.feed);
    if (!again.empty()) out.push_back(again);
    return out;
}

}  // namespace

RestartPlan plan_restart(std::string_view text, std::string_view block, Dialect dialect, bool lathe) {
    LoadOptions lo;
    lo.dialect = dialect == Dialect::automatic ? guess_dialect(text).dialect : dialect;
    LoadedTape tape = load(std::string(text), {}, lo);
    Found found = find_block(tape, block);
    const Program& p = *found.program;
    const Block& target = p.blocks[found.index];
    Walk walk(lo.dialect);
    for (std::size_t i = 0; i < found.index; ++i) walk.block(p.blocks[i]);
    walk.check_at(target);
    RestartPlan plan;
    plan.dialect = lo.dialect;
    plan.block = target.number_text();
    plan.line = target.where.line;
    plan.start = program_start(tape, p, found.index) + definitions_before(tape, p, found.index);
    bool number_sent = p.numbered_by_block && found.index > 0 && p.number && p.blocks[0].source.starts_with(*p.number);
    plan.skipped_blocks = found.index - (number_sent ? 1 : 0);
    plan.marker = "(RESTART AT " + plan.block + ")";
    plan.modal = walk.assignments();
    auto state = walk.state().blocks();
    plan.modal.insert(plan.modal.end(), state.begin(), state.end());
    plan.approach = approach(p, found.index, lo.dialect, lathe, walk, target);
    plan.rest = rest_of_program(tape, p, found.index);
    // The blocks made up here end as the program's own lines do: a CR LF program stays CR LF.
    auto lf = plan.rest.find('\n');
    if (lf != std::string::npos && lf > 0 && plan.rest[lf - 1] == '\r') plan.line_end = "\r\n";
    return plan;
}

}  // namespace tape
