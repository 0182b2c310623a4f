// tape decode: a tape image -> the text program, every bad frame reported; streamed a chunk at a time.
// A binary loader tape (PDP-8 RIM or BIN, PDP-11 absolute loader) gives its memory image instead.
#include <memory>

#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "tape/binary_tape.hpp"
#include "tape/file_io.hpp"
#include "tape_report.hpp"

namespace cli {
namespace {

struct DecodeArgs {
    std::string input = "-", output = "-", format, to = "text";
    CodeChoice choice;
    bool keep_going = false, force = false, unshift_on_space = false, strict = false;
};

// A bad frame as decode says it; blank tape inside a block as a warning (an error with --strict).
// True for the latter.
bool say_decoded(const std::string& name, const tape::Diagnostic& d, bool raw, bool strict) {
    if (d.severity == tape::Severity::note) {
        say(name, where_text(d.where, raw) + ": note: " + d.message);
        return false;
    }
    if (d.code != tape::Errc::blank_frame) {
        say_diagnostic(name, d, raw);
        return false;
    }
    say(name, d.where.describe() + (strict ? ": " : ": warning: ") + d.message);
    return true;
}

// OUT, claimed by run() before the tape was read.
std::unique_ptr<tape::OutputFile> open_output_or_fail(const std::string& path, bool force) {
    try {
        return std::make_unique<tape::OutputFile>(path, force || written_into(path));
    } catch (const tape::Error& e) {
        fail(path, e);
    }
}

void write_or_fail(tape::OutputFile& out, std::string_view data, const std::string& name) {
    try {
        out.write(data);
    } catch (const tape::Error& e) {
        fail(name, e);
    }
}

void commit_or_fail(tape::OutputFile& out, const std::string& name) {
    try {
        out.commit();
    } catch (const tape::Error& e) {
        fail(name, e);
    }
}

// A binary loader tape decoded as text would be noise: say what it is and how to get its memory.
void refuse_binary(tape::Input& in, const std::string& name) {
    if (!in.is_image()) return;
    const tape::CodeDetection* detected = nullptr;
    try {
        detected = &in.detect();
    } catch (const tape::Error& e) {
        fail(name, e, in.format()->bytes_are_frames);
    }
    const tape::CodeDetection& d = *detected;
    if (d.kind != tape::TapeKind::binary || !d.evidence.binary) return;
    fail(name, tape::Errc::unknown_code,
         d.evidence.binary->summary() +
             ": no text to decode; `tape decode --to bin` (or --to octal) writes the memory "
             "image its loader would fill");
}

void say_after_text(tape::Input& in, const std::string& name, const CodeChoice& choice, bool raw) {
    const tape::Decoder* d = in.decoder();
    if (d)
        for (const auto& w : d->ending()) say(name, where_text(w.where, raw) + ": warning: " + w.message);
    if (d && d->line_ends().lines > 0 && d->line_ends().crlf == d->line_ends().lines)
        say(name, "note: every line ends with CR LF on this tape; `tape encode --crlf` punches them so again");
    if (choice.charset == "ascii" && in.detection() && tape::looks_like_koi7(in.detection()->evidence) &&
        in.decode_options().code == tape::Code::iso)
        say(name,
            "note: letters between SO and SI: Russian text in КОИ-7, shown here as Latin letters (use "
            "--charset koi7)");
}

void decode_text(const DecodeArgs& a, tape::Input& in, const std::string& name) {
    bool raw = in.format()->bytes_are_frames;
    if (a.choice.code == "auto") refuse_binary(in, name);
    decide_code(in, name);
    std::unique_ptr<tape::OutputFile> out;
    try {
        tape::DecodeResult piece;
        bool blank_in_block = false;
        while (in.next_text(piece)) {
            for (const auto& d : piece.diagnostics) blank_in_block |= say_decoded(name, d, raw, a.strict);
            piece.diagnostics.clear();
            if (!piece.complete) {  // nothing written: the program would be cut short
                say_other_reading(in, name);
                throw Exit{bad_data};
            }
            if (!out) out = open_output_or_fail(a.output, a.force);
            write_or_fail(*out, piece.text, a.output);
            piece.text.clear();
        }
        if (!out) out = open_output_or_fail(a.output, a.force);  // an empty tape: an empty program
        say_unlisted_frames(name, in.decoder() ? in.decoder()->unlisted() : std::map<tape::Errc, std::uint64_t>{});
        commit_or_fail(*out, a.output);
        say_after_text(in, name, a.choice, raw);
        if (std::uint64_t bad = in.decoder() ? in.decoder()->bad_frames() : 0) {
            say(name, std::to_string(bad) + " bad frame(s), each marked \xEF\xBF\xBD in the text");
            say_other_reading(in, name);
            throw Exit{bad_data};
        }
        if (std::uint64_t doubts = in.doubtful_frames()) {
            say(name, std::to_string(doubts) + " frame(s) restored in doubt, written or left out (" +
                          tape::doubts_file_for(a.input) + ")");
            throw Exit{bad_data};
        }
        if (blank_in_block && a.strict) throw Exit{bad_data};
    } catch (const tape::Error& e) {
        fail(name, e, raw);
    }
}

// The memory a loader would fill: read whole (it is at most 64 KiB), checked block by block.
void decode_memory(const DecodeArgs& a, tape::Input& in, const std::string& name) {
    tape::BinaryDetector binary(true);
    try {
        for (auto frames = in.next_frames(); !frames.empty(); frames = in.next_frames()) binary.feed(frames);
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    binary.finish();
    const tape::BinaryTape* t = binary.tape();
    if (!t)
        fail(name, tape::Errc::unknown_code,
             "no binary loader format (PDP-8 RIM or BIN, PDP-11 absolute loader) explains this tape; `tape info` "
             "tells what it is");
    if (globals().verbosity > 0) say(name, t->summary());
    bool bad = false;
    for (const auto& b : t->blocks)
        if (b.checksum && b.checksum->state != tape::ChecksumSpan::State::holds) {
            say(name, "frame " + std::to_string(b.first + 1) + ": " + binary_block_line(b));
            bad |= b.checksum->state == tape::ChecksumSpan::State::fails;
        }
    if (bad && !a.keep_going) {
        say(name, "a checksum fails: nothing written (--keep-going writes the memory image all the same)");
        throw Exit{bad_data};
    }
    bool bytes = a.to == "bin";
    refuse_binary_terminal(a.output, bytes, a.force);
    auto out = open_output_or_fail(a.output, a.force);
    write_or_fail(*out, bytes ? tape::memory_image_bytes(*binary.image()) : tape::memory_image_octal(*binary.image()),
                  a.output);
    commit_or_fail(*out, a.output);
    if (bad) throw Exit{bad_data};
}

void run(const DecodeArgs& a) {
    std::string name = display_name(a.input);
    tape::InputOptions io = input_options(a.choice, a.format, "image");
    io.decode.keep_going = a.keep_going;
    io.decode.unshift_on_space = a.unshift_on_space;
    if (a.to != "text") io.detect_code = false;  // a binary tape has no character code to find
    io.decided_runs = globals().verbosity > 0;   // -v: where a restoration decided a run against a read
    auto in = open_input(a.input, io);
    claim_output(a.output);  // refused before anything is read when it is the input
    if (a.to == "text")
        decode_text(a, *in, name);
    else
        decode_memory(a, *in, name);
}

}  // namespace

void add_decode(CLI::App& app) {
    auto a = std::make_shared<DecodeArgs>();
    auto* sub = app.add_subcommand("decode",
                                   "Read a tape image back into the text program, or a binary loader "
                                   "tape into its memory image");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    sub->add_option("-o,--output", a->output, "Text file to write; - for stdout");
    add_code_options(sub, a->choice, true, CodeSet::all);
    sub->add_option("--to", a->to,
                    "text (the program), or for a binary loader tape (PDP-8 RIM and BIN, PDP-11 absolute loader) "
                    "its memory image: bin (bytes from address 0 to the highest loaded; PDP-8 words as two bytes, "
                    "low first) or octal (address: words, where anything was loaded)")
        ->check(CLI::IsMember({"text", "bin", "octal"}))
        ->capture_default_str();
    sub->add_option("--format,-f", a->format,
                    "Image format of IN: " + format_choices(false) + " (default: by extension, else by content)")
        ->check(format_check(false));
    sub->add_flag("--keep-going,-k", a->keep_going,
                  "Report every bad frame, write the program with each marked U+FFFD (or the memory image past a "
                  "failing checksum), still exit 1");
    sub->add_flag("--unshift-on-space", a->unshift_on_space,
                  "ITA2: a space returns to letters, as on teleprinters with unshift-on-space (a tape they punched "
                  "has no letters shift after a space)");
    sub->add_flag("--force", a->force, "Replace an existing OUT; write a binary image to a terminal");
    sub->add_flag("--strict", a->strict,
                  "Blank tape inside a block (a character that lost its holes?) is an error: exit 1");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
