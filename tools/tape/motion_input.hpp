// A program's moves for the commands that look at them (plot, diff --motion, info --motion): its text or
// tape streamed through the loader into the interpreter (tape/motion.hpp). Bad frames of a tape are read
// past: their frames are given back, for the commands to mark the moves read from them.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli/programs.hpp"
#include "tape/format_spec.hpp"
#include "tape/machine.hpp"
#include "tape/motion.hpp"

namespace cli {

/// What the tape does not say about the machine.
struct MotionArgs {
    bool lathe = false;
    std::string spec;     ///< --spec: the control's word formats, for the implied point of words without one
    std::string machine;  ///< --machine: lathe or mill, diameters, word formats, arc tolerance, rapid rates
};
/// --lathe and --spec, and --machine unless the command has its own (with_machine false).
void add_motion_options(CLI::App* sub, MotionArgs& args, bool with_machine = true);
/// The machine's profile, when --machine names one: loaded once, kept for the options that point into it.
const tape::MachineProfile* motion_machine(const MotionArgs& args);
/// The interpreter's options (spec, when given, must outlive them).
tape::MotionOptions motion_options(const ProgramSource& source, const MotionArgs& args,
                                   const std::optional<tape::FormatSpec>& spec);

struct MotionRead {
    std::string name;
    bool from_tape = false;
    std::vector<std::uint64_t> bad_frames;  ///< frames read past as bad (1-based)
    ProgramInput in;
};

/// IN's programs interpreted into out; on_block, when given, sees each block before the interpreter.
MotionRead read_motion(const std::string& path, const ProgramSource& source, const MotionArgs& args,
                       tape::MotionVisitor& out, const std::function<void(const tape::Block&)>& on_block = {});
/// After the command's output: exit 1 when bad frames were read past (said as decode says them).
void end_motion(const MotionRead& read);

/// "tape: FILE: line 12: not simulated: ..." for each move not simulated kept, and how many more.
void say_not_simulated(const std::string& name, const std::vector<tape::Move>& kept, std::uint64_t count,
                       bool from_tape);

}  // namespace cli
