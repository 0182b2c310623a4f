#include "cli/programs.hpp"

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/run.hpp"

namespace cli {

void add_program_source_options(CLI::App* sub, ProgramSource& source, bool with_keep_going) {
    add_code_options(sub, source.choice, true, CodeSet::five_track);
    sub->add_option("--format,-f", source.format,
                    "Image format of IN: " + format_choices(false) + " (IN is then a tape image)")
        ->check(format_check(false));
    sub->add_option("--input", source.kind, "What IN is: auto (image or text by extension and content), text, image")
        ->check(CLI::IsMember({"auto", "text", "image"}))
        ->capture_default_str();
    add_dialect_option(sub, source.dialect);
    if (with_keep_going)
        sub->add_flag("--keep-going,-k", source.keep_going,
                      "Go on past bad frames (each reported; exit 1 at the end) instead of stopping at the first");
}

tape::LoadOptions load_options(const ProgramSource& source) {
    return tape::LoadOptions{tape::parse_dialect(source.dialect).value_or(tape::Dialect::automatic)};
}

void say_dialect(const std::string& name, const tape::DialectChoice& choice) {
    if (globals().verbosity <= 0) return;
    say(name, "dialect " + std::string(tape::dialect_name(choice.dialect)) +
                  (choice.reason.empty() ? " (given with --dialect)" : " (" + choice.reason + ")"));
}

ProgramInput open_program(const std::string& path, const ProgramSource& source) {
    tape::InputOptions o = input_options(source.choice, source.format, source.kind);
    o.decode.positions = true;
    o.decode.keep_going = source.keep_going;
    o.decided_runs = source.decided_runs;
    ProgramInput in;
    in.name = display_name(path);
    in.load = load_options(source);
    in.keep_going = source.keep_going;
    in.input = open_input(path, o);
    in.from_tape = in.input->is_image();
    if (in.from_tape) decide_code(*in.input, in.name);
    return in;
}

namespace {
// Bad frames are printed as decode prints them (or left to the visitor), and the dialect said with -v.
class BadFramesFail : public tape::ProgramVisitor {
public:
    BadFramesFail(tape::ProgramVisitor& to, const std::string& name, bool raw, bool frames_to_visitor)
        : to_(to), name_(name), raw_(raw), frames_to_visitor_(frames_to_visitor) {}
    void label(std::string_view text) override { to_.label(text); }
    void program_start(const tape::Program& header) override { to_.program_start(header); }
    void block(const tape::Block& block) override { to_.block(block); }
    void after_end(std::string_view text, const tape::Location& where) override { to_.after_end(text, where); }
    void physical_start() override { to_.physical_start(); }
    void record_end(const tape::Location& where, bool closes_program) override {
        to_.record_end(where, closes_program);
    }
    void dialect(const tape::DialectChoice& choice) override {
        say_dialect(name_, choice);
        to_.dialect(choice);
    }
    void end(const tape::Location& where) override { to_.end(where); }
    void finding(const tape::Finding& f) override {
        if (tape::is_bad_frame(f.code)) {
            bad_ = true;
            if (!frames_to_visitor_) {
                say_diagnostic(name_, f, raw_);
                return;
            }
        }
        to_.finding(f);
    }
    bool bad() const { return bad_; }

private:
    tape::ProgramVisitor& to_;
    const std::string& name_;
    bool raw_;
    bool frames_to_visitor_;
    bool bad_ = false;
};

bool raw_frames(const ProgramInput& in) { return in.from_tape && in.input->format()->bytes_are_frames; }
}  // namespace

void load_program(ProgramInput& in, tape::ProgramVisitor& visitor, bool frames_to_visitor) {
    BadFramesFail guard(visitor, in.name, raw_frames(in), frames_to_visitor && in.keep_going);
    try {
        tape::load_each(*in.input, guard, in.load);
    } catch (const tape::Error& e) {
        fail(in.name, e);
    }
    if (guard.bad()) in.damaged = true;
    if (guard.bad() && !in.keep_going) end_program(in);
}

void end_program(const ProgramInput& in) {
    if (!in.damaged) return;
    if (const tape::Decoder* d = in.input->decoder()) say_unlisted_frames(in.name, d->unlisted());
    say_other_reading(*in.input, in.name);
    throw Exit{bad_data};
}

void load_program_whole(ProgramInput& in) {
    try {
        tape::load(*in.input, in.tape, in.load);
    } catch (const tape::Error& e) {
        fail(in.name, e);
    }
    say_dialect(in.name, tape::DialectChoice{in.tape.dialect, in.tape.dialect_reason});
    bool bad = false;
    for (const auto& f : in.tape.findings)
        if (tape::is_bad_frame(f.code)) {
            say_diagnostic(in.name, f, raw_frames(in));
            bad = true;
        }
    if (bad) {
        say_other_reading(*in.input, in.name);
        throw Exit{bad_data};
    }
}

}  // namespace cli
