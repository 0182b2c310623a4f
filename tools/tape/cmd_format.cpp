// tape format: rewrite a program for a controller's format (§9): explicit <-> implied point, digits, signs.
#include "cli/globals.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/programs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "tape/encode.hpp"
#include "tape/reformat.hpp"

namespace cli {
namespace {

struct FormatArgs {
    std::string input = "-", output = "-", spec, from, out_format, machine;
    ProgramSource source;
    std::string out_code = "iso";
    bool strip_zeros = false, spaces = false, force = false;
    const CLI::Option* from_option = nullptr;  // given or not: "--from ''" is an error, not "no --from"
    const CLI::Option* spec_option = nullptr;  // the same for --spec
};

void run(const FormatArgs& a) {
    auto machine = machine_or_fail(a.machine);
    if (machine.has_value() == (a.spec_option->count() > 0))
        fail("", tape::Errc::usage, "give the format to write: --spec SPEC or --machine NAME (one of them)");
    if (machine && machine->format.words.empty())
        fail("", tape::Errc::usage, "--machine " + a.machine + ": the profile holds no word format");
    std::optional<tape::FormatSpec> spec;
    if (!machine) spec = parse_spec_or_fail(a.spec);
    std::optional<tape::FormatSpec> from;
    if (a.from_option->count() > 0) from = parse_spec_or_fail(a.from);
    ProgramInput in = open_program(a.input, a.source);
    load_program_whole(in);
    std::vector<tape::Diagnostic> findings;
    std::string text = tape::reformat(in.tape,
                                      tape::ReformatOptions{.spec = spec ? &*spec : nullptr,
                                                            .from = from ? &*from : nullptr,
                                                            .strip_zeros = a.strip_zeros,
                                                            .spaces = a.spaces,
                                                            .machine = machine ? &*machine : nullptr},
                                      findings);
    bool failed = false;
    for (const auto& f : findings) {
        std::string block = f.where.block ? ": block " + std::to_string(*f.where.block) : "";
        say(in.name, position_text(f.where, in.from_tape) + block + ": " + with_hint(f.message, f.hint));
        failed |= f.severity == tape::Severity::error;
    }
    if (failed) throw Exit{bad_data};
    std::string kind = a.out_format;
    if (kind.empty()) {
        const tape::ImageFormat* f = a.output == "-" ? nullptr : tape::image_format_for_path(a.output);
        kind = f && !tape::extension_is_ambiguous(a.output) ? std::string(f->id) : "text";
    }
    if (kind == "text") {
        write_output(a.output, text, false, a.force);
        return;
    }
    tape::EncodeOptions eo;
    eo.code = *tape::parse_code(a.out_code);
    eo.eia_table = globals().table();
    try {
        auto frames = tape::encode(text, eo);
        tape::FrameCode code = tape::FrameCode::make(eo.code, eo.parity, eo.eia_table);
        const tape::ImageFormat* f = tape::find_image_format(kind);
        write_output(a.output, f->write(frames, tape::ImageWriteOptions{&code}), f->binary, a.force);
    } catch (const tape::Error& e) {
        fail(in.name + " (formatted)", e);
    }
}

}  // namespace

void add_format(CLI::App& app) {
    auto a = std::make_shared<FormatArgs>();
    auto* sub = app.add_subcommand("format", "Rewrite a program for a controller's format (ГОСТ 20999-83 §9)");
    sub->add_option("input", a->input, "Tape image or text program; - or nothing for stdin");
    a->spec_option =
        sub->add_option("--spec,-s", a->spec, "The controller's format, e.g. \"N03 G02 X+053 Y+053 F031 M02\"");
    add_machine_option(sub, a->machine, "write for its format, each block as its G codes set it (instead of --spec)");
    a->from_option =
        sub->add_option("--from", a->from, "The format the program is written in, for words with an implied point");
    sub->add_option("-o,--output", a->output, "Where to write: text, or a tape image when OUT has an image extension");
    std::vector<std::string> outputs = format_ids(true);
    outputs.insert(outputs.begin(), "text");
    sub->add_option(
           "--to", a->out_format,
           "Output: text, or a tape image: " + format_choices(true) + " (default: by the extension of OUT, else text)")
        ->check(CLI::IsMember(outputs));
    sub->add_option("--to-code", a->out_code, "Code of an image output: iso or eia")
        ->check(CLI::IsMember({"iso", "eia"}))
        ->capture_default_str();
    sub->add_flag("--strip-zeros", a->strip_zeros, "Leave out leading (or trailing) zeros where the format allows");
    sub->add_flag("--spaces", a->spaces, "Put a space between words");
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    add_program_source_options(sub, a->source);
    sub->callback([a] { run(*a); });
}

}  // namespace cli
