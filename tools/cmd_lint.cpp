// tape lint: check programs against ГОСТ 20999-83 and, with --spec, a controller's format.
#include <map>

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
    ProgramInput in = load_program_whole(a.input, a.source);
    auto findings = tape::lint(in.tape, tape::LintOptions{spec ? &*spec : nullptr});
    std::string out;
    std::size_t errors = 0, warnings = 0;
    std::map<std::string, std::uint64_t> shown, unlisted;  // by rule, for --max-errors
    for (const auto& f : findings) {
        errors += f.severity == tape::Severity::error;
        warnings += f.severity == tape::Severity::warning;
        std::string rule(f.id());
        if (globals().max_errors != 0 && shown[rule] >= globals().max_errors) {
            ++unlisted[rule];
            continue;
        }
        ++shown[rule];
        out += in.name + ":" + position_text(f.where, in.from_tape) +
               (f.where.block ? ":block " + std::to_string(*f.where.block) : "") + ": " + rule + ": " +
               (f.severity == tape::Severity::error ? "" : std::string(tape::severity_name(f.severity)) + ": ") +
               tape::visible(f.message) + "\n";
    }
    write_output("-", out, false, false);
    for (const auto& [rule, count] : unlisted) say_unlisted(in.name, count, rule + " finding(s)");
    if (globals().verbosity >= 0 && !findings.empty())
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
