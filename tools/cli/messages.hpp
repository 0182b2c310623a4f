// Messages on stderr: "tape: FILE: frame N: message (hint)", the hints the command line offers, and
// how positions and labels are named for people.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "cli/run.hpp"
#include "tape/error.hpp"
#include "tape/label.hpp"
#include "tape/program.hpp"

namespace cli {

/// "tape: FILE: WHERE: message" on stderr (the program's name first).
void say(const std::string& file, const std::string& message);
/// Prints the error as above and throws Exit with its status.
[[noreturn]] void fail(const std::string& file, const tape::Error& e, bool raw_frames = false);
[[noreturn]] void fail(const std::string& file, tape::Errc code, const std::string& message);

/// "frame 137 (byte 0x88, line 11)": the byte for raw images, where frame N is byte N-1, and the
/// line of the decoded text when known.
std::string where_text(const tape::Position& where, bool raw_frames);

/// Prints one diagnostic: "tape: FILE: frame 12 (byte 0xB): message (hint)".
void say_diagnostic(const std::string& name, const tape::Diagnostic& d, bool raw_frames);
/// "tape: FILE: line 1: note: message" for a finding that is no fault.
void say_note(const std::string& name, const tape::Diagnostic& d);
/// One such line for each kind of bad frame beyond the limit.
void say_unlisted_frames(const std::string& name, const std::map<tape::Errc, std::uint64_t>& unlisted);
/// "12345 more parity error(s) not shown (--max-errors 100)".
void say_unlisted(const std::string& name, std::uint64_t count, const std::string& what);
/// What the command line offers for a hint: "use --force to replace it"; "" for none.
std::string hint_text(const tape::Hint& hint);
/// message, then the hint in brackets when there is one.
std::string with_hint(std::string message, const tape::Hint& hint);

/// "DETAIL 17 (frames 11-65, ISO letters)": a leader label for people.
std::string label_text(const tape::LeaderLabel& label);

/// "frame 137" for tapes, "line 3" for text.
std::string position_text(const tape::Location& where, bool from_tape);
std::string position_text(const tape::Position& where, bool from_tape);

}  // namespace cli
