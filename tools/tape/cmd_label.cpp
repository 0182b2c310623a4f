// tape label: a leader label alone — text as letters of holes, blank tape either side.
#include "cli/globals.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "tape/label.hpp"

namespace cli {
namespace {

struct LabelArgs {
    std::string text, output = "-", format, code = "iso", parity = "even";
    bool force = false;
};

void run(const LabelArgs& a) {
    tape::Code code = *tape::parse_code(a.code);
    tape::Parity parity = *tape::parse_parity(a.parity);
    if (code == tape::Code::eia && parity != tape::Parity::even)
        fail("label", tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    tape::FrameCode frame_code = tape::FrameCode::make(code, parity, globals().table());
    std::vector<tape::Frame> frames(tape::label_blank_around, tape::blank_frame);
    try {
        auto label = tape::label_frames(a.text, frame_code);
        frames.insert(frames.end(), label.begin(), label.end());
    } catch (const tape::Error& e) {
        fail("label", e);
    }
    frames.insert(frames.end(), tape::label_blank_around, tape::blank_frame);
    const tape::ImageFormat& format = output_format(a.format, a.output);
    write_output(a.output, image_text(format, frames, tape::ImageWriteOptions{&frame_code}, a.output), format.binary,
                 a.force);
}

}  // namespace

void add_label(CLI::App& app) {
    auto a = std::make_shared<LabelArgs>();
    auto* sub = app.add_subcommand(
        "label",
        "Punch a leader label alone: text as letters of holes, readable along the tape, 10 blank frames each side");
    sub->add_option("text", a->text, "Latin or Cyrillic capitals, digits, space, - . / (at most 80)")->required();
    sub->add_option("-o,--output", a->output, "Tape image to write; - for stdout (raw refuses a terminal)");
    sub->add_option("--code,-c", a->code, "iso or eia: the layout of the letters")
        ->check(CLI::IsMember({"iso", "eia"}))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity, "Track 8 of ISO frames: even, odd, mark, space or none")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}))
        ->capture_default_str();
    sub->add_option("--format,-f", a->format,
                    "Image format: " + format_choices(true) + " (default: by extension of OUT, else raw)")
        ->check(format_check(true));
    sub->add_flag("--force", a->force, "Replace an existing OUT; write raw to a terminal");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
