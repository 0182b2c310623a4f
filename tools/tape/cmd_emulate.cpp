// tape emulate: act as a tape reader holding IMAGE toward a controller on DEVICE.
#include <algorithm>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/signals.hpp"
#include "commands.hpp"
#include "device_options.hpp"
#include "tape/adapter.hpp"

namespace cli {
namespace {

struct EmulateArgs {
    std::string input, device, format, code = "iso", parity = "even", flow, search = ":", rewind = "%";
    double rate = 1500;
    bool send_leader = false;
    std::vector<std::string> serial_only;  ///< the serial line's options given
    std::string machine;
    bool code_given = false, parity_given = false;
};

// --machine: the profile's reader speed, code and parity where the command line gave none, its serial line
// (baud, bits, stop bits, flow) where the device string gave none.
void machine_line(EmulateArgs& a) {
    auto m = machine_or_fail(a.machine);
    if (!m) return;
    const tape::MachineLine& l = m->line;
    auto given = [&](const char* option) {
        return std::find(a.serial_only.begin(), a.serial_only.end(), option) != a.serial_only.end();
    };
    if (!given("--rate") && l.reader_frames_per_second > 0) a.rate = l.reader_frames_per_second;
    a.device = tape::device_with_machine_line(a.device, l);  // --flow, when given, still overrides the line's flow
    if (!a.code_given && l.code) a.code = std::string(tape::code_name(*l.code));
    if (!a.parity_given && l.parity && a.code == "iso") a.parity = std::string(tape::parity_name(*l.parity));
}

// Through a USB tape adapter wired to the control's reader input: the control's own lines start, stop,
// turn and rewind; the serial line's options have nothing to act on.
void run_on_adapter(const EmulateArgs& a, const std::vector<std::string>& given, tape::EmulatorOptions o) {
    for (const auto& option : given)
        fail("", tape::Errc::usage,
             option +
                 " is for a serial line; through an adapter the control's own lines start, stop and rewind the "
                 "reader, and its frame rate is the adapter's (tape adapter config --frame-rate)");
    TapeInput in = read_tape(a.input, a.format, TextProgram::refused);
    o.eia_table = globals().table();
    install_interrupt_handler();
    o.stop = &interrupted();
    std::string name = display_name(in.name);
    bool quiet = globals().verbosity < 0;
    o.log = [&name, quiet](std::uint64_t frame, const std::string& what) {
        if (!quiet) say(name, (frame ? "frame " + std::to_string(frame) + ": " : "") + what);
    };
    ProgressLine progress("emulating", false);
    try {
        auto r =
            tape::adapter_emulate(a.device, in.frames, o, [&progress](const tape::LineProgress& p) { progress(p); });
        if (globals().verbosity > 0)
            say(name, std::to_string(r.frames_sent) + " frames taken by the control, " + std::to_string(r.starts) +
                          " start(s), " + std::to_string(r.rewinds) + " rewind(s)");
    } catch (const tape::Error& e) {
        fail("", e);
    }
}

void run(const EmulateArgs& a) {
    // Every option is checked before the device is opened: a refusal leaves nothing behind.
    tape::EmulatorOptions o;
    o.rate = a.rate;
    o.skip_leader = !a.send_leader;
    o.code = *tape::parse_code(a.code);
    o.parity = *tape::parse_parity(a.parity);
    if (o.code == tape::Code::eia && o.parity != tape::Parity::even)  // as decode says it
        fail("", tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    if (a.flow == "rtscts")
        o.flow = tape::Flow::rtscts;
    else if (a.flow == "xonxoff")
        o.flow = tape::Flow::xonxoff;
    o.search = parse_byte(a.search, "--search-char");
    o.rewind = parse_byte(a.rewind, "--rewind-char");
    // Commands are compared without bit 8; DC1 and DC3 start and stop the reader.
    auto seven = [](std::uint8_t b) { return b & 0x7F; };
    if (seven(o.search) == seven(o.rewind))
        fail("", tape::Errc::usage, "--search-char and --rewind-char must be different characters (bit 8 aside)");
    for (std::uint8_t b : {o.search, o.rewind})
        if (seven(b) == tape::dc1 || seven(b) == tape::dc3)
            fail("", tape::Errc::usage,
                 "--search-char and --rewind-char cannot be DC1 or DC3: those start and stop the reader");
    if (tape::is_adapter_device(a.device)) return run_on_adapter(a, a.serial_only, o);
    TapeInput in = read_tape(a.input, a.format, TextProgram::refused);
    o.eia_table = globals().table();
    install_interrupt_handler();
    auto line = open_device_or_fail(a.device, tape::DeviceUse::both);
    o.stop = &interrupted();
    std::string name = display_name(in.name);
    o.log = [&name, quiet = globals().verbosity < 0](std::uint64_t frame, const std::string& what) {
        if (!quiet) say(name, "frame " + std::to_string(frame) + ": " + what);
    };
    try {
        // Ctrl-C is the normal end of a reader's run (exit 0); a hang-up is a device failure (exit 3).
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
    sub->add_option("input", a->input, "Tape image")->required();
    sub->add_option("device", a->device,
                    "Device string, e.g. serial:/dev/ttyUSB0?baud=9600, or a USB tape adapter wired to the control's "
                    "reader input: adapter:/dev/ttyACM0, usb:1209:0001, hid:1209:0001")
        ->required();
    add_machine_option(sub, a->machine,
                       "its reader speed, code and parity where these options are not given, its baud rate, data "
                       "bits, stop bits and flow control where the serial: device string gives none");
    sub->add_option("--rate", a->rate, "Reader speed in frames per second (ФС-1501: 1500)")
        ->check(real_number(min_rate, max_rate))
        ->capture_default_str();
    sub->add_option("--code,-c", a->code, "Code of the tape, to find '%', ':' and M02/M30: iso or eia")
        ->check(CLI::IsMember({"iso", "eia"}))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity,
                    "Track 8 rule of an ISO tape: even (NC tapes), odd, mark (DEC-era ASCII), space, none")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}))
        ->capture_default_str();
    sub->add_option("--flow", a->flow, "rtscts: CTS starts and stops the reader instead of DC1/DC3")
        ->check(CLI::IsMember({"xonxoff", "rtscts"}));
    sub->add_option("--search-char", a->search,
                    "Request from the controller to search forward to the next main block (then digits: that block)")
        ->capture_default_str();
    sub->add_option("--rewind-char", a->rewind, "Request from the controller to rewind to the '%' stop")
        ->capture_default_str();
    sub->add_flag("--send-leader", a->send_leader,
                  "Send the blank leader too instead of starting at the first punched frame");
    sub->add_option("--format,-f", a->format, "Image format of IN: " + format_choices(false))
        ->check(format_check(false));
    sub->callback([a, sub] {
        for (const char* option : {"--rate", "--flow", "--search-char", "--rewind-char"})
            if (sub->count(option)) a->serial_only.push_back(option);
        a->code_given = sub->count("--code") > 0;
        a->parity_given = sub->count("--parity") > 0;
        machine_line(*a);
        run(*a);
    });
}

}  // namespace cli
