// tape restore: one tape from several reads of a damaged one, with a report of what was recovered,
// guessed or lost (tape/restore.hpp), and the frames left in doubt kept beside the image.
#include <malloc.h>

#include <algorithm>

#include "cli/files.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/restore_inputs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "picture_reads.hpp"
#include "restore_html.hpp"
#include "restore_report.hpp"
#include "tape/format_spec.hpp"
#include "tape/restore_doubts.hpp"

namespace cli {
namespace {

struct RestoreArgs {
    std::vector<std::string> reads;
    std::string output, report, html, format, code = "auto", parity, dialect = "auto", spec;
    bool json = false, force = false, guess = false, drop_unrelated = false, no_doubts_file = false;
};

tape::RestoreResult run_restore(const RestoreArgs& a, const ReadsAndDoubts& in, const RestoreReportInput& report,
                                const tape::FormatSpec* spec) {
    const std::vector<TapeInput>& reads = in.reads;
    std::vector<std::span<const tape::Frame>> spans;
    for (const auto& r : reads) spans.emplace_back(r.frames);
    tape::RestoreOptions o{.code = report.code, .dialect = *tape::parse_dialect(a.dialect), .spec = spec};
    o.guess = a.guess;
    o.align.drop_unrelated = a.drop_unrelated;
    o.doubts = in.doubts;  // a picture's faint holes weigh less than a sure reading
    try {
        return tape::restore(spans, o);
    } catch (const tape::UnrelatedRead& e) {
        fail(display_name(reads[e.read()].name), tape::Errc::bad_image,
             (report.blank[e.read()] ? "no punched frame (blank tape only): nothing of the tape to restore from"
                                     : unrelated_text(e, reads)) +
                 " (--drop-unrelated goes on without it)");
    } catch (const tape::Error& e) {
        fail("", e);
    }
}

// What the reads and the code say before the report: reads left out, a code that does not fit.
void say_about_reads(const RestoreReportInput& in, const tape::RestoreResult& r) {
    for (std::size_t i = 0; i < in.names.size(); ++i)
        if (!r.related[i]) say(display_name(in.names[i]), left_out_text(in, i));
    if (in.code && r.code_misfit)
        say("", "most frames of the reads fail the code " + in.code_text +
                    ": it is not the tape's, so the reads were only voted, nothing repaired (try --code auto, or "
                    "another --parity)");
}

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
    const tape::ImageFormat& out_format = output_format(a.format, a.output);
    refuse_binary_terminal(a.output, out_format.binary, a.force);
    ReadsAndDoubts in = read_tapes_or_pictures(a.reads);
    const std::vector<TapeInput>& reads = in.reads;
    RestoreReportInput report;
    report.code = code_for_reads(a.code, a.parity, reads, report.code_text);
    for (const auto& r : reads) {
        report.names.push_back(r.name);
        report.sizes.push_back(r.frames.size());
        report.blank.push_back(std::all_of(r.frames.begin(), r.frames.end(), [](tape::Frame f) { return f == 0; }));
    }
    tape::RestoreResult result = run_restore(a, in, report, spec ? &*spec : nullptr);
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
                    "Tape code: auto (from the longest read), iso, eia, or none (a binary tape: vote only)")
        ->check(CLI::IsMember({"auto", "iso", "eia", "none"}))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity,
                    "Track 8 rule of ISO: even (default), odd, mark, space, none; given alone, the code is ISO")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}));
    add_dialect_option(sub, a->dialect);
    sub->add_option("--spec,-s", a->spec, "Controller format repairs must also fit (ГОСТ 20999-83 §9 notation)");
    sub->add_flag("--guess", a->guess,
                  "Where several repairs fit, write the likeliest, marked guessed with the others listed (exit 1)");
    sub->add_flag("--drop-unrelated", a->drop_unrelated,
                  "Go on without a read of another tape (or one too damaged to align), instead of refusing");
    sub->add_flag("--no-doubts-file", a->no_doubts_file, "Do not write IMAGE.restore.json beside the image");
    sub->add_flag("--force", a->force, "Replace an existing output, report or doubts file");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
