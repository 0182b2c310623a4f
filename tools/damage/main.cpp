// tape-damage: a damaged read of a tape image, made from a seed, for testing and benchmarking restoration.
#include <sys/stat.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/json.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "cli/signals.hpp"
#include "tape/code.hpp"
#include "tape/damage.hpp"
#include "tape/detect.hpp"

namespace {

using cli::fail;

struct DamageArgs {
    std::string input, output, format, log;
    std::uint64_t seed = 0;
    double damage = 0, flips = 0, drops = 0, doubles = 0, bursts = 0;
    std::size_t burst_length = 4, torn = 0, start_late = 0, stop_early = 0;
    long leader = 0;
    bool force = false;
    // Rates given one by one replace their share of --damage.
    CLI::Option *flips_given = nullptr, *drops_given = nullptr, *doubles_given = nullptr, *bursts_given = nullptr;
};

tape::DamageOptions damage_options(const DamageArgs& a) {
    tape::DamageOptions o = tape::mixed_damage(a.damage, a.seed, a.burst_length);
    if (a.flips_given->count() > 0) o.flips = a.flips;
    if (a.drops_given->count() > 0) o.drops = a.drops;
    if (a.doubles_given->count() > 0) o.doubles = a.doubles;
    if (a.bursts_given->count() > 0) o.bursts = a.bursts;
    o.torn = a.torn;
    o.leader = a.leader;
    o.start_late = a.start_late;
    o.stop_early = a.stop_early;
    return o;
}

// A holes picture names each frame's character in the code the undamaged tape reads in, so that the damage
// stands out against it (a frame failing that code's parity is marked).
std::string image_text(const tape::ImageFormat& format, std::span<const tape::Frame> original,
                       std::span<const tape::Frame> read) {
    std::optional<tape::FrameCode> code;
    if (auto detected = tape::detect_code(original, cli::globals().table()).code)
        code = tape::FrameCode::make(*detected, tape::Parity::even, cli::globals().table());
    return format.write(read, tape::ImageWriteOptions{code ? &*code : nullptr});
}

// One JSON object a line; frames numbered from 1, as everywhere in the CLI.
std::string log_lines(const tape::DamageLog& log) {
    std::string out;
    for (const tape::DamageEvent& e : log.events) {
        nlohmann::ordered_json j;
        j["kind"] = tape::damage_kind_name(e.kind);
        j["frame"] = e.original + 1;
        j["read_frame"] = e.read + 1;
        j["frames"] = e.frames;
        if (e.kind == tape::DamageKind::flip) j["track"] = e.track;
        out += j.dump() + "\n";
    }
    return out;
}

void run(const DamageArgs& a) {
    if (a.output == "-" && a.log == "-") fail("", tape::Errc::usage, "-o and --log cannot both be standard output");
    const tape::ImageFormat& format = cli::output_format(a.format, a.output);
    tape::DamageOptions options = damage_options(a);
    try {
        tape::check_damage_options(options);
    } catch (const tape::Error& e) {
        fail("", e);
    }
    cli::check_outputs({{"-o", a.output}, {"--log", a.log}});
    cli::refuse_existing(a.output, a.force);
    cli::refuse_existing(a.log, a.force);
    cli::TapeInput in = cli::read_tape(a.input, a.format);
    options.tracks = in.format->tracks;
    tape::DamageLog log;
    std::string image;
    try {
        std::vector<tape::Frame> read = tape::damage(in.frames, options, &log);
        image = image_text(format, in.frames, read);
    } catch (const tape::Error& e) {
        fail(cli::display_name(a.input), e);
    }
    cli::write_output(a.output, image, format.binary, a.force);
    if (!a.log.empty()) cli::write_output(a.log, log_lines(log), false, a.force);
}

void add_options(CLI::App& app, DamageArgs& a) {
    using cli::real_number;
    using cli::whole_number;
    constexpr std::uint64_t most_frames = 1'000'000'000;  // far beyond any tape, well inside memory
    app.add_option("image", a.input,
                   "Tape image to damage (any format: by --format, extension or content); - for stdin")
        ->required();
    app.add_option("-o,--output", a.output,
                   "The damaged read, in the format of its extension (or --format; raw otherwise); - for stdout")
        ->required();
    app.add_option("--seed", a.seed, "Seed: the same tape, options and seed give the same damage everywhere")
        ->required()
        ->check(whole_number(0, std::numeric_limits<std::uint64_t>::max()));
    app.add_option("--damage", a.damage,
                   "About this fraction of frames damaged, spread evenly over flips, drops, doubles and bursts")
        ->check(real_number(0, 1));
    a.flips_given = app.add_option("--flips", a.flips, "Chance per frame that one hole reads the other way")
                        ->check(real_number(0, 1));
    a.drops_given =
        app.add_option("--drops", a.drops, "Chance per frame that it is not read")->check(real_number(0, 1));
    a.doubles_given =
        app.add_option("--doubles", a.doubles, "Chance per frame that it is read twice")->check(real_number(0, 1));
    a.bursts_given = app.add_option("--bursts", a.bursts,
                                    "Chance per frame that a stain or splice starts, garbling --burst-length frames")
                         ->check(real_number(0, 1));
    app.add_option("--burst-length", a.burst_length, "Frames a burst garbles")
        ->check(whole_number(1, most_frames))
        ->capture_default_str();
    app.add_option("--torn", a.torn, "Frames torn out in one piece at a random place inside the data")
        ->check(whole_number(0, most_frames));
    app.add_option("--leader", a.leader, "Blank frames added (+N) or removed (-N, no more than there are) at the start")
        ->check(
            cli::signed_whole_number(-static_cast<std::int64_t>(most_frames), static_cast<std::int64_t>(most_frames)));
    app.add_option("--start-late", a.start_late, "Frames not read at the start")->check(whole_number(0, most_frames));
    app.add_option("--stop-early", a.stop_early, "Frames not read at the end")->check(whole_number(0, most_frames));
    app.add_option("--format,-f", a.format,
                   "Image format of IMAGE and of OUT: " + cli::format_choices(false) + " (default: by extension)")
        ->check(cli::format_check(false));
    app.add_flag("--force", a.force, "Replace an existing OUT or log");
    app.add_option("--log", a.log, "Write what was damaged, one JSON object a line, to FILE; - for stdout");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "tape-damage: a damaged read of a tape image, made from a seed, for testing and benchmarking the "
        "restoration of archived tapes.\n"
        "Applied in this order: --torn, --leader, --start-late/--stop-early, then frame by frame one of burst, "
        "drop, flip or double at most (their rates may add up to 1 at most).",
        "tape-damage"};
    app.set_version_flag("--version", std::string("tape-damage ") + TAPE_VERSION);
    app.footer(
        "Exit status: 0 ok, 1 bad data in the input, 2 usage error, 3 I/O failure.\n"
        "See tape-damage(1), tape-image(5).");
    cli::globals().program = "tape-damage";
    DamageArgs a;
    add_options(app, a);
    app.callback([&a] { run(a); });
    cli::install_output_cleanup();
    return cli::parse_and_run(app, argc, argv);
}
