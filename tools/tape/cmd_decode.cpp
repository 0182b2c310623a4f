// tape decode: a tape image -> the text program, every bad frame reported; streamed a chunk at a time.
#include <memory>

#include "cli/files.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "tape/file_io.hpp"

namespace cli {
namespace {

struct DecodeArgs {
    std::string input = "-", output = "-", format;
    CodeChoice choice;
    bool keep_going = false, force = false, strict = false;
};

// A bad frame as decode says it; blank tape inside a block as a warning (an error with --strict).
// True for the latter.
bool say_decoded(const std::string& name, const tape::Diagnostic& d, bool raw, bool strict) {
    if (d.code != tape::Errc::blank_frame) {
        say_diagnostic(name, d, raw);
        return false;
    }
    say(name, d.where.describe() + (strict ? ": " : ": warning: ") + d.message);
    return true;
}

void run(const DecodeArgs& a) {
    std::string name = display_name(a.input);
    tape::InputOptions io = input_options(a.choice, a.format, "image");
    io.decode.keep_going = a.keep_going;
    auto in = open_input(a.input, io);
    bool raw = in->format()->bytes_are_frames;
    claim_output(a.output);
    decide_code(*in, name);
    std::unique_ptr<tape::OutputFile> out;
    auto open_output = [&] {
        try {
            out = std::make_unique<tape::OutputFile>(a.output, a.force);
        } catch (const tape::Error& e) {
            fail(a.output, e);
        }
    };
    try {
        tape::DecodeResult piece;
        bool blank_in_block = false;
        while (in->next_text(piece)) {
            for (const auto& d : piece.diagnostics) blank_in_block |= say_decoded(name, d, raw, a.strict);
            piece.diagnostics.clear();
            if (!piece.complete) {  // nothing written: the program would be cut short
                say_other_reading(*in, name);
                throw Exit{bad_data};
            }
            if (!out) open_output();
            try {
                out->write(piece.text);
            } catch (const tape::Error& e) {
                fail(a.output, e);
            }
            piece.text.clear();
        }
        if (!out) open_output();  // an empty tape: an empty program
        say_unlisted_frames(name, in->decoder() ? in->decoder()->unlisted() : std::map<tape::Errc, std::uint64_t>{});
        try {
            out->commit();
        } catch (const tape::Error& e) {
            fail(a.output, e);
        }
        if (std::uint64_t bad = in->decoder() ? in->decoder()->bad_frames() : 0) {
            say(name, std::to_string(bad) + " bad frame(s), each marked \xEF\xBF\xBD in the text");
            say_other_reading(*in, name);
            throw Exit{bad_data};
        }
        if (std::uint64_t doubts = in->doubtful_frames()) {
            say(name, std::to_string(doubts) + " frame(s) restored in doubt (" + tape::doubts_file_for(a.input) + ")");
            throw Exit{bad_data};
        }
        if (blank_in_block && a.strict) throw Exit{bad_data};
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
    add_code_options(sub, a->choice, true, true);
    sub->add_option("--format,-f", a->format,
                    "Image format of IN: " + format_choices(false) + " (default: by extension, else by content)")
        ->check(format_check(false));
    sub->add_flag("--keep-going,-k", a->keep_going,
                  "Report every bad frame, write the program with each marked U+FFFD, still exit 1");
    sub->add_flag("--force", a->force, "Replace an existing OUT");
    sub->add_flag("--strict", a->strict,
                  "Blank tape inside a block (a character that lost its holes?) is an error: exit 1");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
