#include "cli_device.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "cli_numbers.hpp"
#include "tape/detect.hpp"
#include "tape/feed.hpp"
#include "tape/file_io.hpp"

namespace cli {

std::unique_ptr<tape::Transport> open_device_or_fail(const std::string& device, tape::DeviceUse use, bool replace) {
    try {
        return tape::open_device(device, use, replace);
    } catch (const tape::Error& e) {
        fail("", e);  // device errors name the device themselves
    }
}

ProgressLine::ProgressLine(std::string verb, bool force)
    : verb_(std::move(verb)), on_(force || ::isatty(STDERR_FILENO)) {}

ProgressLine::~ProgressLine() {
    if (drawn_) std::cerr << '\n';
}

void ProgressLine::operator()(const tape::LineProgress& p) {
    if (!on_) return;
    char line[160];
    if (p.total)
        std::snprintf(line, sizeof line, "\rtape: %s %llu/%llu frames, %.0f frames/s, %llu pause(s)%s   ",
                      verb_.c_str(), static_cast<unsigned long long>(p.frames),
                      static_cast<unsigned long long>(p.total), p.rate, static_cast<unsigned long long>(p.pauses),
                      p.paused ? ", paused (XOFF)" : "");
    else
        std::snprintf(line, sizeof line, "\rtape: %s %llu frames, %.0f frames/s   ", verb_.c_str(),
                      static_cast<unsigned long long>(p.frames), p.rate);
    std::cerr << line << std::flush;
    drawn_ = true;
}

void add_feed_profile_options(CLI::App* sub, FeedProfile& p) {
    add_code_options(sub, p.choice, true, true);  // a text program may be sent in ITA2 or МТК-2
    sub->add_option("--leader", p.leader, "Blank frames (NUL) before the program")
        ->check(whole_number(0, tape::max_blank_frames))
        ->capture_default_str()
        ->each([&p](const std::string&) { p.leader_given = true; });
    sub->add_option("--trailer", p.trailer, "Blank frames after the program")
        ->check(whole_number(0, tape::max_blank_frames))
        ->capture_default_str()
        ->each([&p](const std::string&) { p.trailer_given = true; });
    sub->add_flag("--crlf", p.crlf, "End blocks with CR LF instead of LF (text programs, ISO)");
    sub->add_flag("--percent", p.percent,
                  "Text programs: put a '%' block first when the program has none, and a '%' after it when it does "
                  "not end with one (never doubled); by default the program is sent exactly as written");
    add_dialect_option(sub, p.dialect);
    sub->add_option("--format,-f", p.format,
                    "Image format of IN (IN is then a tape image), and of a file: device: " + format_choices(false))
        ->check(format_check(false));
    sub->add_option("--input", p.kind, "What IN is: auto, text or image")
        ->check(CLI::IsMember({"auto", "text", "image"}))
        ->capture_default_str();
}

std::vector<tape::Frame> frames_to_send(const std::string& path, const FeedProfile& p) {
    std::string name = display_name(path);
    tape::InputOptions io = input_options(p.choice, p.format, p.kind);
    io.detect_code = false;  // an image is sent as it is
    auto input = open_input(path, io);
    tape::FeedOptions o;
    o.encode.code = tape::parse_code(p.choice.code).value_or(tape::Code::iso);  // auto: a text program in ISO
    o.encode.parity = io.decode.parity;
    o.encode.charset = io.decode.charset;
    o.encode.leader = p.leader;
    o.encode.trailer = p.trailer;
    o.encode.crlf = p.crlf;
    o.encode.eia_table = globals().table();
    o.replace_leader = p.leader_given;
    o.replace_trailer = p.trailer_given;
    o.percent = p.percent;
    o.dialect = tape::parse_dialect(p.dialect).value_or(tape::Dialect::automatic);
    try {
        tape::DialectChoice chosen;
        auto frames = tape::frames_to_send(*input, o, &chosen);
        if (!input->is_image()) say_dialect(name, chosen);
        return frames;
    } catch (const tape::Error& e) {
        fail(name, e);
    }
}

namespace {

void send_or_fail(tape::Transport& line, std::span<const tape::Frame> frames, tape::SendOptions o,
                  const std::string& verb, bool progress_forced) {
    o.stop = &interrupted();
    ProgressLine progress(verb, progress_forced);
    o.progress = [&progress](const tape::LineProgress& p) { progress(p); };
    tape::SendResult r;
    try {
        r = tape::send_frames(line, frames, o);
    } catch (const tape::Error& e) {
        fail("", e);
    }
    if (r.stopped) {
        say(line.name(),
            "stopped after " + std::to_string(r.sent) + " of " + std::to_string(frames.size()) + " frames");
        throw Exit{interrupted_status};
    }
    if (globals().verbosity > 0)
        say(line.name(),
            verb + " " + std::to_string(r.sent) + " frames, " + std::to_string(r.pauses) + " pause(s) (XOFF)");
}

// Holes pictures are annotated with the characters of the code the frames are in, when one fits.
std::string image_text(const tape::ImageFormat& format, std::span<const tape::Frame> frames) {
    std::optional<tape::FrameCode> code;
    if (auto detected = tape::detect_code(frames).code)
        code = tape::FrameCode::make(*detected, tape::Parity::even, globals().table());
    return format.write(frames, tape::ImageWriteOptions{code ? &*code : nullptr});
}

}  // namespace

std::optional<std::string> file_device_path(const std::string& device) {
    if (!device.starts_with("file:")) return std::nullopt;
    try {
        return tape::file_device_path(std::string_view(device).substr(5));
    } catch (const tape::Error& e) {
        fail("", e);  // the message names the device
    }
}

void deliver_or_fail(const Delivery& to, std::span<const tape::Frame> frames, tape::SendOptions o,
                     const std::string& verb) {
    if (auto path = file_device_path(to.device)) {
        // The messages match the file backend's own, as a device string would get them.
        if (o.flow == tape::Flow::rtscts)
            fail(to.device, tape::Errc::usage, "flow=rtscts, but this device has no modem lines");
        if (o.wait_xon) fail(to.device, tape::Errc::usage, "a file sends no DC1 (XON): --wait-xon needs a line");
        const tape::ImageFormat* format =
            to.format.empty() ? tape::image_format_for_path(*path) : tape::find_image_format(to.format);
        if (!format) format = &tape::default_image_format();
        // The default Ctrl-C handling stays: it removes the temporary, so the file is whole or absent.
        try {
            tape::write_file_atomic(*path, image_text(*format, frames), to.force);
        } catch (const tape::Error& e) {
            fail(to.device, e);
        }
        if (globals().verbosity > 0)
            say(to.device,
                verb + " " + std::to_string(frames.size()) + " frames as a " + std::string(format->id) + " image");
        return;
    }
    install_interrupt_handler();
    auto line = open_device_or_fail(to.device, to.use, to.force);
    send_or_fail(*line, frames, o, verb, to.progress);
}

std::uint8_t parse_byte(const std::string& text, const std::string& option) {
    try {
        std::size_t used = 0;
        unsigned long v = std::stoul(text, &used, 0);
        if (used == text.size() && v < 256) return static_cast<std::uint8_t>(v);
    } catch (const std::exception&) {
    }
    if (text.size() == 1) return static_cast<std::uint8_t>(text[0]);
    fail("", tape::Errc::usage, option + " takes a character or a byte value such as 0x11, not '" + text + "'");
}

}  // namespace cli
