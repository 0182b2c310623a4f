// tape decode: a tape image -> the text program, every bad frame reported; streamed a chunk at a time.
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "tape/file_io.hpp"
#include "tape/image_input.hpp"

namespace cli {
namespace {

struct DecodeArgs {
    std::string input = "-", output = "-", format;
    CodeChoice choice;
    bool keep_going = false, force = false;
};

void run(const DecodeArgs& a) {
    std::string name = display_name(a.input);
    std::unique_ptr<tape::ImageInput> in;
    try {
        in =
            std::make_unique<tape::ImageInput>(a.input, a.format.empty() ? nullptr : tape::find_image_format(a.format));
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    bool raw = in->format().id == "raw";
    std::unique_ptr<tape::OutputFile> out;
    try {
        tape::DecodeOptions o = resolve_code(a.choice, name, [&] { return in->detect(); });
        o.keep_going = a.keep_going;
        tape::Decoder decoder(o);
        tape::DecodeResult piece;
        for (auto frames = in->next(); !frames.empty(); frames = in->next()) {
            bool going = decoder.feed(frames, piece);
            for (const auto& d : piece.diagnostics) say(name, where_text(d.where, raw) + ": " + d.message);
            piece.diagnostics.clear();
            if (!going) throw Exit{bad_data};  // nothing written: the program would be cut short
            if (!out) {
                try {
                    out = std::make_unique<tape::OutputFile>(a.output, a.force);
                } catch (const tape::Error& e) {
                    fail(a.output, e);
                }
            }
            try {
                out->write(piece.text);
            } catch (const tape::Error& e) {
                fail(a.output, e);
            }
            piece.text.clear();
        }
        if (!out) out = std::make_unique<tape::OutputFile>(a.output, a.force);  // an empty tape: an empty program
        say_unlisted_frames(name, decoder.unlisted());
        try {
            out->commit();
        } catch (const tape::Error& e) {
            fail(a.output, e);
        }
        if (decoder.bad_frames()) {
            say(name, std::to_string(decoder.bad_frames()) + " bad frame(s), each marked \xEF\xBF\xBD in the text");
            throw Exit{bad_data};
        }
    } catch (const tape::Error& e) {
        fail(name, e, raw);
    }
}

}  // namespace

void add_decode(CLI::App& app) {
    auto a = std::make_shared<DecodeArgs>();
    auto* sub = app.add_subcommand("decode", "Read a tape image back into the text program");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    sub->add_option("-o,--output", a->output, "Text file to write; - for stdout");
    add_code_options(sub, a->choice, true);
    sub->add_option("--format,-f", a->format,
                    "Image format of IN: " + format_choices(false) + " (default: by extension, else by content)")
        ->check(format_check(false));
    sub->add_flag("--keep-going,-k", a->keep_going,
                  "Report every bad frame, write the program with each marked U+FFFD, still exit 1");
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
