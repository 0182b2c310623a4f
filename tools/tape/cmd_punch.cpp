// tape punch: the generic punch: a tape image's frames out to any device.

#include <algorithm>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/run.hpp"
#include "cli/signals.hpp"
#include "commands.hpp"
#include "device_options.hpp"
#include "send.hpp"
#include "tape/limits.hpp"

namespace cli {
namespace {

struct PunchArgs {
    std::string input, device, format, verify;
    double rate = 0, verify_timeout = 5;
    bool force = false, progress = false;
};

// Reads the punched tape back from the reader and names every frame that differs (exit 1 if any).
void verify(const PunchArgs& a, const std::vector<tape::Frame>& punched) {
    install_interrupt_handler();
    auto reader = open_device_or_fail(a.verify, tape::DeviceUse::read);
    std::vector<tape::Frame> read;
    tape::ReceiveOptions o;
    o.idle_timeout = std::chrono::milliseconds(static_cast<long long>(a.verify_timeout * 1000));
    o.stop = &interrupted();
    o.sink = [&](std::span<const tape::Frame> frames) {
        if (read.size() + frames.size() > tape::max_tape_frames)
            fail(a.verify, tape::Errc::io, "the read-back " + std::string(tape::too_long_text));
        read.insert(read.end(), frames.begin(), frames.end());
    };
    try {
        tape::receive_frames(*reader, o);
    } catch (const tape::Error& e) {
        fail("", e);
    }
    if (reader->backwards()) std::reverse(read.begin(), read.end());  // the tape read back from its end
    std::uint64_t differ = 0, shown = 0;
    std::size_t common = std::min(read.size(), punched.size());
    for (std::size_t i = 0; i < common; ++i) {
        if (read[i] == punched[i]) continue;
        ++differ;
        if (globals().max_errors && shown >= globals().max_errors) continue;
        ++shown;
        say(a.verify, "frame " + std::to_string(i + 1) + ": punched " + tape::frame_hex(punched[i]) + ", read back " +
                          tape::frame_hex(read[i]));
    }
    if (differ > shown) say_unlisted(a.verify, differ - shown, "differing frame(s)");
    if (read.size() != punched.size())
        say(a.verify, "frame " + std::to_string(common + 1) + ": read back " + std::to_string(read.size()) +
                          " frames, punched " + std::to_string(punched.size()));
    if (differ || read.size() != punched.size()) throw Exit{bad_data};
    if (globals().verbosity > 0) say(a.verify, "verified " + std::to_string(read.size()) + " frames");
}

void run(const PunchArgs& a) {
    SendInput in = open_image_to_send(a.input, a.format);  // read as it is punched
    if (!a.verify.empty()) in.keep();                      // to compare the read-back with
    tape::SendOptions o;
    o.rate = a.rate;
    deliver_or_fail(Delivery{.device = a.device,
                             .use = tape::DeviceUse::write,
                             .format = a.format,
                             .force = a.force,
                             .progress = a.progress},
                    in, o, "punched");
    if (!a.verify.empty()) verify(a, in.kept());
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
    sub->add_option("--verify", a->verify,
                    "Then read the punched tape back from this device (a reader) and name every frame that differs "
                    "(exit 1)");
    sub->add_option("--verify-timeout", a->verify_timeout, "End the read-back after SECONDS without a frame")
        ->check(real_number(0.1, max_timeout_s))
        ->capture_default_str();
    sub->add_flag("--force", a->force, "Replace an existing file: device");
    sub->add_flag("--progress", a->progress, "Show progress even when stderr is not a terminal");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
