// Opening what a command reads: an image or a text program through the library's one entry point,
// the code it is decoded in, or a tape image read whole.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "tape/decode.hpp"
#include "tape/file_io.hpp"
#include "tape/image.hpp"
#include "tape/input.hpp"

namespace cli {

/// A tape image read whole from a file or stdin (for the commands that need all of it at once).
struct TapeInput {
    std::string name;  ///< as given, "-" for stdin; "stdin" in messages
    const tape::ImageFormat* format = nullptr;
    std::vector<tape::Frame> frames;
};

/// "stdin" for "-" or nothing, else the path.
std::string display_name(const std::string& path);

/// The library's input options for --code/--parity/--charset, --format and --input.
tape::InputOptions input_options(const CodeChoice& choice, const std::string& format_id,
                                 const std::string& kind = "auto");
/// IN ("-" = stdin) opened by the library's one entry point: an image by --format, extension or
/// content, or a text program. Failure ends the program.
std::unique_ptr<tape::Input> open_input(const std::string& path, const tape::InputOptions& options);
/// How an image is decoded, the code detected when asked (said with -v); failure ends the program.
const tape::DecodeOptions& decide_code(tape::Input& input, const std::string& name);
/// After bad frames of a tape read with a code or parity given by hand: says when it reads cleanly
/// another way (or is a 5-track, binary or text file), with the hint to read it so.
void say_other_reading(tape::Input& input, const std::string& name);

/// IN ("-" = stdin) opened to be read as bytes, a chunk at a time (a text to encode); failure ends the program.
std::unique_ptr<tape::FileSource> open_source(const std::string& path);

/// What reading IN as a tape image makes of a text program: its bytes taken as frames, or refused.
enum class TextProgram { as_bytes, refused };
/// Reads IN ("-" = stdin) whole as an image: --format, else by extension, else by content. A tape
/// longer than tape::max_tape_frames ends the program (bad data, exit 1) before it fills memory.
TapeInput read_tape(const std::string& path, const std::string& format_id, TextProgram text = TextProgram::as_bytes);
/// Ends the program (usage, exit 2) when input is a text program, for the commands that send frames as
/// they are (punch, emulate): its characters would go out with no parity and no leader, a tape no
/// reader takes. feed encodes a text; --format raw sends a file's bytes as they are.
void refuse_text_program(const tape::Input& input, const std::string& name);

}  // namespace cli
