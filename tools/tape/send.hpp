// Sending frames to a device (feed, punch): what a text program becomes on the line, and the run.
#pragma once

#include <CLI/CLI.hpp>
#include <span>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "tape/device.hpp"
#include "tape/dnc.hpp"
#include "tape/encode.hpp"
#include "tape/input.hpp"

namespace cli {

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

}  // namespace cli
