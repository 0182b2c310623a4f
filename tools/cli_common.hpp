// What every subcommand shares: reading inputs, writing outputs, code options, error reporting.
#pragma once

#include <CLI/CLI.hpp>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tape/code.hpp"
#include "tape/decode.hpp"
#include "tape/detect.hpp"
#include "tape/error.hpp"
#include "tape/format_spec.hpp"
#include "tape/image.hpp"
#include "tape/input.hpp"
#include "tape/label.hpp"
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
    std::string program = "tape";    ///< what messages start with: tape-damage shares this code
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

/// Exit status of a run the user interrupted (128 + SIGINT).
inline constexpr int interrupted_status = 130;

/// Set by SIGINT/SIGTERM once install_interrupt_handler() ran; device runs stop cleanly on it.
std::atomic<bool>& interrupted();
void install_interrupt_handler();

/// main()'s end for every program of the toolkit: parses argv and runs what it calls. --help and
/// --version are answered; a usage error is said as "PROGRAM: what" then "PROGRAM: run HELP for the
/// options" (HELP defaults to 'PROGRAM --help'), with status usage; Exit ends with its status.
int parse_and_run(CLI::App& app, int argc, char** argv, const std::string& help = "");

/// "tape: FILE: WHERE: message" on stderr (the program's name first).
void say(const std::string& file, const std::string& message);
/// Prints the error as above and throws Exit with its status.
[[noreturn]] void fail(const std::string& file, const tape::Error& e, bool raw_frames = false);
[[noreturn]] void fail(const std::string& file, tape::Errc code, const std::string& message);

/// "frame 137 (byte 0x88, line 11)": the byte for raw images, where frame N is byte N-1, and the
/// line of the decoded text when known.
std::string where_text(const tape::Position& where, bool raw_frames);

/// The code chosen for a decoding run: --code auto detects and explains itself with -v.
struct CodeChoice {
    std::string code = "auto";
    std::string parity = "even";
    std::string charset = "ascii";
};
/// A tape image read whole from a file or stdin (for the device commands, which send it whole).
struct TapeInput {
    std::string name;  ///< as given, "-" for stdin; "stdin" in messages
    const tape::ImageFormat* format = nullptr;
    std::vector<tape::Frame> frames;
};
/// Prints one diagnostic: "tape: FILE: frame 12 (byte 0xB): message (hint)".
void say_diagnostic(const std::string& name, const tape::Diagnostic& d, bool raw_frames);
/// "tape: FILE: line 1: note: message" for a finding that is no fault.
void say_note(const std::string& name, const tape::Diagnostic& d);
/// After bad frames of a tape read with a code or parity given by hand: says when it reads cleanly
/// another way (or is a 5-track, binary or text file), with the hint to read it so.
void say_other_reading(tape::Input& input, const std::string& name);
/// One such line for each kind of bad frame beyond the limit.
void say_unlisted_frames(const std::string& name, const std::map<tape::Errc, std::uint64_t>& unlisted);
/// "12345 more parity error(s) not shown (--max-errors 100)".
void say_unlisted(const std::string& name, std::uint64_t count, const std::string& what);
/// What the command line offers for a hint: "use --force to replace it"; "" for none.
std::string hint_text(const tape::Hint& hint);
/// message, then the hint in brackets when there is one.
std::string with_hint(std::string message, const tape::Hint& hint);

/// IN ("-" = stdin) opened by the library's one entry point: an image by --format, extension or
/// content, or a text program. Failure ends the program.
std::unique_ptr<tape::Input> open_input(const std::string& path, const tape::InputOptions& options);
/// The library's input options for --code/--parity/--charset, --format and --input.
tape::InputOptions input_options(const CodeChoice& choice, const std::string& format_id,
                                 const std::string& kind = "auto");
/// How an image is decoded, the code detected when asked (said with -v); failure ends the program.
const tape::DecodeOptions& decide_code(tape::Input& input, const std::string& name);
/// Reads IN ("-" = stdin) whole as an image: --format, else by extension, else by content.
TapeInput read_tape(const std::string& path, const std::string& format_id);
std::string display_name(const std::string& path);

