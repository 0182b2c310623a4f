// tape render: a tape image drawn to scale as SVG, to look at or print, or as a picture (PNG, JPEG,
// TIFF) at a true size for printing and for testing tape scan.
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "tape/detect.hpp"
#include "tape/file_io.hpp"
#include "tape/label.hpp"
#include "tape/picture.hpp"
#include "tape/render.hpp"
#include "tape/restore_doubts.hpp"
#include "tape/scan.hpp"

namespace cli {
namespace {

// No paper tape is longer: 10^8 frames are 254 km. An input that goes on (/dev/zero) is refused there.
constexpr std::uint64_t max_render_frames = 100'000'000;

struct RenderArgs {
    std::string input = "-", output = "-", format, code = "auto", parity = "even", effects;
    std::uint64_t from = 1, to = 0;
    double strip_mm = 254, dpi = 0;
    bool strip_given = false, mirror = false, force = false;
};

struct Drawn {
    std::vector<tape::Frame> frames;  // from the first up to --to (or the end)
    std::optional<tape::LeaderLabel> label;
};

// The frames read a chunk at a time, no further than the last drawn.
Drawn read_frames(const RenderArgs& a, const std::string& name) {
    tape::InputOptions o = input_options(CodeChoice{}, a.format, "image");
    o.detect_code = false;
    auto input = open_input(a.input, o);
    Drawn d;
    try {
        d.label = input->label();
        for (auto f = input->next_frames(); !f.empty(); f = input->next_frames()) {
            std::size_t take = a.to ? std::min<std::uint64_t>(f.size(), a.to - d.frames.size()) : f.size();
            d.frames.insert(d.frames.end(), f.begin(), f.begin() + static_cast<std::ptrdiff_t>(take));
            if (a.to && d.frames.size() >= a.to) break;
            if (d.frames.size() > max_render_frames)
                fail(name, tape::Errc::bad_image,
                     "more than 10^8 frames (254 km of tape): no tape is that long; give --to to draw a part");
        }
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    return d;
}

std::optional<tape::FrameCode> code_of(const RenderArgs& a, const Drawn& d, const std::string& name) {
    std::optional<tape::FrameCode> code;
    if (a.code == "iso" || a.code == "eia") {
        code = tape::FrameCode::make(*tape::parse_code(a.code), *tape::parse_parity(a.parity), globals().table());
    } else if (a.code == "auto") {
        // The code is told from the tape without its leader label, as decoding tells it.
        std::vector<tape::Frame> scratch;
        auto det = tape::detect_code(tape::without_label(d.frames, 0, d.label, scratch), globals().table());
        if (det.code)
            code = tape::FrameCode::make(
                *det.code, *det.code == tape::Code::eia ? tape::Parity::odd : tape::Parity::even, globals().table());
        if (globals().verbosity > 0)
            say(name, det.code ? "drawn as " + std::string(tape::code_name(*det.code)) + ": " + det.reason
                               : "no characters drawn: " + det.reason);
    }
    if (code && code->code() == tape::Code::eia && a.parity != "even")
        fail(name, tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    return code;
}

void write_svg(const RenderArgs& a, const Drawn& d, const tape::RenderOptions& o, const std::string& name) {
    std::unique_ptr<tape::OutputFile> out = open_output(a.output, a.force);
    try {
        tape::render_svg(d.frames, o, [&out](std::string_view piece) { out->write(piece); });
        out->commit();
    } catch (const tape::Error& e) {
        fail(e.code() == tape::Errc::usage ? name : display_name(a.output), e);
    }
}

void write_picture(const RenderArgs& a, const Drawn& d, std::string_view format, const std::string& name) {
    if (!tape::scan_available()) fail("", tape::Errc::io, std::string(tape::scan_unavailable_message()));
    refuse_binary_terminal(a.output, true, a.force);
    tape::RasterOptions r{.dpi = a.dpi ? a.dpi : 300, .strip_mm = a.strip_given ? a.strip_mm : 0, .mirror = a.mirror};
    tape::PictureEffects e;
    std::vector<std::uint8_t> bytes;
    try {
        tape::parse_picture_effects(a.effects, r, e);
        std::uint64_t last = a.to ? a.to : d.frames.size();
        if (a.from > last || last > d.frames.size())
            throw tape::Error(tape::Errc::usage, "frames " + std::to_string(a.from) + " to " + std::to_string(last) +
                                                     ": the tape has " + std::to_string(d.frames.size()) + " frames");
        auto drawn = std::span(d.frames).subspan(a.from - 1, last + 1 - a.from);
        tape::Picture p = tape::render_picture(drawn, r);
        tape::apply_effects(p, e, r.dpi);
        bytes = tape::encode_picture(p, format, 95);
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    write_output(a.output, std::string(bytes.begin(), bytes.end()), true, a.force);
}

void run(const RenderArgs& a) {
    std::string name = display_name(a.input);
    std::string_view picture = tape::picture_format_for_path(a.output);
    if (picture.empty() && (a.dpi > 0 || !a.effects.empty()))
        fail(a.output, tape::Errc::usage, "--dpi and --effects draw a picture: name the output .png, .jpg or .tif");
    Drawn d = read_frames(a, name);
    if (!picture.empty()) return write_picture(a, d, picture, name);
    auto code = code_of(a, d, name);
    tape::RenderOptions o;
    o.code = code ? &*code : nullptr;
    o.from = a.from;
    o.to = a.to;
    o.strip_mm = a.strip_mm;
    o.mirror = a.mirror;
    if (d.label) {
        o.label_first = d.label->first + 1;
        o.label_frames = d.label->frames;
    }
    // Frames a restoration left in doubt (its doubts file beside the image) in the doubt colour.
    if (a.input != "-")
        for (const auto& doubt : tape::doubts_beside(a.input))
            if (std::uint64_t at = std::max<std::uint64_t>(doubt.frame, 1); at <= d.frames.size())
                o.marks.push_back({at, tape::MarkKind::doubtful, doubt.message()});
    write_svg(a, d, o, name);
}

}  // namespace

void add_render(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    auto* sub = app.add_subcommand(
        "render",
        "Draw a tape image to scale: SVG with frame numbers and characters, or a picture (PNG, JPEG, TIFF) "
        "at its true size");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    sub->add_option("-o,--output", a->output,
                    "SVG file to write (- for stdout); a name ending .png, .jpg or .tif draws a picture");
    sub->add_option("--code,-c", a->code, "auto, iso, eia, or none (no characters, no parity marks)")
        ->check(CLI::IsMember({"auto", "iso", "eia", "none"}))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity, "Track 8 rule of an ISO tape: even, odd, mark, space or none")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}))
        ->capture_default_str();
    sub->add_option("--from", a->from, "First frame drawn (1-based)")
        ->check(whole_number(1, std::numeric_limits<std::uint32_t>::max()))
        ->capture_default_str();
    sub->add_option("--to", a->to, "Last frame drawn (default: the end)")
        ->check(whole_number(1, std::numeric_limits<std::uint32_t>::max()));
    sub->add_option("--strip-length", a->strip_mm,
                    "Length of tape in one strip, in mm; longer tapes wrap (a picture: one strip unless given)")
        ->check(real_number(2.54, 100000.0))
        ->each([a](const std::string&) { a->strip_given = true; })
        ->capture_default_str();
    sub->add_flag("--mirror", a->mirror, "Seen from the other side: track 1 on top");
    sub->add_option("--dpi", a->dpi,
                    "A picture's resolution in pixels per inch (default 300): printed at it, true size")
        ->check(real_number(10, 4800));
    sub->add_option("--effects", a->effects,
                    "A picture as a scanner or camera shows it: KEY=VALUE,... of skew (degrees), bow (mm), stains, "
                    "paper and backing (RRGGBB), light (0-0.9), dust, blur (px), noise (grey levels), jpeg "
                    "(quality), seed");
    sub->add_option("--format,-f", a->format, "Image format of IN: " + format_choices(false))
        ->check(format_check(false));
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
