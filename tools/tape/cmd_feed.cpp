// tape feed: send a program to a controller over a line, as a tape reader would (DNC, drip feed).
#include "cli/inputs.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "commands.hpp"
#include "device_options.hpp"
#include "restart_frames.hpp"
#include "send.hpp"

namespace cli {
namespace {

struct FeedArgs {
    std::string input, device;
    FeedProfile profile;
    double rate = 0, delay_ms = 0;
    bool wait_xon = false, progress = false, force = false;
    double xon_timeout = 0;
    std::string flow, xon = "0x11", xoff = "0x13";
    std::string from_block;  // restart after a tool break
    bool show = false, lathe = false;
    std::string machine;
    bool parity_given = false;
};

// --machine: the profile's code, parity, dialect, serial line (baud, bits, stop bits, flow), DC1 wait, reader
// speed and lathe where the command line and the device string gave none.
void machine_line(FeedArgs& a) {
    auto m = machine_or_fail(a.machine);
    if (!m) return;
    const tape::MachineLine& l = m->line;
    if (a.profile.choice.code == "auto" && l.code) a.profile.choice.code = std::string(tape::code_name(*l.code));
    if (!a.parity_given && l.parity && (a.profile.choice.code == "iso" || a.profile.choice.code == "auto"))
        a.profile.choice.parity = std::string(tape::parity_name(*l.parity));
    if (a.profile.dialect == "auto") a.profile.dialect = std::string(tape::dialect_name(m->dialect));
    a.device = tape::device_with_machine_line(a.device, l);
    if (l.dc_codes) a.wait_xon = true;
    if (m->kind == tape::MachineKind::lathe) a.lathe = true;  // a restart's approach: X clear, then Z
    if (a.rate == 0 && a.delay_ms == 0) a.rate = l.reader_frames_per_second;
}

void run(FeedArgs& a) {
    machine_line(a);
    // Every option is checked before the device is opened: a refusal leaves no file and sends nothing.
    tape::SendOptions o;
    o.rate = a.rate > 0 ? a.rate : (a.delay_ms > 0 ? 1000.0 / a.delay_ms : 0);
    if (a.flow == "xonxoff")
        o.flow = tape::Flow::xonxoff;
    else if (a.flow == "rtscts")
        o.flow = tape::Flow::rtscts;
    else if (a.flow == "none")
        o.flow = tape::Flow::none;
    o.wait_xon = a.wait_xon;
    o.xon_timeout = std::chrono::milliseconds(static_cast<long long>(a.xon_timeout * 1000));  // at most a day
    o.xon = parse_byte(a.xon, "--xon");
    o.xoff = parse_byte(a.xoff, "--xoff");
    if ((o.xon & 0x7F) == (o.xoff & 0x7F))
        fail("", tape::Errc::usage,
             "--xon '" + a.xon + "' and --xoff '" + a.xoff + "' are the same character (bit 8 is not compared)");
    if (a.show && a.from_block.empty()) fail("", tape::Errc::usage, "--show shows a restart: give --from-block");
    if (!a.show && a.device.empty()) fail("", tape::Errc::usage, "DEVICE is required (or --show with --from-block)");
    // A restart is made whole first (its modal state is rebuilt from the blocks before it); any other
    // program or tape is read as it is sent.
    std::optional<SendInput> restart;
    if (!a.from_block.empty()) {
        auto frames = restart_frames(a.input, a.profile, a.from_block, a.show, a.lathe);
        if (a.show) return;
        restart = frames_in_memory(std::move(frames), display_name(a.input));
    }
    SendInput frames = restart ? std::move(*restart) : open_frames_to_send(a.input, a.profile);
    deliver_or_fail(Delivery{.device = a.device,
                             .use = tape::DeviceUse::both,
                             .format = a.profile.format,
                             .force = a.force,
                             .progress = a.progress},
                    frames, o, "sent");
}

}  // namespace

void add_feed(CLI::App& app) {
    auto a = std::make_shared<FeedArgs>();
    auto* sub = app.add_subcommand("feed", "Send a program to a controller over a line, as a tape reader would (DNC)");
    sub->add_option("input", a->input, "Text program or tape image; - for stdin")->required();
    sub->add_option("device", a->device,
                    "Device string, e.g. serial:/dev/ttyUSB0?baud=9600&flow=xonxoff; file:PATH gets the image at once");
    add_feed_profile_options(sub, a->profile);
    auto* rate = sub->add_option("--rate", a->rate, "Frames per second (default: the line's speed)")
                     ->check(real_number(min_rate, max_rate));
    sub->add_option("--delay", a->delay_ms, "Milliseconds between characters (instead of --rate)")
        ->check(real_number(0, max_delay_ms))
        ->excludes(rate);
    sub->add_option("--flow", a->flow, "Override the device's flow control: xonxoff, rtscts or none")
        ->check(CLI::IsMember({"xonxoff", "rtscts", "none"}));
    add_machine_option(sub, a->machine,
                       "its code, parity, dialect, DC1 wait and reader speed where these options are not given, its "
                       "baud rate, data bits, stop bits and flow control where the serial: device string gives none");
    sub->add_flag("--wait-xon", a->wait_xon, "Send nothing before the controller's first DC1 (XON)");
    sub->add_option("--xon-timeout", a->xon_timeout,
                    "With --wait-xon: give up after SECONDS (default 0: wait until Ctrl-C)")
        ->check(real_number(0, max_timeout_s));
    sub->add_option("--xon", a->xon, "The resume character (default DC1, 0x11; bit 8 is not compared)")
        ->capture_default_str();
    sub->add_option("--xoff", a->xoff, "The pause character (default DC3, 0x13; bit 8 is not compared)")
        ->capture_default_str();
    sub->add_option("--from-block", a->from_block,
                    "Restart after a tool break: the program's start, the modal state at block N (G groups, F, S, "
                    "T, spindle and coolant) rebuilt as blocks, a safe approach to where N starts (retract, across, "
                    "down at the feed), then N to the end; refused, saying why, where it cannot be rebuilt safely")
        ->type_name("N");
    sub->add_flag("--lathe", a->lathe,
                  "With --from-block: the program is a lathe's (the approach goes X clear, then Z, then X)");
    sub->add_flag("--show", a->show, "With --from-block: print the restart's header on stdout, send nothing");
    sub->add_flag("--progress", a->progress, "Show progress even when stderr is not a terminal");
    sub->add_flag("--force", a->force, "Replace an existing file: device");
    sub->callback([a, sub] {
        a->parity_given = sub->count("--parity") > 0;
        run(*a);
    });
}

}  // namespace cli
