// tape emulate: act as a tape reader holding IMAGE toward a controller on DEVICE.
#include "cli_device.hpp"
#include "commands.hpp"

namespace cli {
namespace {

struct EmulateArgs {
    std::string input, device, format, code = "iso", flow, search = ":", rewind = "%";
    double rate = 1500;
    bool send_leader = false;
};

void run(const EmulateArgs& a) {
    TapeInput in = read_tape(a.input, a.format);
    install_interrupt_handler();
    auto line = open_device_or_fail(a.device, tape::DeviceUse::both);
    tape::EmulatorOptions o;
    o.rate = a.rate;
    o.skip_leader = !a.send_leader;
    o.code = *tape::parse_code(a.code);
    o.eia_table = globals().table();
    if (a.flow == "rtscts") o.flow = tape::Flow::rtscts;
    else if (a.flow == "xonxoff") o.flow = tape::Flow::xonxoff;
    o.search = parse_byte(a.search, "--search-char");
    o.rewind = parse_byte(a.rewind, "--rewind-char");
    o.stop = &interrupted();
    std::string name = display_name(in.name);
    o.log = [&name, quiet = globals().verbosity < 0](std::uint64_t frame, const std::string& what) {
        if (!quiet) say(name, "frame " + std::to_string(frame) + ": " + what);
    };
    if (a.rate <= 0) fail("", tape::Errc::usage, "--rate must be above 0");
    try {
        auto r = tape::emulate_reader(*line, in.frames, o);
        if (globals().verbosity > 0)
            say(name, std::to_string(r.frames_sent) + " frames sent, " + std::to_string(r.starts) + " start(s), " +
                          std::to_string(r.rewinds) + " rewind(s), " + std::to_string(r.searches) + " search(es)");
    } catch (const tape::Error& e) {
        fail("", e);
    }
}

}  // namespace

void add_emulate(CLI::App& app) {
    auto a = std::make_shared<EmulateArgs>();
    auto* sub = app.add_subcommand("emulate", "Act as a tape reader holding IMAGE toward a controller on DEVICE");
    sub->add_option("input", a->input, "Tape image (raw or holes)")->required();
    sub->add_option("device", a->device, "Device string, e.g. serial:/dev/ttyUSB0?baud=9600")->required();
    sub->add_option("--rate", a->rate, "Reader speed in frames per second (ФС-1501: 1500)")->capture_default_str();
    sub->add_option("--code,-c", a->code, "Code of the tape, to find '%', ':' and M02/M30: iso or eia")->check(CLI::IsMember({"iso", "eia"}))->capture_default_str();
    sub->add_option("--flow", a->flow, "rtscts: CTS starts and stops the reader instead of DC1/DC3")->check(CLI::IsMember({"xonxoff", "rtscts"}));
    sub->add_option("--search-char", a->search, "Request from the controller to search forward to the next main block (then digits: that block)")->capture_default_str();
    sub->add_option("--rewind-char", a->rewind, "Request from the controller to rewind to the '%' stop")->capture_default_str();
    sub->add_flag("--send-leader", a->send_leader, "Send the blank leader too instead of starting at the first punched frame");
    sub->add_option("--format,-f", a->format, "Image format of IN: raw or holes")->check(CLI::IsMember({"raw", "holes"}));
    sub->callback([a] { run(*a); });
}

}  // namespace cli
