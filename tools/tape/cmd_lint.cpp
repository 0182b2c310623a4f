// tape lint: check programs against ГОСТ 20999-83 or a controller dialect and, with --spec, a
// controller's format.

#include "cli/globals.hpp"
#include "cli/json.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/programs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "tape/lint.hpp"
#include "tape/rules.hpp"
#include "tape/utf8_text.hpp"

namespace cli {
namespace {

struct LintArgs {
    std::string input = "-", spec, explain, machine;
    ProgramSource source;
    bool json = false, rules = false, strict = false;
    std::uint64_t max = 0;
    std::optional<double> arc_tolerance;
};

std::string rule_names() {
    std::string names;
    for (const auto& r : tape::all_rules()) names += (names.empty() ? "" : ", ") + std::string(r.id);
    return names;
}

void explain(const std::string& id) {
    const tape::Rule* r = tape::find_rule(id);
    if (!r) fail("", tape::Errc::usage, "--explain: no rule '" + id + "'; the rules are " + rule_names());
    std::string out = std::string(r->id) + " (" + std::string(tape::severity_name(r->severity)) + ")\n" +
                      "  checks:    " + std::string(r->checks) + "\n" + "  why:       " + std::string(r->why) + "\n" +
                      "  reference: " + std::string(r->reference) + "\n" + "  dialects:  " + std::string(r->dialects) +
                      "\n";
    write_output("-", out, false, false);
}

std::string finding_line(const ProgramInput& in, const tape::Finding& f) {
    return in.name + ":" + position_text(f.where, in.from_tape) +
           (f.where.block ? ":block " + std::to_string(*f.where.block) : "") + ": " + std::string(f.id()) + ": " +
           (f.severity == tape::Severity::error ? "" : std::string(tape::severity_name(f.severity)) + ": ") +
           tape::visible(f.message) + "\n";
}

std::string counted(std::uint64_t n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// "3 errors, 1 warning, 2 notes in 1 program: g-group 2, repeated-dimension 1, ...", and what the
// dialect's choice left out.
std::string summary_text(const tape::LintVisitor& linter) {
    std::string s = counted(linter.count(tape::Severity::error), "error") + ", " +
                    counted(linter.count(tape::Severity::warning), "warning");
    if (std::uint64_t notes = linter.count(tape::Severity::note)) s += ", " + counted(notes, "note");
    s += " in " + counted(linter.programs(), "program");
    std::string rules;
    for (const auto& [rule, count] : linter.by_rule())
        rules += (rules.empty() ? ": " : ", ") + std::string(rule) + " " + std::to_string(count);
    s += rules;
    if (linter.dialect() == tape::Dialect::none)
        s += "; no known dialect fits: only what holds for every control was checked";
    if (auto close = linter.close())
        s += "; " + std::string(tape::dialect_name(linter.dialect())) + " and " +
             std::string(tape::dialect_name(*close)) + " were close: only what both readings find is listed";
    return s;
}

Json summary_value(const tape::LintVisitor& linter, std::uint64_t unlisted) {
    Json rules = Json::object();
    for (const auto& [rule, count] : linter.by_rule()) rules[std::string(rule)] = count;
    return Json{{"errors", linter.count(tape::Severity::error)},
                {"warnings", linter.count(tape::Severity::warning)},
                {"notes", linter.count(tape::Severity::note)},
                {"programs", linter.programs()},
                {"by_rule", rules},
                {"not_listed", unlisted}};
}

void list_rules() {
    std::string out;
    for (const auto& r : tape::all_rules())
        out += std::string(r.id) + std::string(r.id.size() < 24 ? 24 - r.id.size() : 1, ' ') +
               std::string(tape::severity_name(r.severity)) +
               std::string(9 - tape::severity_name(r.severity).size(), ' ') + std::string(r.dialects) + "\n";
    write_output("-", out, false, false);
}

void run(const LintArgs& a) {
    if (a.rules) {
        list_rules();
        return;
    }
    if (!a.explain.empty()) {
        explain(a.explain);
        return;
    }
    std::optional<tape::FormatSpec> spec;
    if (!a.spec.empty()) spec = parse_spec_or_fail(a.spec);
    // Streamed: a tape of any length is checked in bounded memory (--max-errors findings a rule).
    ProgramSource source = a.source;
    source.decided_runs = true;  // a restored image: where a wrong run length could hide, as notes
    ProgramInput in = open_program(a.input, source);
    auto machine = machine_or_fail(a.machine);
    if (machine && spec)
        fail("", tape::Errc::usage, "--spec and --machine: the machine's profile has its format; give one");
    if (machine && a.source.dialect == "auto") in.load.dialect = machine->dialect;
    tape::LintVisitor linter(tape::LintOptions{spec ? &*spec : nullptr, globals().max_errors, a.strict,
                                               machine ? &*machine : nullptr, a.arc_tolerance});
    load_program(in, linter, true);
    std::vector<tape::Finding> findings = linter.findings();
    std::uint64_t unlisted = 0;
    for (const auto& [rule, count] : linter.unlisted()) unlisted += count;
    if (a.max && findings.size() > a.max) {
        unlisted += findings.size() - a.max;
        findings.resize(a.max);
    }
    std::string out;
    if (a.json) {
        Json listed = Json::array();
        for (const auto& f : findings) listed.push_back(finding_value(f));
        Json close = linter.close() ? Json(std::string(tape::dialect_name(*linter.close()))) : Json(nullptr);
        out = json_text(Json{{"file", in.name},
                             {"dialect", std::string(tape::dialect_name(linter.dialect()))},
                             {"close", close},
                             {"findings", listed},
                             {"summary", summary_value(linter, unlisted)}}) +
              "\n";
    } else {
        for (const auto& f : findings) out += finding_line(in, f);
    }
    write_output("-", out, false, false);
    if (!a.json) {
        if (unlisted)
            say(in.name, std::to_string(unlisted) + " more finding(s) not shown (" +
                             (a.max ? "--max " + std::to_string(a.max) + ", " : std::string()) + "--max-errors " +
                             std::to_string(globals().max_errors) + " a rule)");
        if (globals().verbosity >= 0) say(in.name, summary_text(linter));
    }
    end_program(in);
    if (linter.count(tape::Severity::error)) throw Exit{bad_data};
}

}  // namespace

void add_lint(CLI::App& app) {
    auto a = std::make_shared<LintArgs>();
    auto* sub = app.add_subcommand(
        "lint", "Check programs against ГОСТ 20999-83 or a controller dialect (and a controller format with --spec)");
    sub->add_option("input", a->input, "Tape image or text program; - or nothing for stdin");
    add_program_source_options(sub, a->source, true);
    sub->add_option("--spec,-s", a->spec,
                    "Controller format, ГОСТ 20999-83 §9 notation, e.g. \"N03 G02 X+053 Y+053 F031 S04 T04 M02\"");
    sub->add_flag("--json", a->json,
                  "Every finding as JSON: rule, severity (error, warning, note), position, message; and a summary");
    sub->add_option("--max", a->max, "List at most N findings in all (the rest are counted); 0: no limit")
        ->check(whole_number(0, 1000000000))
        ->capture_default_str();
    sub->add_option("--explain", a->explain, "Print what RULE checks, why, and its reference; no input is read")
        ->option_text("RULE");
    sub->add_flag("--rules", a->rules, "List every rule: id, severity, the dialects it applies to; no input is read");
    add_machine_option(sub, a->machine,
                       "its word format as its G codes set it (in place of --spec), feed and speed codes");
    sub->add_flag("--strict", a->strict, "Blank tape inside a block (a character that lost its holes?) is an error");
    sub->add_option("--arc-tolerance", a->arc_tolerance,
                    "How far (mm) an arc's end may be off its circle: the radii to start and end may differ by this "
                    "much. Default: the dialect's control (ГОСТ: 0.001, the seeds' alarm 7.56; LinuxCNC: 0.0283 or "
                    "0.1 % of the radius; Fanuc: 0.02, parameter No. 3410)")
        ->check(CLI::Range(0.0, 1000.0))
        ->option_text("MM");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
