// What the device subcommands share: opening devices, Ctrl-C, progress lines, the frames to send.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "tape/device.hpp"
#include "tape/dnc.hpp"
#include "tape/encode.hpp"

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

/// How a text program becomes frames on the line (tape feed's profile options).
struct FeedProfile {
    CodeChoice choice;
    std::size_t leader = tape::default_leader, trailer = tape::default_trailer;
    bool leader_given = false, trailer_given = false;
    bool crlf = false;             ///< CR LF at the end of each block
    bool percent = false;          ///< wrap a text program in '%' ... '%' where it lacks them
    std::string dialect = "auto";  ///< how a text program is read (Fanuc's ';' ends of block)
    std::string format;            ///< image format of IN, when an image
    std::string kind = "auto";
};
void add_feed_profile_options(CLI::App* sub, FeedProfile& p);

/// The frames to send for IN: an image as it is (blank ends replaced when --leader/--trailer are given),
/// or a text program encoded with the profile.
std::vector<tape::Frame> frames_to_send(const std::string& path, const FeedProfile& p);
/// The same for an input already open (a restart's text); name is for messages.
std::vector<tape::Frame> frames_to_send(tape::Input& input, const std::string& name, const FeedProfile& p);
/// How IN is opened for the profile: an image is sent as it is, its code not detected.
tape::InputOptions feed_input_options(const FeedProfile& p);

/// Where feed and punch send their frames.
struct Delivery {
    std::string device;
    tape::DeviceUse use = tape::DeviceUse::write;
    std::string format;  ///< a file: device's image format, raw or holes (default: by extension, else raw)
    bool force = false;  ///< a file: device may replace an existing file
    bool progress = false;
};

/// Sends frames (feed, punch). A file: device gets the whole image at once through the image writer,
/// atomically (Ctrl-C leaves the old state, no part); it answers nothing, so RTS/CTS and --wait-xon
/// are refused for it and there is no pacing. Any other device is opened and sent to frame by frame,
/// with Ctrl-C and a progress line wired here. A device failure ends the program with status 3,
/// Ctrl-C with 130; -v reports the count.
void deliver_or_fail(const Delivery& to, std::span<const tape::Frame> frames, tape::SendOptions o,
                     const std::string& verb);

/// Receives frames from device into the image output as they arrive (receive, read): Ctrl-C and a
/// progress line wired here; a device failure ends the program with status 3. Returns how it ended.
tape::ReceiveResult::End receive_into_image(const std::string& device, const std::string& output,
                                            const std::string& format_id, bool force, tape::ReceiveOptions o,
                                            bool progress_forced, const char* verb);

/// The PATH of a "file:PATH" device string, or nullopt for another device.
std::optional<std::string> file_device_path(const std::string& device);

/// "--xon 0x11" style byte options; a bad one ends the program with status 2.
std::uint8_t parse_byte(const std::string& text, const std::string& option);

/// The ranges of the numeric device options, in --help and in their checks.
inline constexpr double min_rate = 0.1, max_rate = 100000;  ///< frames per second
inline constexpr double max_delay_ms = 60000;               ///< --delay: a minute between characters
inline constexpr double max_timeout_s = 86400;              ///< time-outs: a day

}  // namespace cli
