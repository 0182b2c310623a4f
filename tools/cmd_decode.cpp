// tape decode: a tape image -> the text program, every bad frame reported.
#include "cli_common.hpp"
#include "commands.hpp"

namespace cli {
namespace {

struct DecodeArgs {
    std::string input = "-", output = "-", format;
    CodeChoice choice;
    bool keep_going = false, force = false;
};

void run(const DecodeArgs& a) {
    TapeInput in = read_tape(a.input, a.format);
    std::string name = display_name(in.name);
    tape::DecodeOptions o = resolve_code(a.choice, in);
    o.keep_going = a.keep_going;
    tape::DecodeResult r = tape::decode(in.frames, o);
    for (const auto& d : r.diagnostics) say(name, where_text(d.where, in.raw()) + ": " + d.message);
    if (!r.complete) throw Exit{bad_data};  // nothing written: the program would be cut short
    write_output(a.output, r.text, false, a.force);
    if (!r.ok()) {
        say(name, std::to_string(r.diagnostics.size()) + " bad frame(s), each marked \xEF\xBF\xBD in the text");
        throw Exit{bad_data};
    }
}

}  // namespace

void add_decode(CLI::App& app) {
    auto a = std::make_shared<DecodeArgs>();
    auto* sub = app.add_subcommand("decode", "Read a tape image back into the text program");
    sub->add_option("input", a->input, "Tape image (raw or holes); - or nothing for stdin");
    sub->add_option("-o,--output", a->output, "Text file to write; - for stdout");
    add_code_options(sub, a->choice, true);
    sub->add_option("--format,-f", a->format, "Image format of IN: raw or holes (default: by extension, else by content)")
        ->check(CLI::IsMember({"raw", "holes"}));
    sub->add_flag("--keep-going,-k", a->keep_going,
                  "Report every bad frame, write the program with each marked U+FFFD, still exit 1");
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
