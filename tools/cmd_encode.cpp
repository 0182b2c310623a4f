// tape encode: a text program -> a tape image.
#include "cli_common.hpp"
#include "commands.hpp"
#include "tape/encode.hpp"
#include "tape/file_io.hpp"

namespace cli {
namespace {

struct EncodeArgs {
    std::string input = "-", output = "-", format;
    CodeChoice choice;
    std::size_t leader = tape::default_leader, trailer = tape::default_trailer;
    bool force = false;
};

void run(const EncodeArgs& a) {
    std::string in_name = display_name(a.input);
    std::vector<std::uint8_t> bytes;
    try {
        bytes = tape::read_file(a.input);
    } catch (const tape::Error& e) {
        fail(in_name, e);
    }
    tape::EncodeOptions o;
    o.code = *tape::parse_code(a.choice.code);
    o.parity = *tape::parse_parity(a.choice.parity);
    o.charset = *tape::parse_charset(a.choice.charset);
    o.leader = a.leader;
    o.trailer = a.trailer;
    o.eia_table = globals().table();
    if (o.code == tape::Code::eia && o.parity != tape::Parity::even)
        fail(in_name, tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    std::vector<tape::Frame> frames;
    try {
        frames = tape::encode(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), o);
    } catch (const tape::Error& e) {
        fail(in_name, e);
    }
    const tape::ImageFormat* format = a.format.empty() ? nullptr : tape::find_image_format(a.format);
    if (!format && a.output != "-") format = tape::image_format_for_path(a.output);
    if (!format) format = tape::find_image_format("raw");
    tape::FrameCode code = tape::FrameCode::make(o.code, o.parity, o.eia_table);
    tape::ImageWriteOptions wo{&code};
    write_output(a.output, format->write(frames, wo), format->binary, a.force);
    if (globals().verbosity > 0) say(in_name, std::to_string(frames.size()) + " frames written as " + std::string(format->id));
}

}  // namespace

void add_encode(CLI::App& app) {
    auto a = std::make_shared<EncodeArgs>();
    auto* sub = app.add_subcommand("encode", "Punch a text program into a tape image (each line a block)");
    sub->add_option("input", a->input, "Text program; - or nothing for stdin");
    sub->add_option("-o,--output", a->output, "Tape image to write; - for stdout (raw refuses a terminal)");
    add_code_options(sub, a->choice, false);
    sub->add_option("--leader", a->leader, "Blank frames before the program (10 frames = 25.4 mm)")->capture_default_str();
    sub->add_option("--trailer", a->trailer, "Blank frames after the program")->capture_default_str();
    sub->add_option("--format,-f", a->format, "Image format: raw or holes (default: by extension of OUT, else raw)")
        ->check(CLI::IsMember({"raw", "holes"}));
    sub->add_flag("--force", a->force, "Replace an existing OUT; write raw to a terminal");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
