#include "receive_image.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "cli/signals.hpp"
#include "device_options.hpp"
#include "tape/file_io.hpp"
#include "tape/frame_file_writer.hpp"

namespace cli {
namespace {

const char* end_text(tape::ReceiveResult::End e) {
    switch (e) {
        case tape::ReceiveResult::End::program_end:
            return "end of program";
        case tape::ReceiveResult::End::idle:
            return "no frame for the time-out";
        case tape::ReceiveResult::End::hangup:
            return "end of tape, or the other side hung up";
        case tape::ReceiveResult::End::stopped:
            return "stopped";
    }
    return "";
}

// A tape read backwards, whole: its image is written again, atomically, first frame first. Throws
// Error; the image is then as read.
void turn_around(const std::string& output, const tape::ImageFormat& format, const tape::FrameCode& annotate) {
    auto frames = format.read(tape::read_file(output));
    std::reverse(frames.begin(), frames.end());
    tape::write_file_atomic(output, format.write(frames, tape::ImageWriteOptions{.annotate = &annotate}), true);
}

// The image format of OUT, checked against what the line brings before anything is created: a run
// that cannot be kept whole is refused at once, not after the first frame.
const tape::ImageFormat& output_format_for(tape::Transport& line, const std::string& output,
                                           const std::string& format_id, const tape::ReceiveOptions& o, bool force) {
    if (line.seven_bit() && o.code != tape::Code::iso)  // as receive_frames would refuse it
        fail(line.name(), tape::Errc::usage,
             "a 7-bit line carries ISO tapes only (the UART's parity stands for track 8): use bits=8 for EIA");
    const tape::ImageFormat* format = format_id.empty()
                                          ? (output == "-" ? nullptr : tape::image_format_for_path(output))
                                          : tape::find_image_format(format_id);
    if (!format) format = &tape::default_image_format();
    if (!format->can_write())
        fail(output, tape::Errc::usage, "cannot write " + std::string(format->id) + " images, only read them");
    if (format->tracks < line.tracks())
        fail(output, tape::Errc::usage,
             std::string(format->id) + " images hold " + std::to_string(format->tracks) + "-track tape, and " +
                 line.name() + " reads " + std::to_string(line.tracks()) + " tracks: write " +
                 (line.tracks() > 5 ? "hex8, raw or holes" : "hex5") + " (or --format)");
    refuse_binary_terminal(output, format->binary, force);
    return *format;
}

// Frames the reader itself doubts are kept, and named, also when the run fails after them. A tape
// read backwards and turned: in the tape's order (rows - n + 1 for the n-th row that came).
void say_doubts(tape::Transport& line, std::optional<std::uint64_t> turned_rows) {
    auto doubts = line.take_doubts();
    std::uint64_t shown = 0, unshown = doubts.unkept;
    if (turned_rows) std::reverse(doubts.runs.begin(), doubts.runs.end());
    for (const auto& d : doubts.runs) {
        if (globals().max_errors && shown >= globals().max_errors) {
            unshown += d.last - d.first + 1;
            continue;
        }
        ++shown;
        auto [first, last] =
            turned_rows ? std::pair(*turned_rows - d.last + 1, *turned_rows - d.first + 1) : std::pair(d.first, d.last);
        std::string run = last > first ? "doubtful, to frame " + std::to_string(last) + ": " : "doubtful: ";
        say_diagnostic(line.name(),
                       tape::Diagnostic{.code = tape::Errc::doubtful_frame,
                                        .where = tape::Position{.frame = first},
                                        .message = run + d.what,
                                        .severity = tape::Severity::warning},
                       false);
    }
    if (unshown) say_unlisted(line.name(), unshown, "doubtful frame(s)");
}

// One run of receiving into an image: the device, the image written as frames come, and how it ends.
class ImageReceiver {
public:
    ImageReceiver(tape::Transport& line, const std::string& output, const tape::ImageFormat& format,
                  tape::FrameCode annotate, bool force)
        : line_(line), output_(output), format_(format), annotate_(annotate) {
        claim_output(output);
        try {
            out_ = std::make_unique<tape::FrameFileWriter>(output, format, &annotate_, force || written_into(output));
        } catch (const tape::Error& e) {
            fail(output, e);
        }
    }

    tape::ReceiveResult run(tape::ReceiveOptions o, bool progress_forced, const char* verb) {
        o.stop = &interrupted();
        o.sink = [this](std::span<const tape::Frame> frames) {
            try {
                out_->append(frames);
            } catch (const tape::Error& e) {
                fail(output_, e);
            }
        };
        ProgressLine progress(verb, progress_forced);
        o.progress = [&progress](const tape::LineProgress& p) { progress(p); };
        try {
            return tape::receive_frames(line_, o);
        } catch (const tape::Error& e) {
            try {
                out_->sync();
            } catch (const tape::Error&) {  // the run's own failure is the one to report
            }
            say_read_order();
            say_doubts(line_, std::nullopt);
            fail("", e);
        }
    }

    // Only a whole reading, to the tape's start, is turned: a part of a tape (stopped, quiet) turned
    // would number its frames from nowhere on the tape. tape read keeps every row, so the image's
    // frames are the reader's rows. Returns whether it was turned.
    bool finish(const tape::ReceiveResult& r, const tape::ReceiveOptions& o) {
        bool turn = line_.backwards() && r.end == tape::ReceiveResult::End::hangup && !o.drop_flow_codes &&
                    !o.until_program_end && out_->frames() == r.frames && out_->is_file();
        try {
            if (turn) {
                out_->close();  // with its format's ending, before it is read back
                turn_around(output_, format_, annotate_);
            } else {
                out_->sync();
            }
        } catch (const tape::Error& e) {
            if (turn) {
                say_read_order();
                say_doubts(line_, std::nullopt);
            }
            fail(output_, e);
        }
        if (!turn) say_read_order();
        say_doubts(line_, turn ? std::optional(r.frames) : std::nullopt);
        return turn;
    }

private:
    // Said before the doubts, whose frame numbers then count in the order read.
    void say_read_order() {
        if (line_.backwards() && out_->frames() > 1)
            say(output_,
                "read backwards and not to the tape's start: its frames are in the order read, the "
                "tape's last first");
    }

    tape::Transport& line_;
    const std::string& output_;
    const tape::ImageFormat& format_;
    tape::FrameCode annotate_;
    std::unique_ptr<tape::FrameFileWriter> out_;
};

}  // namespace

tape::ReceiveResult::End receive_into_image(const std::string& device, const std::string& output,
                                            const std::string& format_id, bool force, tape::ReceiveOptions o,
                                            bool progress_forced, const char* verb) {
    install_interrupt_handler();
    auto line = open_device_or_fail(device, tape::DeviceUse::read);
    const tape::ImageFormat& format = output_format_for(*line, output, format_id, o, force);
    ImageReceiver receiver(*line, output, format, tape::FrameCode::make(o.code, o.parity, o.eia_table), force);
    tape::ReceiveResult r = receiver.run(o, progress_forced, verb);
    bool turned = receiver.finish(r, o);
    if (globals().verbosity > 0)
        for (const auto& note : line->take_notes()) say(line->name(), note);
    if (globals().verbosity >= 0)
        say(device, std::to_string(r.frames) + " frames " + verb + " into " + (output == "-" ? "stdout" : output) +
                        " (" + end_text(r.end) + (turned ? "; read backwards, turned to the tape's order" : "") + ")");
    return r.end;
}

}  // namespace cli
