// tape read: the generic reader: frames from any device into a tape image, nothing lost.
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "commands.hpp"
#include "device_options.hpp"
#include "receive_image.hpp"

namespace cli {

namespace {

struct ReadArgs {
    std::string device, output, format;
    double timeout = 5;
    bool force = false, progress = false;
};

}  // namespace

void add_read(CLI::App& app) {
    auto a = std::make_shared<ReadArgs>();
    auto* sub = app.add_subcommand(
        "read",
        "Read a tape from a device into an image; ends at the end of the tape, a quiet line, a hang-up or Ctrl-C");
    sub->add_option("device", a->device, "Device string: file:PATH, serial:PATH?...")->required();
    sub->add_option("-o,--output", a->output,
                    "Tape image to write (frames appended as they arrive, flushed every second)")
        ->required();
    sub->add_option("--timeout", a->timeout, "End after SECONDS without a frame (0: never)")
        ->check(real_number(0, max_timeout_s))
        ->capture_default_str();
    sub->add_option("--format,-f", a->format,
                    "Image format: " + format_choices(true) + " (default: by extension, else raw)")
        ->check(format_check(true));
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    sub->add_flag("--progress", a->progress, "Show progress even when stderr is not a terminal");
    sub->callback([a] {
        tape::ReceiveOptions o;
        o.idle_timeout = std::chrono::milliseconds(static_cast<long long>(a->timeout * 1000));  // at most a day
        // The user stopping a reader (Ctrl-C, SIGTERM) is its normal end: exit 0, every frame kept.
        receive_into_image(a->device, a->output, a->format, a->force, o, a->progress, "read");
    });
}

}  // namespace cli
