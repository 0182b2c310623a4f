// tape render: a tape image drawn to scale as SVG, to look at or print.
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "tape/detect.hpp"
#include "tape/label.hpp"
#include "tape/render.hpp"

namespace cli {
namespace {

struct RenderArgs {
    std::string input = "-", output = "-", format, code = "auto", parity = "even";
    std::uint64_t from = 1, to = 0;
    double strip_mm = 254;
    bool mirror = false, force = false;
};

void run(const RenderArgs& a) {
    TapeInput in = read_tape(a.input, a.format);
    std::string name = display_name(a.input);
    std::optional<tape::FrameCode> code;
    auto label = tape::find_label(in.frames);
    if (a.code == "iso" || a.code == "eia") {
        code = tape::FrameCode::make(*tape::parse_code(a.code), *tape::parse_parity(a.parity), globals().table());
    } else if (a.code == "auto") {
        // The code is told from the tape without its leader label, as decoding tells it.
        std::vector<tape::Frame> scratch;
        auto d = tape::detect_code(tape::without_label(in.frames, 0, label, scratch), globals().table());
        if (d.code)
            code = tape::FrameCode::make(*d.code, *d.code == tape::Code::eia ? tape::Parity::odd : tape::Parity::even,
                                         globals().table());
        if (globals().verbosity > 0)
            say(name, d.code ? "drawn as " + std::string(tape::code_name(*d.code)) + ": " + d.reason
                             : "no characters drawn: " + d.reason);
    }
    if (code && code->code() == tape::Code::eia && a.parity != "even")
        fail(name, tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    tape::RenderOptions o;
    o.code = code ? &*code : nullptr;
    o.from = a.from;
    o.to = a.to;
    o.strip_mm = a.strip_mm;
    o.mirror = a.mirror;
    if (label) {
        o.label_first = label->first + 1;
        o.label_frames = label->frames;
    }
    std::string svg;
    try {
        svg = tape::render_svg(in.frames, o);
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    write_output(a.output, svg, false, a.force);
}

}  // namespace

void add_render(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    auto* sub = app.add_subcommand("render", "Draw a tape image to scale as SVG: holes, frame numbers, characters");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    sub->add_option("-o,--output", a->output, "SVG file to write; - for stdout");
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
    sub->add_option("--strip-length", a->strip_mm, "Length of tape in one strip, in mm; longer tapes wrap")
        ->check(real_number(2.54, 100000.0))
        ->capture_default_str();
    sub->add_flag("--mirror", a->mirror, "Seen from the other side: track 1 on top");
    sub->add_option("--format,-f", a->format, "Image format of IN: " + format_choices(false))
        ->check(format_check(false));
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
