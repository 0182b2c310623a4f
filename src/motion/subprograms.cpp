// Subprograms followed by the interpreter: Fanuc/Haas M98 P (L repeats, or Fanuc's P####LLLL), Haas M97
// P (a block of the same program), M99 (back to the caller; M99 P<N> on at the caller's block N when it
// is ahead), LinuxCNC o<name> call ... o<name> sub/endsub/return. A called body is loaded again from its
// place in the text (SubprogramText) each time; its moves carry its own blocks' places. What cannot be
// followed is named at the calling block, and the tool's place is lost.
#include "motion/subprograms.hpp"

#include <algorithm>
#include <cmath>

#include "motion/machine.hpp"

namespace tape {

using namespace motion;

namespace {

// The calling depth a control allows: Fanuc 4 levels of subprograms (0i/16i/18i manuals); LinuxCNC
// 10 (INTERP_SUB_ROUTINE_LEVELS).
std::size_t nesting_limit(Dialect d) { return d == Dialect::linuxcnc ? 10 : 4; }

// The loader's blocks of a called body, their places counted on from where the body starts in the text,
// to the machine until the body returns.
class Replay : public ProgramVisitor {
public:
    /// lead: the lines fed before the body's text (a '%' line where the dialect needs one).
    Replay(MotionMachine& to, const TextPlace& from, std::uint64_t lead_lines, std::uint64_t lead_bytes)
        : to_(to), from_(from), lead_lines_(lead_lines), lead_bytes_(lead_bytes) {}
    void block(const Block& b) override {
        if (to_.call_over()) return;
        block_ = b;
        shift(block_.where);
        block_.ordinal = from_.ordinal + b.ordinal - 1;
        if (block_.number) shift(block_.number->where);
        for (auto& w : block_.words) shift(w.where);
        for (auto& c : block_.comments) shift(c.where);
        for (auto& s : block_.statements) shift(s.where);
        to_.called_block(block_);
    }

private:
    void shift(Location& at) const {
        at.line -= lead_lines_;
        if (at.line == 1) at.column += from_.column - 1;
        at.line += from_.line - 1;
        at.offset += from_.offset - lead_bytes_;
    }
    MotionMachine& to_;
    TextPlace from_;
    std::uint64_t lead_lines_, lead_bytes_;
    Block block_;  // reused: its strings and vectors keep their room
};

// The call as written for notes: "M98 P1000", "o<name> call".
std::string call_text(const PendingCall& c) {
    return c.kind == PendingCall::Kind::o_sub ? "o" + c.label + " call" : c.label;
}

std::string program_name(long long n) {
    std::string d = std::to_string(n);
    return "O" + std::string(d.size() < 4 ? 4 - d.size() : 0, '0') + d;
}

}  // namespace

void MotionMachine::subprograms(const SubprogramText* text) {
    subs_ = text;
    following_ = subs_ && subs_->has_calls() && opt_.follow_subprograms;
}

// Blocks and repeats run from subprograms are bounded (hostile repeat counts): past the bound nothing
// more runs, said once.
bool MotionMachine::over_budget() {
    if (++calls_.replayed <= CallState::max_replayed) return false;
    if (!calls_.ended)
        not_simulated("more than 10 million blocks run from subprograms: the rest are not followed", all_axes);
    calls_.ended = true;
    return true;
}

bool MotionMachine::call_over() const { return calls_.returned || calls_.ended; }

void MotionMachine::called_block(const Block& b) {
    if (over_budget()) return;
    if (!opt_.findings_only) out_.subprogram_block(b);
    block(b);
}

// A new program: a program some M98 of the text calls does not run on its own (only when called).
void MotionMachine::calls_start(const Program& header) {
    calls_.reset();
    if (!following_ || !header.number) return;
    const SubprogramIndex& index = subs_->index(dialect_);
    std::size_t i = index.program_at(header.start.offset);
    const auto& entry = index.program_entry(i);
    calls_.standalone = entry.number && index.called(*entry.number, i);
}

// Blocks that do not run: a called program in text order, what follows M02/M30, and the caller's blocks
// an M99 P jumps over.
bool MotionMachine::call_skips(const Block& b) {
    if (calls_.standalone || calls_.ended) return true;
    if (calls_.skip_to < 0 || calls_.stack.size() != calls_.skip_depth) return false;
    if (!b.number || b.number->integer() != calls_.skip_to) return true;
    calls_.skip_to = -1;
    return false;
}

// o-words about subroutines, outside definitions: "call" (followed once the block has run, or named),
// "return" and "endsub" inside a call (back to the caller). False for the other o-words.
bool MotionMachine::o_word_call(const Statement& s) {
    if ((s.keyword == "return" || s.keyword == "endsub") && !calls_.stack.empty()) {
        calls_.returned = true;
        return true;
    }
    if (s.keyword != "call") return false;
    if (!following_)
        not_simulated("a subroutine call (" + s.text + ") is not followed: where it leaves the tool is not known",
                      all_axes);
    else
        calls_.pending = PendingCall{.kind = PendingCall::Kind::o_sub, .label = s.label};
    return true;
}

// M97, M98 and M99 (inside a call): a call to follow once the block has run, or a return. True when m
// was one of them and is dealt with; M02/M30 end what is followed.
bool MotionMachine::call_m(int m) {
    if (m == 2 || m == 30) {
        calls_.ended = following_;
        return false;
    }
    if (m == 99 && !calls_.stack.empty()) {
        calls_.returned = true;
        if (w_.has('P')) return_to_block();
        return true;
    }
    if ((m != 98 && m != 97) || dialect_ == Dialect::linuxcnc) return false;
    std::string written = "M" + std::to_string(m) + (w_.word_of('P') ? " " + w_.word_of('P')->text : "");
    if (!following_) {
        not_simulated("a subprogram call (" + written + ") is not followed: where it leaves the tool is not known",
                      all_axes);
        return true;
    }
    if (!w_.ok('P') || (w_.has('L') && !w_.ok('L'))) {
        std::string why = !w_.has('P') ? "no P says which subprogram is called"
                                       : "the subprogram or its repeats are a value known only when the program runs";
        not_simulated(written + ": " + why + ", so where it leaves the tool is not known", all_axes);
        return true;
    }
    PendingCall& c = calls_.pending;
    c = PendingCall{.kind = m == 98 ? PendingCall::Kind::program : PendingCall::Kind::local,
                    .number = std::llround(w_.get('P')),
                    .p_digits = static_cast<int>(w_.word_of('P')->digits().size()),
                    .repeats = w_.ok('L') ? std::llround(std::clamp(w_.get('L'), 0.0, 1e9)) : 1,
                    .repeats_given = w_.ok('L'),
                    .label = written};
    return true;
}

// M99 P<N> in a subprogram: the caller goes on at its block N. Followed when N is ahead of the call in
// the caller's program (its blocks up to N do not run); a jump back is a loop, named.
void MotionMachine::return_to_block() {
    if (!w_.ok('P')) {
        not_simulated("M99 " + w_.word_of('P')->text + ": the block returned to is known only when the program runs",
                      all_axes);
        return;
    }
    long long n = std::llround(w_.get('P'));
    auto& frame = calls_.stack.back();
    const SubprogramIndex& index = subs_->index(dialect_);
    const TextPlace* to = index.numbered(index.program_at(frame.call_offset), n);
    if (!to || to->offset <= frame.call_offset) {
        not_simulated("M99 P" + std::to_string(n) + " returns to N" + std::to_string(n) +
                          (to ? ", before the call: a loop, not followed" : ", which is not in the calling program") +
                          ": where the tool goes after it is not known",
                      all_axes);
        return;
    }
    frame.jumped = true;
    calls_.skip_to = n;
    calls_.skip_depth = calls_.stack.size() - 1;
}

// The body a pending call runs, and its name for notes ("O1000", "N15", "o<name>"); nullopt, named at the
// calling block, when it is not in the text.
std::optional<Body> MotionMachine::call_body(PendingCall& c, std::string& name) {
    const SubprogramIndex& index = subs_->index(dialect_);
    std::optional<Body> body;
    std::string missing;
    if (c.kind == PendingCall::Kind::o_sub) {
        name = "o" + c.label;
        if (const auto* sub = index.sub(c.label)) body = sub->body;
        missing = "no o" + c.label + " sub in this text (LinuxCNC would look for its own file)";
    } else if (c.kind == PendingCall::Kind::local) {
        name = "N" + std::to_string(c.number);
        auto i = index.program_at(block_->where.offset);
        if (const TextPlace* at = index.numbered(i, c.number)) body = Body{*at, index.program_entry(i).body.end};
        missing = "no block " + name + " in this program";
    } else {
        name = program_name(c.number);
        const auto* whole = index.program(c.number);
        // Fanuc's M98 P####LLLL: the leading digits are repeats, the last four the program.
        bool split_form = !c.repeats_given && c.p_digits > 4;
        const auto* split = split_form ? index.program(c.number % 10000) : nullptr;
        if (whole && split) {
            not_simulated(c.label + ": program " + name + ", or " + program_name(c.number % 10000) + " " +
                              std::to_string(c.number / 10000) +
                              " times (Fanuc's P####LLLL): both are in the text, which one the control calls is "
                              "not known",
                          all_axes);
            return std::nullopt;
        }
        if (split) {
            name = program_name(c.number % 10000);
            c.repeats = c.number / 10000;
        }
        if (whole || split) body = (whole ? whole : split)->body;
        missing = "program " + name + " is not in this text";
    }
    if (!body)
        not_simulated(
            call_text(c) + ": " + missing + ": its moves are not simulated, and where it leaves the tool is not known",
            all_axes);
    return body;
}

// A call deeper than the control nests, or of a body already running, is named, not followed.
bool MotionMachine::call_allowed(const Body& body, const std::string& name, const PendingCall& c) {
    std::string call = call_text(c);
    std::size_t limit = nesting_limit(dialect_);
    if (calls_.stack.size() >= limit) {
        // A ГОСТ control's depth is in its manual, not on tape: Fanuc's is the bound followed, said so.
        bool own = dialect_ == Dialect::linuxcnc || dialect_ == Dialect::fanuc;
        not_simulated(call + ": a call nested deeper than the " + std::to_string(limit) + " levels " +
                          (dialect_ == Dialect::linuxcnc ? "LinuxCNC" : "a Fanuc control") +
                          (own ? " allows: the control stops with an alarm; not followed"
                               : " allows (this control's own limit is not known here): not followed"),
                      all_axes);
        return false;
    }
    // Running: the bodies called, and the program the calling block stands in (a program calling itself).
    const SubprogramIndex& index = subs_->index(dialect_);
    bool itself = c.kind == PendingCall::Kind::program &&
                  index.program_entry(index.program_at(block_->where.offset)).body.from.offset == body.from.offset;
    for (const auto& f : calls_.stack) itself = itself || f.body == body.from.offset;
    if (itself) {
        not_simulated(call + " calls " + name +
                          " while it runs (recursion): without a macro to end it the calls "
                          "never end; not followed",
                      all_axes);
        return false;
    }
    return true;
}

// The call met in the block just run, followed: its body run as many times as repeated.
void MotionMachine::follow() {
    PendingCall c = std::move(calls_.pending);
    calls_.pending = PendingCall{};
    const Block* caller = block_;
    std::string name;
    auto body = call_body(c, name);
    if (!body || !call_allowed(*body, name, c)) return;
    calls_.stack.push_back({body->from.offset, caller->where.offset, name, false});
    for (long long i = 0; i < c.repeats && !calls_.ended; ++i) {
        // A repeat counts as a block: an empty body repeated without end stops at the bound too.
        if (over_budget()) break;
        replay(*body);
        calls_.returned = false;
        block_ = caller;
        if (calls_.stack.back().jumped) {
            if (i + 1 < c.repeats)
                not_simulated(call_text(c) + ": M99 P returned from " + name +
                                  " with repeats left: whether they run is "
                                  "not known; not followed",
                              all_axes);
            break;
        }
    }
    calls_.stack.pop_back();
}

// The body's text through the loader again, its blocks to the machine.
void MotionMachine::replay(const Body& body) {
    std::string_view text = subs_->text();
    std::uint64_t from = std::min<std::uint64_t>(body.from.offset, text.size());
    std::uint64_t len = std::min<std::uint64_t>(body.end, text.size()) - std::min(from, body.end);
    bool percent = dialect_rules(dialect_).needs_percent;  // ГОСТ: no program without its '%'
    Replay to(*this, body.from, percent ? 1 : 0, percent ? 2 : 0);
    LoadOptions lo;
    lo.dialect = dialect_;
    lo.leader = false;
    ProgramLoader loader(to, lo);
    if (percent) loader.feed("%\n");
    auto frames = subs_->frame_of();
    loader.feed(text.substr(from, len), frames.size() >= from + len ? frames.subspan(from, len) : decltype(frames){});
    loader.finish();
}

}  // namespace tape
