// tape restore: one tape from several reads of a damaged one, with a report of what was recovered,
// guessed or lost (tape/restore.hpp).
#include "cli/files.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "picture_reads.hpp"
#include "restore_html.hpp"
#include "restore_report.hpp"
#include "tape/format_spec.hpp"

namespace cli {
namespace {

struct RestoreArgs {
    std::vector<std::string> reads;
    std::string output, report, html, format, code = "auto", parity = "even", dialect = "auto", spec;
    bool json = false, force = false;
};

void run(const RestoreArgs& a) {
    check_outputs({{"-o", a.output}, {"--report", a.report}, {"--html", a.html}});
    std::optional<tape::FormatSpec> spec;
    if (!a.spec.empty()) spec = parse_spec_or_fail(a.spec);
    const tape::ImageFormat& out_format = output_format(a.format, a.output);
    refuse_binary_terminal(a.output, out_format.binary, a.force);
    std::vector<TapeInput> reads;
    for (const auto& path : a.reads) reads.push_back(is_picture(path) ? read_picture(path).read : read_tape(path, ""));
    RestoreReportInput report;
    report.code = code_for_reads(a.code, a.parity, reads, report.code_text);
    std::vector<std::span<const tape::Frame>> spans;
    for (const auto& r : reads) {
        spans.emplace_back(r.frames);
        report.names.push_back(r.name);
        report.sizes.push_back(r.frames.size());
    }
    tape::RestoreResult result;
    try {
        result = tape::restore(spans, tape::RestoreOptions{.code = report.code,
                                                           .dialect = *tape::parse_dialect(a.dialect),
                                                           .spec = spec ? &*spec : nullptr});
    } catch (const tape::Error& e) {
        fail("", e);
    }
    report.result = &result;
    // The image first: it is what the run is for, and it is written even when not every frame was restored.
    tape::ImageWriteOptions wo;
    if (report.code) wo.annotate = &*report.code;
    write_output(a.output, out_format.write(result.frames, wo), out_format.binary, a.force);
    std::string text = a.json ? restore_report_json(report) : restore_report_text(report);
    write_output(a.report.empty() ? "-" : a.report, text, false, a.force);
    if (!a.html.empty()) write_output(a.html, restore_report_html(report), false, a.force);
    if (!result.complete()) throw Exit{bad_data};
}

}  // namespace

void add_restore(CLI::App& app) {
    auto a = std::make_shared<RestoreArgs>();
    auto* sub = app.add_subcommand(
        "restore", "One tape from several reads of a damaged one: aligned, voted, repaired where only one way fits");
    sub->add_option("reads", a->reads,
                    "Reads of one physical tape, in any image format, or pictures of it (PNG, JPEG, TIFF: read as by "
                    "tape scan); one or more")
        ->required();
    sub->add_option("-o,--output", a->output, "The restored image (format by extension, or --format)")->required();
    sub->add_option("--report", a->report, "Write the report to FILE instead of standard output");
    sub->add_flag("--json", a->json, "The report as JSON (schema tape-restore/1, in tape(1))");
    sub->add_option("--html", a->html,
                    "Also write the report as one self-contained HTML page: the tape drawn with its problem "
                    "frames marked, and a table of them");
    sub->add_option("--format,-f", a->format, "Image format of the output: " + format_choices(true))
        ->check(format_check(true));
    sub->add_option("--code,-c", a->code,
                    "Tape code: auto (from the longest read), iso, eia, or none (a binary tape: vote only)")
        ->check(CLI::IsMember({"auto", "iso", "eia", "none"}))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity, "Track 8 rule with --code iso: even, odd, mark, space, none")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}))
        ->capture_default_str();
    add_dialect_option(sub, a->dialect);
    sub->add_option("--spec,-s", a->spec, "Controller format repairs must also fit (ГОСТ 20999-83 §9 notation)");
    sub->add_flag("--force", a->force, "Replace an existing output or report");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
