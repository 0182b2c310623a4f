// Sending frames to a device (feed, punch): what a text program becomes on the line, and the run.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
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

/// What feed and punch send: IN opened and read as it is sent, so that a tape of any length is sent
/// in bounded memory. A bad frame of the image met on the way ends the program naming IN.
class SendInput : public tape::FrameSource {
public:
    std::span<const tape::Frame> next() override;
    std::uint64_t total() const override { return frames_->total(); }
    const std::string& name() const { return name_; }
    /// The code the frames are in, when one fits (for a holes picture's characters), or nullopt.
    std::optional<tape::FrameCode> code() const { return code_; }
    /// Frames are also kept (up to max_tape_frames), for a read-back to compare with.
    void keep() { keep_ = true; }
    const std::vector<tape::Frame>& kept() const { return kept_; }
    /// The input, for the code a picture of its frames is annotated with (nullptr for frames in memory).
    tape::Input* input_for_code() { return input_.get(); }

private:
    friend SendInput open_frames_to_send(const std::string&, const FeedProfile&, bool);
    friend SendInput frames_in_memory(std::vector<tape::Frame>, const std::string&, std::optional<tape::FrameCode>);

    std::string name_;
    std::unique_ptr<tape::Input> input_;
    std::unique_ptr<tape::FrameSource> frames_;
    std::optional<tape::FrameCode> code_;
    bool keep_ = false;
    std::vector<tape::Frame> kept_;
};

/// The frames to send for IN: an image as it is (blank ends replaced when --leader/--trailer are given),
/// or a text program encoded with the profile.
/// text_refused: a text program is refused (refuse_text_program), for punch's frames as they are.
SendInput open_frames_to_send(const std::string& path, const FeedProfile& p, bool text_refused = false);
/// A tape image's frames exactly as they are (punch); a text program is refused (refuse_text_program).
SendInput open_image_to_send(const std::string& path, const std::string& format_id);
/// Frames made whole before they are sent (a restart); name is for messages, code for a holes picture.
SendInput frames_in_memory(std::vector<tape::Frame> frames, const std::string& name,
                           std::optional<tape::FrameCode> code = std::nullopt);
/// The frames for an input already open (a restart's text), in memory; name is for messages.
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

/// Sends frames (feed, punch). A file: device gets the image through the image writer, atomically
/// (Ctrl-C leaves the old state, no part); it answers nothing, so RTS/CTS and --wait-xon are refused for
/// it and there is no pacing. Any other device is opened and sent to frame by frame, with Ctrl-C and a
/// progress line wired here. A device failure ends the program with status 3, Ctrl-C with 130; -v
/// reports the count.
void deliver_or_fail(const Delivery& to, SendInput& frames, tape::SendOptions o, const std::string& verb);

}  // namespace cli
