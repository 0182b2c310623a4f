// tape encode: a text program -> a tape image.
#include <cstdlib>
#include <memory>
#include <new>
#include <span>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "tape/encode.hpp"
#include "tape/file_io.hpp"
#include "tape/utf8_text.hpp"

namespace cli {
namespace {

struct EncodeArgs {
    std::string input = "-", output = "-", format, label;
    CodeChoice choice;
    std::size_t leader = tape::default_leader, trailer = tape::default_trailer;
    bool crlf = false, force = false;
};

tape::EncodeOptions encode_options(const EncodeArgs& a, const std::string& in_name) {
    tape::EncodeOptions o;
    o.code = *tape::parse_code(a.choice.code);
    o.parity = *tape::parse_parity(a.choice.parity);
    o.charset = *tape::parse_charset(a.choice.charset);
    o.leader = a.leader;
    o.trailer = a.trailer;
    o.crlf = a.crlf;
    o.eia_table = globals().table();
    o.label = a.label;
    if (o.code == tape::Code::eia && o.parity != tape::Parity::even)
        fail(in_name, tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    if (tape::is_five_track(o.code) && o.parity != tape::Parity::even)
        fail(in_name, tape::Errc::usage, "--parity is for ISO tapes; 5-track codes carry none");
    if (tape::is_telecode(o.code) && o.parity != tape::Parity::even)
        fail(in_name, tape::Errc::usage, "--parity is for ISO tapes; the Elliott telecodes have their own");
    return o;
}

// OUT, written a chunk of frames at a time. It is created once the first chunk has encoded, so that a
// text the code cannot carry leaves nothing behind.
class EncodedOutput {
public:
    EncodedOutput(const EncodeArgs& a, const tape::ImageFormat& format, const tape::FrameCode& code)
        : a_(a), format_(format), writer_(format.make_writer(tape::ImageWriteOptions{&code})) {}

    void write(const std::vector<tape::Frame>& frames, bool last) {
        written_ += frames.size();
        if (!out_) out_ = open_output(a_.output, a_.force);
        try {
            if (format_.bytes_are_frames) {  // raw: the frames are the bytes, no copy into a string
                out_->write(std::string_view(reinterpret_cast<const char*>(frames.data()), frames.size()));
                return;
            }
            picture_.clear();
            writer_->write(frames, picture_);
            if (last) writer_->finish(picture_);
            out_->write(picture_);
        } catch (const tape::Error& e) {
            fail(name(), e);
        }
    }
    void discard() {
        if (out_) out_->discard();
    }
    void commit() {
        try {
            out_->commit();
        } catch (const tape::Error& e) {
            fail(name(), e);
        }
    }
    std::uint64_t written() const { return written_; }

private:
    std::string name() const { return a_.output == "-" ? "stdout" : a_.output; }
    const EncodeArgs& a_;
    const tape::ImageFormat& format_;
    std::unique_ptr<tape::ImageWriter> writer_;
    std::unique_ptr<tape::OutputFile> out_;
    std::string picture_;
    std::uint64_t written_ = 0;
};

// IN read, encoded and written a chunk at a time; a text the code cannot carry ends the program.
void encode_chunks(tape::FileSource& source, tape::Encoder& encoder, EncodedOutput& out, const std::string& in_name) {
    std::vector<tape::Frame> frames;
    bool noted = false;
    auto note_bom = [&] {
        if (noted || !encoder.skipped_byte_order_mark()) return;
        say_note(in_name, tape::byte_order_mark_note());
        noted = true;
    };
    try {
        // Page-aligned: read() copies into it faster than into malloc's page + 16 bytes.
        constexpr std::size_t chunk = 128 << 10;
        std::unique_ptr<std::uint8_t, decltype(&std::free)> storage(
            static_cast<std::uint8_t*>(std::aligned_alloc(4096, chunk)), &std::free);
        if (!storage) throw std::bad_alloc();
        std::span<std::uint8_t> buffer(storage.get(), chunk);
        for (std::size_t n; (n = source.read(buffer)) > 0;) {
            encoder.feed(std::string_view(reinterpret_cast<const char*>(buffer.data()), n), frames);
            note_bom();
            if (!frames.empty()) out.write(frames, false);
            frames.clear();
        }
        encoder.finish(frames);
    } catch (const tape::Error& e) {
        out.discard();
        note_bom();
        fail(in_name, e);
    }
    out.write(frames, true);
}

void run(const EncodeArgs& a) {
    std::string in_name = display_name(a.input);
    tape::EncodeOptions o = encode_options(a, in_name);
    const tape::ImageFormat& format = output_format(a.format, a.output);
    refuse_binary_terminal(a.output, format.binary, a.force);
    tape::FrameCode code = tape::FrameCode::make(o.code, o.parity, o.eia_table);
    std::unique_ptr<tape::Encoder> encoder;
    try {
        encoder = std::make_unique<tape::Encoder>(o);  // a label the font or the leader cannot take fails here
    } catch (const tape::Error& e) {
        fail(a.label.empty() ? in_name : "--label", e);
    }
    EncodedOutput out(a, format, code);
    auto source = open_source(a.input);
    encode_chunks(*source, *encoder, out, in_name);
    out.commit();
    if (const auto& mark = encoder->skipped_end_of_file_mark()) say_note(in_name, tape::dos_end_of_file_note(*mark));
    if (globals().verbosity > 0)
        say(in_name, std::to_string(out.written()) + " frames written as " + std::string(format.id));
}

}  // namespace

void add_encode(CLI::App& app) {
    auto a = std::make_shared<EncodeArgs>();
    auto* sub = app.add_subcommand("encode", "Punch a text program into a tape image (each line a block)");
    sub->add_option("input", a->input, "Text program; - or nothing for stdin");
    sub->add_option("-o,--output", a->output, "Tape image to write; - for stdout (raw refuses a terminal)");
    add_code_options(sub, a->choice, false, CodeSet::all);
    sub->add_option("--leader", a->leader, "Blank frames before the program (10 frames = 25.4 mm)")
        ->check(whole_number(0, tape::max_blank_frames))
        ->capture_default_str();
    sub->add_option("--trailer", a->trailer, "Blank frames after the program")
        ->check(whole_number(0, tape::max_blank_frames))
        ->capture_default_str();
    sub->add_flag("--crlf", a->crlf,
                  "End each block with CR LF on tape (ISO and the Elliott codes; 5-track tapes always have it), as "
                  "`tape decode` says a CR LF tape does: decode, then encode --crlf, gives the tape back");
    sub->add_option("--format,-f", a->format,
                    "Image format: " + format_choices(true) + " (default: by extension of OUT, else raw)")
        ->check(format_check(true));
    sub->add_option("--label", a->label,
                    "Punch TEXT into the leader as letters of holes, readable along the tape (Latin or Cyrillic "
                    "capitals, digits, space, - . /); the program is unchanged");
    sub->add_flag("--force", a->force, "Replace an existing OUT; write raw to a terminal");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
