// tape lint: check programs against ГОСТ 20999-83 and, with --spec, a controller's format.

#include "cli_common.hpp"
#include "commands.hpp"
#include "tape/lint.hpp"
#include "tape/utf8_text.hpp"

namespace cli {
namespace {

struct LintArgs {
    std::string input = "-", spec;
    ProgramSource source;
};

void run(const LintArgs& a) {
    std::optional<tape::FormatSpec> spec;
    if (!a.spec.empty()) {
        try {
            spec = tape::parse_format_spec(a.spec);
        } catch (const tape::Error& e) {
            fail("", e);
        }
    }
    // Streamed: a tape of any length is checked in bounded memory.
    ProgramInput in = open_program(a.input, a.source);
    tape::LintVisitor linter(tape::LintOptions{spec ? &*spec : nullptr, globals().max_errors});
    load_program(in, linter);
    std::string out;
    for (const auto& f : linter.findings()) {
        out += in.name + ":" + position_text(f.where, in.from_tape) +
               (f.where.block ? ":block " + std::to_string(*f.where.block) : "") + ": " + std::string(f.id()) + ": " +
               (f.severity == tape::Severity::error ? "" : std::string(tape::severity_name(f.severity)) + ": ") +
               tape::visible(f.message) + "\n";
    }
    write_output("-", out, false, false);
    for (const auto& [rule, count] : linter.unlisted()) say_unlisted(in.name, count, std::string(rule) + " finding(s)");
    auto errors = linter.count(tape::Severity::error), warnings = linter.count(tape::Severity::warning);
    if (globals().verbosity >= 0 && errors + warnings + linter.count(tape::Severity::note) > 0)
        say(in.name, std::to_string(errors) + " error(s), " + std::to_string(warnings) + " warning(s)");
    if (errors) throw Exit{bad_data};
}

}  // namespace

void add_lint(CLI::App& app) {
    auto a = std::make_shared<LintArgs>();
    auto* sub =
        app.add_subcommand("lint", "Check programs against ГОСТ 20999-83 (and a controller format with --spec)");
    sub->add_option("input", a->input, "Tape image or text program; - or nothing for stdin");
    add_program_source_options(sub, a->source);
    sub->add_option("--spec,-s", a->spec,
                    "Controller format, ГОСТ 20999-83 §9 notation, e.g. \"N03 G02 X+053 Y+053 F031 S04 T04 M02\"");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
