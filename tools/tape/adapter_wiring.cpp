#include "adapter_wiring.hpp"

#include "cli/numbers.hpp"

namespace cli {
namespace {

constexpr const char* group = "Emulate role: the adapter as the control's tape reader (sent when any is given)";

// The options of the group, for finish_wiring to tell whether one was given.
const char* const wiring_options[] = {"--data-pins",    "--strobe-pin", "--run-pin",        "--reverse-pin",
                                      "--rewind-pin",   "--out-invert", "--out-strobe-low", "--run-low",
                                      "--reverse-low",  "--rewind-low", "--braking",        "--frame-rate",
                                      "--strobe-width", "--setup",      "--hold",           "--start-delay"};

}  // namespace

void add_wiring_options(CLI::App& cfg, const std::shared_ptr<WiringArgs>& a) {
    tape::AdapterWiring& w = a->wiring;
    auto pin = whole_number(0, 63);
    cfg.add_option("--data-pins", w.data_pins, "The board's pins (GPIO numbers) driving tracks 1 to N, comma-separated")
        ->delimiter(',')
        ->check(pin)
        ->group(group);
    cfg.add_option("--strobe-pin", w.strobe_pin, "Pin of the sprocket strobe toward the control")
        ->check(pin)
        ->capture_default_str()
        ->group(group);
    cfg.add_option("--run-pin", w.run_pin, "Pin of the control's start/stop line")
        ->check(pin)
        ->capture_default_str()
        ->group(group);
    cfg.add_option("--reverse-pin", w.reverse_pin, "Pin of the control's direction line, where it has one")
        ->check(pin)
        ->group(group);
    cfg.add_option("--rewind-pin", w.rewind_pin, "Pin of the control's rewind line, where it has one")
        ->check(pin)
        ->group(group);
    cfg.add_option("--out-invert", w.data_invert, "Data lines driven low for a hole: a mask, bit n for track n+1")
        ->check(whole_number(0, 255))
        ->group(group);
    cfg.add_flag("--out-strobe-low", w.strobe_low, "The strobe toward the control is active low")->group(group);
    cfg.add_flag("--run-low", w.run_low, "The control's start/stop line is active low (low: run)")->group(group);
    cfg.add_flag("--reverse-low", w.reverse_low, "The control's direction line is active low")->group(group);
    cfg.add_flag("--rewind-low", w.rewind_low, "The control's rewind line is active low")->group(group);
    cfg.add_option("--braking", w.braking, "Frames the control may still see after its stop (a ФС-1501: 1)")
        ->check(whole_number(0, 2))
        ->capture_default_str()
        ->group(group);
    cfg.add_option("--frame-rate", w.rate, "Frames per second toward the control (ФС-1501: 1500)")
        ->check(whole_number(1, 4000))
        ->capture_default_str()
        ->group(group);
    cfg.add_option("--strobe-width", w.strobe_us, "Microseconds the strobe is held")
        ->check(whole_number(1, 65535))
        ->capture_default_str()
        ->group(group);
    cfg.add_option("--setup", w.setup_us, "Microseconds the data stand on the lines before the strobe")
        ->check(whole_number(0, 65535))
        ->capture_default_str()
        ->group(group);
    cfg.add_option("--hold", w.hold_us, "Microseconds the data stay after the strobe")
        ->check(whole_number(0, 65535))
        ->capture_default_str()
        ->group(group);
    cfg.add_option("--start-delay", w.start_delay_us, "Microseconds from the control's start to the first frame")
        ->check(whole_number(0, 65535))
        ->capture_default_str()
        ->group(group);
}

void finish_wiring(CLI::App& cfg, WiringArgs& a, unsigned tracks) {
    for (const char* option : wiring_options) a.given = a.given || cfg.count(option) > 0;
    a.wiring.tracks = tracks;
    // The default pins: tracks 1 to N on pins 0 to N-1.
    if (!cfg.count("--data-pins")) a.wiring.data_pins.resize(tracks);
}

std::string wiring_text(const tape::AdapterWiring& w) {
    auto level = [](bool low) { return std::string(low ? "active low" : "active high"); };
    auto pin = [](const std::optional<unsigned>& p) { return p ? "pin " + std::to_string(*p) : std::string("none"); };
    std::string pins;
    for (unsigned p : w.data_pins) pins += (pins.empty() ? "" : ",") + std::to_string(p);
    char invert[8];
    std::snprintf(invert, sizeof invert, "0x%02X", w.data_invert);
    std::string out;
    out += "emulate data\tpins " + pins + ", inverted " + invert + "\n";
    out += "emulate strobe\tpin " + std::to_string(w.strobe_pin) + ", " + level(w.strobe_low) + ", " +
           std::to_string(w.strobe_us) + " us, data " + std::to_string(w.setup_us) + " us before and " +
           std::to_string(w.hold_us) + " us after\n";
    out += "emulate start/stop\tpin " + std::to_string(w.run_pin) + ", " + level(w.run_low) + "; braking " +
           std::to_string(w.braking) + " frame(s); first frame " + std::to_string(w.start_delay_us) +
           " us after a start\n";
    out += "emulate direction\t" + pin(w.reverse_pin) + (w.reverse_pin ? ", " + level(w.reverse_low) : "") + "\n";
    out += "emulate rewind\t" + pin(w.rewind_pin) + (w.rewind_pin ? ", " + level(w.rewind_low) : "") + "\n";
    out += "emulate rate\t" + std::to_string(w.rate) + " frames/s\n";
    return out;
}

}  // namespace cli
