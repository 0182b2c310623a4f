// tape restore: one tape from several reads of a damaged one, with a report of what was recovered,
// guessed or lost (tape/restore.hpp), and the frames left in doubt kept beside the image.
#include <malloc.h>

#include <algorithm>

#include "cli/files.hpp"
#include "cli/inputs.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "picture_reads.hpp"
#include "restore_html.hpp"
#include "restore_report.hpp"
#include "restore_run.hpp"
#include "tape/format_spec.hpp"
#include "tape/restore_doubts.hpp"

namespace cli {
namespace {

struct RestoreArgs {
    std::vector<std::string> reads;
    std::string output, report, html, format, code = "auto", parity, dialect = "auto", spec, machine;
    bool json = false, force = false, guess = false, drop_unrelated = false, no_doubts_file = false;
};

// Restoring aligns and votes in vectors of many megabytes, made and freed stage after stage: glibc gives
// each back to the system and takes it again, zeroed, a fifth of the run. Freed memory is kept instead.
void keep_freed_memory() {
    constexpr int keep = 256 << 20;
    mallopt(M_MMAP_THRESHOLD, keep);
    mallopt(M_TRIM_THRESHOLD, keep);
}

void run(const RestoreArgs& a) {
    keep_freed_memory();
    check_outputs({{"-o", a.output}, {"--report", a.report}, {"--html", a.html}});
    // Every output is looked at before the reads are, and before anything is written: a refusal after the
    // image was written would leave a run half done.
    std::string doubts_file = tape::doubts_file_for(a.output);
    bool doubts = a.output != "-" && !a.no_doubts_file && a.report != doubts_file;
    for (const std::string& out : {a.output, doubts ? doubts_file : "", a.report, a.html})
        refuse_existing(out, a.force);
    std::optional<tape::FormatSpec> spec;
    if (!a.spec.empty()) spec = parse_spec_or_fail(a.spec);
    auto machine = machine_or_fail(a.machine);
    if (machine && spec)
        fail("", tape::Errc::usage, "--spec and --machine: the machine's profile has its format; give one");
    const tape::ImageFormat& out_format = output_format(a.format, a.output);
    refuse_binary_terminal(a.output, out_format.binary, a.force);
    ReadsAndDoubts in = read_tapes_or_pictures(a.reads);
    const std::vector<TapeInput>& reads = in.reads;
    RestoreReportInput report;
    report.code = code_for_reads(a.code, a.parity, reads, report.code_text);
    for (const auto& r : reads) report.names.push_back(r.name);
    describe_reads(in, report);
    RestoreChoices choices{.dialect = a.dialect, .guess = a.guess, .drop_unrelated = a.drop_unrelated};
    choices.spec = spec ? &*spec : nullptr;
    choices.machine = machine ? &*machine : nullptr;
    tape::RestoreResult result = run_restore(choices, in, report);
    report.result = &result;
    say_about_reads(report, result);
    // The image first: it is what the run is for, and it is written even when not every frame was restored.
    tape::ImageWriteOptions wo;
    if (report.code) wo.annotate = &*report.code;
    try {
        report.image_bytes = out_format.write(result.frames, wo);
    } catch (const tape::Error& e) {
        fail(display_name(a.output), e);
    }
    report.image_name = a.output;
    write_output(a.output, report.image_bytes, out_format.binary, a.force);
    if (doubts) write_output(doubts_file, restore_report_json(report), false, a.force);
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
    sub->add_option("-o,--output", a->output,
                    "The restored image (format by extension, or --format); the report in JSON goes beside it to "
                    "IMAGE.restore.json, so that every command reading IMAGE names the frames left in doubt")
        ->required();
    sub->add_option("--report", a->report, "Write the report to FILE instead of standard output");
    sub->add_flag("--json", a->json, "The report as JSON (schema tape-restore/2, in tape(1))");
    sub->add_option("--html", a->html,
                    "Also write the report as one self-contained HTML page: the problem frames with what each read "
                    "saw, and the tape drawn around them");
    sub->add_option("--format,-f", a->format, "Image format of the output: " + format_choices(true))
        ->check(format_check(true));
    sub->add_option("--code,-c", a->code,
                    "Tape code: auto (the code most reads fit), iso, eia, or none (a binary tape: vote only)")
        ->check(CLI::IsMember({"auto", "iso", "eia", "none"}))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity,
                    "Track 8 rule of ISO: even (default), odd, mark, space, none; given alone, the code is ISO")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}));
    add_dialect_option(sub, a->dialect);
    sub->add_option("--spec,-s", a->spec, "Controller format repairs must also fit (ГОСТ 20999-83 §9 notation)");
    add_machine_option(
        sub, a->machine,
        "repairs must fit its word format mode by mode, feed code table and S, T, M words (instead of --spec)");
    sub->add_flag("--guess", a->guess,
                  "Where several repairs fit, write the likeliest, marked guessed with the others listed (exit 1)");
    sub->add_flag("--drop-unrelated", a->drop_unrelated,
                  "Go on without a read of another tape (or one too damaged to align), instead of refusing");
    sub->add_flag("--no-doubts-file", a->no_doubts_file, "Do not write IMAGE.restore.json beside the image");
    sub->add_flag("--force", a->force, "Replace an existing output, report or doubts file");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
