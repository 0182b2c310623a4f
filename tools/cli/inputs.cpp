#include "cli/inputs.hpp"

#include <sys/stat.h>

#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/messages.hpp"
#include "tape/detect.hpp"
#include "tape/limits.hpp"

namespace cli {

std::string display_name(const std::string& path) { return path.empty() || path == "-" ? "stdin" : path; }

tape::InputOptions input_options(const CodeChoice& choice, const std::string& format_id, const std::string& kind) {
    tape::InputOptions o;
    o.kind = kind == "text"    ? tape::InputKind::text
             : kind == "image" ? tape::InputKind::image
                               : tape::InputKind::automatic;
    o.format = format_id.empty() ? nullptr : tape::find_image_format(format_id);
    o.detect_code = choice.code == "auto";
    o.decode.code = tape::parse_code(choice.code).value_or(tape::Code::iso);
    o.decode.parity = *tape::parse_parity(choice.parity);
    o.decode.charset = *tape::parse_charset(choice.charset);
    o.decode.eia_table = globals().table();
    o.decode.max_diagnostics = globals().max_errors;
    return o;
}

std::unique_ptr<tape::Input> open_input(const std::string& path, const tape::InputOptions& options) {
    if (!options.detect_code && options.decode.code == tape::Code::eia && options.decode.parity != tape::Parity::even)
        fail(display_name(path), tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    note_input(path);
    std::unique_ptr<tape::Input> input;
    try {
        input = std::make_unique<tape::Input>(path.empty() ? "-" : path, options);
    } catch (const tape::Error& e) {
        fail(display_name(path), e);
    }
    for (const auto& note : input->notes()) say_note(display_name(path), note);
    return input;
}

const tape::DecodeOptions& decide_code(tape::Input& input, const std::string& name) {
    try {
        const tape::DecodeOptions& o = input.decode_options();
        if (globals().verbosity > 0 && input.detection()) say(name, "code " + input.detection()->reason);
        // A code or parity given by hand is taken as given; the verdict is still drawn (from the
        // read-ahead), so that a tape failing the given code can be said to read cleanly another way.
        if (!input.detection()) input.detect();
        if (input.closest_taken()) say(name, "warning: " + tape::closest_reading_note(*input.detection()));
        return o;
    } catch (const tape::Error& e) {
        const tape::CodeDetection* d = input.is_image() && input.detection() ? &*input.detection() : nullptr;
        if (e.code() != tape::Errc::unknown_code || !d || !d->closest) fail(name, e);
        // No code fits, one is closest: the text can be had all the same, each failing frame marked.
        fail(name, tape::Errc::unknown_code,
             d->reason + " (`tape decode -k` decodes it all the same as " + tape::reading_name(*d->closest) +
                 ", the closest, marking each frame that fails)");
    }
}

void say_other_reading(tape::Input& input, const std::string& name) {
    if (!input.is_image() || !input.detection()) return;
    const tape::DecodeOptions& o = input.decode_options();
    // The verdict weighs 8-track readings only: a 5-track code given by hand is not second-guessed.
    if (o.code == tape::Code::ita2 || o.code == tape::Code::mtk2) return;
    tape::Reading forced{o.code, o.code == tape::Code::eia ? tape::Parity::odd : o.parity};
    if (auto note = tape::other_reading(*input.detection(), forced)) say(name, with_hint(note->message, note->hint));
}

std::unique_ptr<tape::FileSource> open_source(const std::string& path) {
    note_input(path);
    try {
        return std::make_unique<tape::FileSource>(path);
    } catch (const tape::Error& e) {
        fail(display_name(path), e);
    }
}

void refuse_text_program(const tape::Input& input, const std::string& name) {
    if (!input.is_image())
        fail(name, tape::Errc::usage,
             "a text program: use feed, or encode it first (--format raw sends its bytes as they are)");
}

TapeInput read_tape(const std::string& path, const std::string& format_id, TextProgram text) {
    TapeInput in;
    in.name = path.empty() ? "-" : path;
    tape::InputOptions o = input_options(CodeChoice{}, format_id, text == TextProgram::refused ? "auto" : "image");
    o.detect_code = false;
    auto input = open_input(in.name, o);
    std::string name = display_name(in.name);
    if (text == TextProgram::refused) refuse_text_program(*input, name);
    in.format = input->format();
    // A raw file's size is its frames: one too long for any tape is refused before it is read.
    struct stat st {};
    if (in.format->bytes_are_frames && in.name != "-" && ::stat(in.name.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        static_cast<std::uint64_t>(st.st_size) > tape::max_tape_frames)
        fail(name, tape::Errc::bad_image, std::string(tape::too_long_text));
    try {
        for (auto frames = input->next_frames(); !frames.empty(); frames = input->next_frames()) {
            if (in.frames.size() + frames.size() > tape::max_tape_frames)
                fail(name, tape::Errc::bad_image, std::string(tape::too_long_text));
            in.frames.insert(in.frames.end(), frames.begin(), frames.end());
        }
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    return in;
}

}  // namespace cli
