#include "device_options.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"

namespace cli {

std::unique_ptr<tape::Transport> open_device_or_fail(const std::string& device, tape::DeviceUse use, bool replace) {
    // A file: device is an input or an output of the run like any other file.
    if (auto path = file_device_path(device)) {
        if (use == tape::DeviceUse::read)
            note_input(*path);
        else
            claim_output(*path);
    }
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

std::optional<std::string> file_device_path(const std::string& device) {
    if (!device.starts_with("file:")) return std::nullopt;
    try {
        return tape::file_device_path(std::string_view(device).substr(5));
    } catch (const tape::Error& e) {
        fail("", e);  // the message names the device
    }
}

std::uint8_t parse_byte(const std::string& text, const std::string& option) {
    if (auto v = byte_value(text)) return *v;
    fail("", tape::Errc::usage, option + " takes a character or a byte value such as 0x11, not '" + text + "'");
}

}  // namespace cli
