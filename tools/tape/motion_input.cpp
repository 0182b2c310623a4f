#include "motion_input.hpp"

#include "cli/inputs.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"

namespace cli {
namespace {

// The loader's blocks to the interpreter, and bad frames counted as they are read past.
class MotionFeed : public tape::ProgramVisitor {
public:
    MotionFeed(tape::Interpreter& to, const std::function<void(const tape::Block&)>& on_block,
               std::vector<std::uint64_t>& bad)
        : to_(to), on_block_(on_block), bad_(bad) {}
    void dialect(const tape::DialectChoice& choice) override { to_.dialect(choice); }
    void program_start(const tape::Program& header) override { to_.program_start(header); }
    void block(const tape::Block& block) override {
        if (on_block_) on_block_(block);
        to_.block(block);
    }
    void end(const tape::Location& where) override { to_.end(where); }
    void finding(const tape::Finding& f) override {
        if (tape::is_bad_frame(f.code) && f.where.frame) bad_.push_back(*f.where.frame);
    }

private:
    tape::Interpreter& to_;
    const std::function<void(const tape::Block&)>& on_block_;
    std::vector<std::uint64_t>& bad_;
};

// The subprograms a block calls are looked up in the whole text, read a first time before the blocks
// are streamed; it is kept only when it writes a call, and up to this size (a bound on memory).
constexpr std::size_t max_called_text = 64 << 20;

// The whole of path's text (and frames) as the streaming pass will read it; nullopt for standard input
// (read once), a text too long to keep, or one that cannot be read (the streaming pass says why).
std::optional<tape::DecodeResult> text_for_calls(const std::string& path, const ProgramSource& source) {
    if (path.empty() || path == "-") return std::nullopt;
    try {
        tape::InputOptions o = input_options(source.choice, source.format, source.kind);
        o.decode.positions = true;
        o.decode.keep_going = true;
        o.decided_runs = source.decided_runs;
        tape::Input in(path, o);
        tape::DecodeResult all;
        while (in.next_text(all) && all.complete)
            if (all.text.size() > max_called_text) return std::nullopt;
        return all;
    } catch (const tape::Error&) {
        return std::nullopt;
    }
}

}  // namespace

void add_motion_options(CLI::App* sub, MotionArgs& args, bool with_machine) {
    sub->add_flag("--lathe", args.lathe, "The program is for a lathe (X-Z turning, X written as a diameter)");
    auto* spec = sub->add_option("--spec,-s", args.spec,
                                 "Controller format, ГОСТ 20999-83 §9 notation (\"X+053 Z+053 F031\"): where the "
                                 "point of a number written without one stands");
    if (with_machine)
        add_machine_option(sub, args.machine,
                           "lathe or mill, X as a diameter, its word formats, arc tolerance and rapid rates")
            ->excludes(spec);
}

const tape::MachineProfile* motion_machine(const MotionArgs& args) {
    static std::optional<tape::MachineProfile> loaded;  // one command, one machine
    if (args.machine.empty()) return nullptr;
    if (!loaded) loaded = machine_or_fail(args.machine);
    return &*loaded;
}

tape::MotionOptions motion_options(const ProgramSource& source, const MotionArgs& args,
                                   const std::optional<tape::FormatSpec>& spec) {
    tape::Dialect dialect = load_options(source).dialect;
    const tape::MachineProfile* machine = motion_machine(args);
    if (machine && source.dialect == "auto") dialect = machine->dialect;
    tape::MotionOptions o = machine ? tape::motion_options(*machine, dialect) : tape::motion_options(dialect);
    if (!o.spec && spec) o.spec = &*spec;  // a machine without a word format: --spec's
    if (!machine) o.lathe = args.lathe;
    return o;
}

MotionRead read_motion(const std::string& path, const ProgramSource& source, const MotionArgs& args,
                       tape::MotionVisitor& out, const std::function<void(const tape::Block&)>& on_block) {
    ProgramSource reading = source;
    reading.keep_going = true;  // a damaged tape is still drawn and compared: its bad frames are marked
    MotionRead read;
    read.in = open_program(path, reading);
    read.name = read.in.name;
    read.from_tape = read.in.from_tape;
    std::optional<tape::FormatSpec> spec;
    if (!args.spec.empty()) spec = parse_spec_or_fail(args.spec);
    auto whole = text_for_calls(path, reading);
    std::optional<tape::SubprogramText> subs;
    if (whole)
        subs.emplace(whole->text, read.from_tape ? std::span<const std::uint64_t>(whole->frame_of)
                                                 : std::span<const std::uint64_t>());
    tape::Interpreter interpreter(out, motion_options(source, args, spec));
    if (subs && subs->has_calls()) interpreter.subprograms(&*subs);
    MotionFeed feed(interpreter, on_block, read.bad_frames);
    load_program(read.in, feed, true);
    return read;
}

void end_motion(const MotionRead& read) {
    if (!read.bad_frames.empty())
        say(read.name,
            std::to_string(read.bad_frames.size()) + " bad frame(s) read past: the moves of their blocks are in doubt");
    end_program(read.in);
}

void say_not_simulated(const std::string& name, const std::vector<tape::Move>& kept, std::uint64_t count,
                       bool from_tape) {
    for (const auto& m : kept) say(name, position_text(m.where, from_tape) + ": not simulated: " + m.note);
    if (count > kept.size()) say(name, std::to_string(count - kept.size()) + " more block(s) not simulated");
}

}  // namespace cli
