// What the device subcommands share: opening devices, their numeric options, progress lines.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "tape/device.hpp"
#include "tape/dnc.hpp"
#include "tape/machine.hpp"

namespace cli {

/// Opens a device string; errors end the program with the right status.
std::unique_ptr<tape::Transport> open_device_or_fail(const std::string& device, tape::DeviceUse use,
                                                     bool replace = false);

/// A progress line on stderr, when stderr is a terminal (or forced), at most a few times a second.
class ProgressLine {
public:
    ProgressLine(std::string verb, bool force);
    ~ProgressLine();
    void operator()(const tape::LineProgress& p);

private:
    std::string verb_;
    bool on_;
    bool drawn_ = false;
};

/// The PATH of a "file:PATH" device string, or nullopt for another device.
std::optional<std::string> file_device_path(const std::string& device);

/// "--xon 0x11" style byte options; a bad one ends the program with status 2.
std::uint8_t parse_byte(const std::string& text, const std::string& option);

/// The ranges of the numeric device options, in --help and in their checks.
inline constexpr double min_rate = 0.1, max_rate = 100000;  ///< frames per second
inline constexpr double max_delay_ms = 60000;               ///< --delay: a minute between characters
inline constexpr double max_timeout_s = 86400;              ///< time-outs: a day

}  // namespace cli
