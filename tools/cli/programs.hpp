// Programs read for the commands that look at them (blocks, lint, search, format): IN opened as an
// image decoded with positions or as a text program, streamed through the loader.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli/options.hpp"
#include "tape/input.hpp"
#include "tape/program.hpp"

namespace cli {

/// Options saying how IN is read: as decode's, plus --input text|image|auto, --dialect, and for the
/// commands that only look (blocks, lint, search) --keep-going past bad frames.
struct ProgramSource {
    CodeChoice choice;
    std::string format;
    std::string kind = "auto";
    std::string dialect = "auto";
    bool keep_going = false;
    bool decided_runs = false;  ///< name the runs a restoration decided against a read (tape::InputOptions)
};
void add_program_source_options(CLI::App* sub, ProgramSource& source, bool with_keep_going = false);
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

}  // namespace cli
