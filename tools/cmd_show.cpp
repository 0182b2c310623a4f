// tape show: the holes picture with frame numbers and characters, bad frames marked.
#include "cli_common.hpp"
#include "commands.hpp"
#include "tape/survey.hpp"

namespace cli {
namespace {

struct ShowArgs {
    std::string input = "-", format;
    CodeChoice choice;
};

void run(const ShowArgs& a) {
    TapeInput in = read_tape(a.input, a.format);
    tape::DecodeOptions o = resolve_code(a.choice, in);
    tape::FrameCode code = tape::FrameCode::make(o.code, o.parity, o.eia_table);
    write_output("-", tape::find_image_format("holes")->write(in.frames, tape::ImageWriteOptions{&code}), false, false);
    auto s = tape::survey(in.frames, code);
    if (s.parity_errors + s.not_in_code > 0) {
        say(display_name(in.name), std::to_string(s.parity_errors) + " parity error(s), " +
                                       std::to_string(s.not_in_code) + " frame(s) not in the code, marked '!'");
        throw Exit{bad_data};
    }
}

}  // namespace

void add_show(CLI::App& app) {
    auto a = std::make_shared<ShowArgs>();
    auto* sub = app.add_subcommand("show", "Draw the tape: holes, frame numbers, characters, bad frames marked '!'");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    add_code_options(sub, a->choice, true);
    sub->add_option("--format,-f", a->format, "Image format of IN: " + format_choices(false))
        ->check(format_check(false));
    sub->callback([a] { run(*a); });
}

}  // namespace cli
