// tape receive: take a program a controller punches out over a line, frames kept as they arrive.
#include "cli/globals.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "device_options.hpp"
#include "receive_image.hpp"

namespace cli {
namespace {

struct ReceiveArgs {
    std::string device, output, format, code = "iso", parity = "even";
    double timeout = 10;
    bool force = false, keep_flow_codes = false, progress = false, whole = false;
};

void run(const ReceiveArgs& a) {
    tape::ReceiveOptions o;
    o.idle_timeout = std::chrono::milliseconds(static_cast<long long>(a.timeout * 1000));  // at most a day
    o.until_program_end = !a.whole;
    o.code = *tape::parse_code(a.code);
    o.parity = *tape::parse_parity(a.parity);
    if (o.code == tape::Code::eia && o.parity != tape::Parity::even)  // as decode says it
        fail("", tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    o.eia_table = globals().table();
    o.drop_flow_codes = !a.keep_flow_codes;
    if (receive_into_image(a.device, a.output, a.format, a.force, o, a.progress, "received") ==
        tape::ReceiveResult::End::stopped)
        throw Exit{interrupted_status};
}

}  // namespace

void add_receive(CLI::App& app) {
    auto a = std::make_shared<ReceiveArgs>();
    auto* sub = app.add_subcommand("receive", "Take a program a controller punches out over a line into a tape image");
    sub->add_option("device", a->device, "Device string, e.g. serial:/dev/ttyUSB0?baud=9600")->required();
    sub->add_option("-o,--output", a->output, "Tape image to write (frames appended as they arrive)")->required();
    sub->add_option("--timeout", a->timeout, "End after SECONDS without a frame (0: never)")
        ->check(real_number(0, max_timeout_s))
        ->capture_default_str();
    sub->add_option("--code,-c", a->code, "Code of the program, to see its end: iso or eia")
        ->check(CLI::IsMember({"iso", "eia"}))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity,
                    "Track 8 rule of an ISO program: even (NC tapes), odd, mark (DEC-era ASCII), space, none; "
                    "on a bits=7 line track 8 is punched back by it")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}))
        ->capture_default_str();
    sub->add_flag("--whole", a->whole, "Do not end at the '%' after M02/M30: keep receiving until time-out or hang-up");
    sub->add_flag("--keep-flow-codes", a->keep_flow_codes,
                  "Keep DC1-DC4 in the image (they are line control, dropped by default)");
    sub->add_option("--format,-f", a->format,
                    "Image format: " + format_choices(true) + " (default: by extension, else raw)")
        ->check(format_check(true));
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    sub->add_flag("--progress", a->progress, "Show progress even when stderr is not a terminal");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
