// tape punch: the generic punch: a tape image's frames out to any device.
#include "cli_device.hpp"
#include "commands.hpp"

namespace cli {
namespace {

struct PunchArgs {
    std::string input, device, format;
    double rate = 0;
    bool force = false, progress = false;
};

void run(const PunchArgs& a) {
    TapeInput in = read_tape(a.input, a.format);
    install_interrupt_handler();
    auto line = open_device_or_fail(a.device, tape::DeviceUse::write, a.force);
    tape::SendOptions o;
    o.rate = a.rate;
    send_or_fail(*line, in.frames, o, "punched", a.progress);
}

}  // namespace

void add_punch(CLI::App& app) {
    auto a = std::make_shared<PunchArgs>();
    auto* sub = app.add_subcommand("punch", "Punch a tape image on a device, frame for frame");
    sub->add_option("input", a->input, "Tape image; - for stdin")->required();
    sub->add_option("device", a->device, "Device string: file:PATH (a new raw image), serial:PATH?...")->required();
    sub->add_option("--rate", a->rate, "Frames per second (default: the line's speed; files unpaced; ПЛ-150 punches about 150)");
    sub->add_option("--format,-f", a->format, "Image format of IN: raw or holes")->check(CLI::IsMember({"raw", "holes"}));
    sub->add_flag("--force", a->force, "Replace an existing file: device");
    sub->add_flag("--progress", a->progress, "Show progress even when stderr is not a terminal");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
