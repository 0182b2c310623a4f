// tape punch: the generic punch: a tape image's frames out to any device.
#include "cli_device.hpp"
#include "cli_numbers.hpp"
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
    tape::SendOptions o;
    o.rate = a.rate;
    deliver_or_fail(Delivery{.device = a.device,
                             .use = tape::DeviceUse::write,
                             .format = a.format,
                             .force = a.force,
                             .progress = a.progress},
                    in.frames, o, "punched");
}

}  // namespace

void add_punch(CLI::App& app) {
    auto a = std::make_shared<PunchArgs>();
    auto* sub = app.add_subcommand("punch", "Punch a tape image on a device, frame for frame");
    sub->add_option("input", a->input, "Tape image; - for stdin")->required();
    sub->add_option(
           "device", a->device,
           "Device string: file:PATH (a new image, raw or holes by extension, written at once), serial:PATH?...")
        ->required();
    sub->add_option(
           "--rate", a->rate,
           "Frames per second (default: the line's speed; ПЛ-150 punches about 150); a file: device is written at once")
        ->check(real_number(min_rate, max_rate));
    sub->add_option("--format,-f", a->format,
                    "Image format of IN, and of a file: OUT: " + format_choices(false) + " (default: by extension)")
        ->check(format_check(false));
    sub->add_flag("--force", a->force, "Replace an existing file: device");
    sub->add_flag("--progress", a->progress, "Show progress even when stderr is not a terminal");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
