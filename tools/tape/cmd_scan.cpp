// tape scan: pictures of a tape (flatbed scans, photos of a tape lying flat) read as a tape image, with
// a report of what was seen and which frames are doubtful (tape/scan.hpp).
#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "scan_report.hpp"
#include "tape/file_io.hpp"
#include "tape/scan.hpp"

namespace cli {
namespace {

struct ScanArgs {
    std::vector<std::string> images;
    std::string output, report, format, debug_svg, start = "auto";
    int tracks = 8;
    double dpi = 0;
    bool json = false, force = false;
};

// Where the report goes: --report FILE, else standard output, else (the read itself on standard
// output) standard error.
void write_report(const ScanArgs& a, const std::string& text) {
    if (!a.report.empty()) return write_output(a.report, text, false, a.force);
    if (a.output == "-") {
        std::cerr << text;
        return;
    }
    write_output("-", text, false, a.force);
}

void run(const ScanArgs& a) {
    if (!tape::scan_available()) fail("", tape::Errc::io, std::string(tape::scan_unavailable_message()));
    check_outputs({{"-o", a.output}, {"--report", a.report}, {"--debug-svg", a.debug_svg}});
    for (const auto& image : a.images) note_input(image);  // no output may be written over a picture read
    for (const auto* path : {&a.output, &a.report}) refuse_existing(*path, a.force);
    if (a.images.size() == 1) refuse_existing(a.debug_svg, a.force);
    const tape::ImageFormat& out_format = output_format(a.format, a.output);
    refuse_binary_terminal(a.output, out_format.binary, a.force);
    tape::ScanOptions o{.tracks = a.tracks, .dpi_hint = a.dpi, .start = *tape::parse_tape_start(a.start)};
    tape::ScanResult r;
    try {
        r = tape::scan_images(a.images, o);
    } catch (const tape::Error& e) {
        fail("", e);  // the message names the picture
    }
    // The read first: it is what the run is for, and it is written even when some frames are doubtful.
    write_output(a.output, out_format.write(r.frames, tape::ImageWriteOptions{}), out_format.binary, a.force);
    say_scan_findings(r, display_name(a.output));
    write_report(a, a.json ? scan_report_json(r) : scan_report_text(r));
    if (!a.debug_svg.empty()) write_debug_pictures(r, a.debug_svg, a.force);
    if (!r.complete()) throw Exit{bad_data};
}

}  // namespace

void add_scan(CLI::App& app) {
    auto a = std::make_shared<ScanArgs>();
    auto* sub = app.add_subcommand(
        "scan",
        "Read pictures of a tape (flatbed scans, photos of a tape lying flat) as a tape image, with the "
        "doubtful frames named");
    sub->add_option("images", a->images,
                    "PNG, JPEG or TIFF pictures of one tape, in any order: overlapping pictures are joined")
        ->required();
    sub->add_option("-o,--output", a->output, "The read (format by extension, or --format); - for stdout")->required();
    sub->add_option("--report", a->report, "Write the report to FILE instead of standard output");
    sub->add_flag("--json", a->json, "The report as JSON (schema tape-scan/1, in tape(1))");
    sub->add_option(
        "--debug-svg", a->debug_svg,
        "Also draw what was found over each picture, as SVG (several pictures: FILE-1.svg, FILE-2.svg, ...)");
    sub->add_option("--tracks", a->tracks, "Tracks of the tape: 8, or 5 (telegraph tape)")
        ->check(whole_number(5, 8))  // a whole number first, said as such; then one of the two
        ->check(CLI::IsMember({5, 8}))
        ->capture_default_str();
    sub->add_option("--dpi", a->dpi, "The resolution, if known: only checked against the 2.54 mm between feed holes")
        ->check(real_number(10, 20000));
    sub->add_option("--start", a->start,
                    "Where the tape's start is in the first picture, when the tape cannot tell: auto, left, right, "
                    "top, bottom")
        ->check(CLI::IsMember({"auto", "left", "right", "top", "bottom"}))
        ->capture_default_str();
    sub->add_option("--format,-f", a->format, "Image format of the read: " + format_choices(true))
        ->check(format_check(true));
    sub->add_flag("--force", a->force, "Replace an existing output, report or picture");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
