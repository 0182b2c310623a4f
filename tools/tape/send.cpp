#include "send.hpp"

#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/programs.hpp"
#include "cli/run.hpp"
#include "cli/signals.hpp"
#include "device_options.hpp"
#include "tape/detect.hpp"
#include "tape/feed.hpp"
#include "tape/file_io.hpp"

namespace cli {

void add_feed_profile_options(CLI::App* sub, FeedProfile& p) {
    add_code_options(sub, p.choice, true, CodeSet::five_track);  // a text program may be sent in ITA2 or МТК-2
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

tape::InputOptions feed_input_options(const FeedProfile& p) {
    tape::InputOptions io = input_options(p.choice, p.format, p.kind);
    io.detect_code = false;  // an image is sent as it is
    return io;
}

namespace {

tape::FeedOptions feed_options(const FeedProfile& p) {
    tape::InputOptions io = feed_input_options(p);
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
    return o;
}

// The frames of a restart, made whole before anything is sent.
class FramesInMemory : public tape::FrameSource {
public:
    explicit FramesInMemory(std::vector<tape::Frame> frames) : frames_(std::move(frames)), source_(frames_) {}
    std::span<const tape::Frame> next() override { return source_.next(); }
    std::uint64_t total() const override { return frames_.size(); }

private:
    std::vector<tape::Frame> frames_;
    tape::SpanSource source_;
};

}  // namespace

std::vector<tape::Frame> frames_to_send(tape::Input& input, const std::string& name, const FeedProfile& p) {
    tape::FeedOptions o = feed_options(p);
    try {
        tape::DialectChoice chosen;
        auto frames = tape::frames_to_send(input, o, &chosen);
        if (!input.is_image()) say_dialect(name, chosen);
        return frames;
    } catch (const tape::Error& e) {
        fail(name, e);
    }
}

SendInput open_frames_to_send(const std::string& path, const FeedProfile& p, bool text_refused) {
    SendInput in;
    in.name_ = display_name(path);
    in.input_ = open_input(path, feed_input_options(p));
    if (text_refused) refuse_text_program(*in.input_, in.name_);
    tape::FeedOptions o = feed_options(p);
    try {
        tape::DialectChoice chosen;
        in.frames_ = tape::feed_source(*in.input_, o, &chosen);
        if (!in.input_->is_image()) {
            say_dialect(in.name_, chosen);
            in.code_ = tape::FrameCode::make(o.encode.code, o.encode.parity, o.encode.eia_table);
        }
    } catch (const tape::Error& e) {
        fail(in.name_, e);
    }
    return in;
}

SendInput frames_in_memory(std::vector<tape::Frame> frames, const std::string& name,
                           std::optional<tape::FrameCode> code) {
    SendInput in;
    in.name_ = name;
    // A holes picture shows the frames' characters in the code they are in, when one fits.
    if (!code)
        if (auto detected = tape::detect_code(frames).code)
            code = tape::FrameCode::make(*detected, tape::Parity::even, globals().table());
    in.code_ = code;
    in.frames_ = std::make_unique<FramesInMemory>(std::move(frames));
    return in;
}

SendInput open_image_to_send(const std::string& path, const std::string& format_id) {
    FeedProfile p;
    p.format = format_id;
    return open_frames_to_send(path, p, true);  // no code, parity or leader chosen for a text
}

std::span<const tape::Frame> SendInput::next() {
    std::span<const tape::Frame> chunk;
    try {
        chunk = frames_->next();
    } catch (const tape::Error& e) {
        fail(name_, e);
    }
    if (keep_) {
        if (kept_.size() + chunk.size() > tape::max_tape_frames)
            fail(name_, tape::Errc::usage, std::string(tape::too_long_text));
        kept_.insert(kept_.end(), chunk.begin(), chunk.end());
    }
    return chunk;
}

namespace {

void send_or_fail(tape::Transport& line, SendInput& frames, tape::SendOptions o, const std::string& verb,
                  bool progress_forced) {
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
        say(line.name(), "stopped after " + std::to_string(r.sent) +
                             (frames.total() ? " of " + std::to_string(frames.total()) : std::string()) + " frames");
        throw Exit{interrupted_status};
    }
    if (globals().verbosity > 0)
        say(line.name(),
            verb + " " + std::to_string(r.sent) + " frames, " + std::to_string(r.pauses) + " pause(s) (XOFF)");
}

// The code a holes picture shows the frames' characters in: a text program's own, or the one detected
// from the start of an image (its read-ahead, the whole of most tapes).
std::optional<tape::FrameCode> picture_code(tape::Input* input, const std::optional<tape::FrameCode>& own) {
    if (own) return own;
    if (!input || !input->is_image()) return std::nullopt;
    if (auto detected = input->detect().code)
        return tape::FrameCode::make(*detected, tape::Parity::even, globals().table());
    return std::nullopt;
}

// A file: device gets the image written as the frames come, made final at the end (atomically).
std::uint64_t write_image_file(const std::string& path, const tape::ImageFormat& format, SendInput& frames,
                               const std::optional<tape::FrameCode>& code, bool force) {
    auto writer = format.make_writer(tape::ImageWriteOptions{code ? &*code : nullptr});
    tape::OutputFile out(path, force);
    std::uint64_t written = 0;
    std::string piece;
    writer->write({}, piece);  // the format's header, also for an empty tape
    for (auto chunk = frames.next(); !chunk.empty(); chunk = frames.next()) {
        writer->write(chunk, piece);
        out.write(piece);
        piece.clear();
        written += chunk.size();
    }
    writer->finish(piece);
    out.write(piece);
    out.commit();
    return written;
}

}  // namespace

void deliver_or_fail(const Delivery& to, SendInput& frames, tape::SendOptions o, const std::string& verb) {
    if (auto path = file_device_path(to.device)) {
        // The messages match the file backend's own, as a device string would get them.
        if (o.flow == tape::Flow::rtscts)
            fail(to.device, tape::Errc::usage, "flow=rtscts, but this device has no modem lines");
        if (o.wait_xon) fail(to.device, tape::Errc::usage, "a file sends no DC1 (XON): --wait-xon needs a line");
        const tape::ImageFormat* format =
            to.format.empty() ? tape::image_format_for_path(*path) : tape::find_image_format(to.format);
        if (!format) format = &tape::default_image_format();
        claim_output(*path);
        std::optional<tape::FrameCode> code;
        try {
            code = picture_code(frames.input_for_code(), frames.code());
        } catch (const tape::Error& e) {
            fail(frames.name(), e);
        }
        // The default Ctrl-C handling stays: it removes the temporary, so the file is whole or absent.
        std::uint64_t written = 0;
        try {
            written = write_image_file(*path, *format, frames, code, to.force);
        } catch (const tape::Error& e) {
            fail(to.device, e);
        }
        if (globals().verbosity > 0)
            say(to.device, verb + " " + std::to_string(written) + " frames as a " + std::string(format->id) + " image");
        return;
    }
    install_interrupt_handler();
    auto line = open_device_or_fail(to.device, to.use, to.force);
    send_or_fail(*line, frames, o, verb, to.progress);
}

}  // namespace cli