/// --code (with auto for reading; with the 5-track codes where the command handles them), --parity, --charset.
void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto, bool five_track = false);
/// The image formats of the table that can be read (or written): "raw or holes", and a CLI11 check
/// that accepts exactly their ids. The CLI's --format choices come from here, never from a list of its own.
std::string format_choices(bool for_writing);
std::vector<std::string> format_ids(bool for_writing);
CLI::Validator format_check(bool for_writing);

/// The image format to write OUT in: --format, else by OUT's extension, else raw; fails (usage) for a
/// format that can only be read.
const tape::ImageFormat& output_format(const std::string& format_id, const std::string& path);

/// Fails (usage) when a binary image would go to standard output on a terminal without --force.
void refuse_binary_terminal(const std::string& path, bool binary, bool force);

/// Writes data to OUT ("-" or empty = stdout) atomically; refuses to replace a file without force,
/// and a binary image on a terminal without force.
void write_output(const std::string& path, const std::string& data, bool binary, bool force);

/// Options saying how IN is read: as decode's, plus --input text|image|auto, --dialect, and for the
/// commands that only look (blocks, lint, search) --keep-going past bad frames.
struct ProgramSource {
    CodeChoice choice;
    std::string format;
    std::string kind = "auto";
    std::string dialect = "auto";
    bool keep_going = false;
};
void add_program_source_options(CLI::App* sub, ProgramSource& source, bool with_keep_going = false);
/// --dialect alone (feed reads programs but not through the loader's listing).
void add_dialect_option(CLI::App* sub, std::string& dialect);
tape::LoadOptions load_options(const ProgramSource& source);
/// "dialect fanuc (O program numbers, Custom Macro B)" with -v.
void say_dialect(const std::string& name, const tape::DialectChoice& choice);
/// IN opened for the loader: an image (by --format, extension, or content) decoded with positions,
/// or a text program.
struct ProgramInput {
    std::string name;  ///< for messages
    bool from_tape = false;
    tape::LoadOptions load;
    bool keep_going = false;
    bool damaged = false;  ///< bad frames were read past (--keep-going): the command ends with exit 1
    std::unique_ptr<tape::Input> input;
    tape::LoadedTape tape;  ///< filled by load_program_whole only
};
ProgramInput open_program(const std::string& path, const ProgramSource& source);
/// Streams IN's programs into visitor. A bad frame is printed and ends the program with exit 1, as
/// decode does; so does a text program that is not clean text. With --keep-going the bad frames are
/// printed (or, frames_to_visitor, given to the visitor among its findings) and loading goes on;
/// end_program then ends with exit 1.
void load_program(ProgramInput& in, tape::ProgramVisitor& visitor, bool frames_to_visitor = false);
/// After a --keep-going run over bad frames: says how else the tape reads, and exits 1.
void end_program(const ProgramInput& in);
/// The whole of IN's programs into in.tape, for the commands that need all of it at once.
void load_program_whole(ProgramInput& in);

/// SPEC in the notation of ГОСТ 20999-83 §9; a malformed one ends the program (usage, exit 2).
tape::FormatSpec parse_spec_or_fail(const std::string& text);

/// A JSON string literal for s (UTF-8 passed through, controls escaped).
std::string json_string(const std::string& s);
/// A number, or null.
std::string json_number(const std::optional<std::uint64_t>& n);
/// {"rule", "severity", "frame", "line", "column", "block", "message"}: one finding as tape(1) documents it.
std::string finding_json(const tape::Diagnostic& f);

/// "DETAIL 17 (frames 11-65, ISO letters)": a leader label for people.
std::string label_text(const tape::LeaderLabel& label);
/// {"text", "first_frame", "frames", "code"} or null.
std::string label_json(const std::optional<tape::LeaderLabel>& label);

/// "frame 137" for tapes, "line 3" for text.
std::string position_text(const tape::Location& where, bool from_tape);
std::string position_text(const tape::Position& where, bool from_tape);

}  // namespace cli
