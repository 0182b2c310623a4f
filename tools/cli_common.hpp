// What every subcommand shares: reading inputs, writing outputs, code options, error reporting.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tape/code.hpp"
#include "tape/decode.hpp"
#include "tape/detect.hpp"
#include "tape/error.hpp"
#include "tape/image.hpp"
#include "tape/program.hpp"

namespace cli {

/// Thrown to end the program with an exit status once the message is printed.
struct Exit {
    int status;
};

/// Exit statuses: mapped here and nowhere else.
enum Status { ok = 0, bad_data = 1, usage = 2, io_failure = 3 };
int status_for(tape::Errc code);

/// Options given before or after the subcommand.
struct Globals {
    int verbosity = 0;               ///< -v steps up, -q down
    std::string eia_table;           ///< --eia-table FILE: a corrected EIA table
    std::uint64_t max_errors = 100;  ///< --max-errors: messages of one kind before the rest are only counted
    std::optional<tape::CodeTable> loaded_table;

    /// The EIA table to use (loaded on first use), or nullptr for the built-in one.
    const tape::CodeTable* table();
};
Globals& globals();

/// SIGINT, SIGTERM, SIGHUP and SIGQUIT remove an output's temporary file, then end the run as the
/// signal would. Device runs replace this with their own stop flag.
void install_output_cleanup();

/// "tape: FILE: WHERE: message" on stderr.
void say(const std::string& file, const std::string& message);
/// Prints the error as above and throws Exit with its status.
[[noreturn]] void fail(const std::string& file, const tape::Error& e, bool raw_frames = false);
[[noreturn]] void fail(const std::string& file, tape::Errc code, const std::string& message);

/// "frame 137 (byte 0x88)" for raw images, where frame N is byte N-1.
std::string where_text(const tape::Position& where, bool raw_frames);

/// A tape image read from a file or stdin.
struct TapeInput {
    std::string name;  ///< as given, "-" for stdin; "stdin" in messages
    const tape::ImageFormat* format = nullptr;
    std::vector<tape::Frame> frames;
    bool raw() const { return format && format->id == "raw"; }
};
/// Prints the bad frames a decoding kept, then how many more of each kind were only counted.
void report_bad_frames(const std::string& name, const tape::DecodeResult& r, bool raw_frames);
/// One such line for each kind of bad frame beyond the limit.
void say_unlisted_frames(const std::string& name, const std::map<tape::Errc, std::uint64_t>& unlisted);
/// "12345 more parity error(s) not shown (--max-errors 100)".
void say_unlisted(const std::string& name, std::uint64_t count, const std::string& what);

/// Reads IN ("-" = stdin) as an image: --format, else by extension, else by content.
TapeInput read_tape(const std::string& path, const std::string& format_id);
/// The same from bytes already read.
TapeInput tape_from_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes,
                          const std::string& format_id);
/// The whole of IN ("-" or empty = stdin); failure ends the program.
std::vector<std::uint8_t> read_input(const std::string& path);
/// Whether IN is a tape image rather than a text program: --input, --format, a raw image's extension,
/// a holes picture, or anything that is not clean UTF-8 text.
bool is_image_input(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::string& format_id,
                    const std::string& kind);
std::string display_name(const std::string& path);
/// Fails (exit 1) naming the line and column of the first byte a text program cannot hold.
void require_program_text(const std::string& path, std::span<const std::uint8_t> bytes);

/// The code chosen for a decoding run: --code auto detects and explains itself with -v.
struct CodeChoice {
    std::string code = "auto";
    std::string parity = "even";
    std::string charset = "ascii";
};
void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto);
/// Options for the library from the choice, detecting the code when asked; fails with exit 1 when
/// the tape fits neither code.
tape::DecodeOptions resolve_code(const CodeChoice& choice, const TapeInput& input);
/// The same for a tape being streamed: detect is called only when the code is to be detected.
tape::DecodeOptions resolve_code(const CodeChoice& choice, const std::string& name,
                                 const std::function<tape::CodeDetection()>& detect);

/// The image formats of the table that can be read (or written): "raw or holes", and a CLI11 check
/// that accepts exactly their ids. The CLI's --format choices come from here, never from a list of its own.
std::string format_choices(bool for_writing);
CLI::Validator format_check(bool for_writing);

/// Fails (usage) when a binary image would go to standard output on a terminal without --force.
void refuse_binary_terminal(const std::string& path, bool binary, bool force);

/// Writes data to OUT ("-" or empty = stdout) atomically; refuses to replace a file without force,
/// and a binary image on a terminal without force.
void write_output(const std::string& path, const std::string& data, bool binary, bool force);

/// A program read for the loader: a text program, or a tape image decoded with frame positions.
struct ProgramInput {
    std::string name;  ///< for messages
    bool from_tape = false;
    tape::LoadedTape tape;
};
/// Options saying how IN is read: as decode's, plus --input text|image|auto.
struct ProgramSource {
    CodeChoice choice;
    std::string format;
    std::string kind = "auto";
};
void add_program_source_options(CLI::App* sub, ProgramSource& source);
/// Reads IN: an image (by --format, extension, or content) is decoded with positions; anything that
/// is clean UTF-8 text is a text program. A bad frame on a tape fails with exit 1, as decode does.
ProgramInput load_program(const std::string& path, const ProgramSource& source);

/// A JSON string literal for s (UTF-8 passed through, controls escaped).
std::string json_string(const std::string& s);

/// "frame 137" for tapes, "line 3" for text.
std::string position_text(const tape::Location& where, bool from_tape);

}  // namespace cli
