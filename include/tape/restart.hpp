// Restarting a program at a block after a tool break: the program's start, the modal state in force
// at the block rebuilt as blocks, then the block and the rest of the program as written.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tape/dialect.hpp"

namespace tape {

/// A program cut to restart at one block.
struct RestartPlan {
    std::string start;               ///< the program's start as written: its '%' line, its "O1234" block
    std::string marker;              ///< "(RESTART AT N50)": a comment block saying what follows
    std::vector<std::string> modal;  ///< the state in force at the block, one block each, in the order sent
    /// After modal: the tool taken to where the block starts, in G90 (retract to the safe height, across
    /// by rapid, down at the feed in force), then the distance mode and motion in force at the block again.
    std::vector<std::string> approach;
    std::string rest;                  ///< the block and all after it to the program's end, as written
    std::string block;                 ///< the block's number as written: "N50"
    std::uint64_t line = 0;            ///< the block's line in the text, from 1
    std::uint64_t skipped_blocks = 0;  ///< blocks before it that are not sent
    Dialect dialect = Dialect::gost;   ///< the dialect the text was read in
    std::string line_end = "\n";       ///< the program's own line end ("\r\n" for a CR LF text), for marker and modal

    /// start, marker, modal, approach and rest, each block ending with the program's line end: the program to send.
    std::string text() const;
    /// start, marker, modal and approach: what `tape feed --show` prints.
    std::string header() const;
};

/// Plans the restart of the program in text at block ("N50", "50" or ":50"; a main block ':50' answers
/// to N50 too). The modal state at the block is rebuilt from the blocks before it: units, plane,
/// absolute/incremental, feed mode, constant surface speed, work offset, tool length and cutter
/// compensation (with their H and D), the motion mode with F, S, the tool an M06 put in the spindle
/// (and a T made ready after it), the spindle and coolant M codes; macro assignments before it are carried in order.
/// Throws Error(Errc::usage) naming the line, and why, where a restart cannot be rebuilt safely: the
/// block is missing or occurs twice, it stands inside a macro loop or a subprogram definition, a
/// subprogram or macro is called before it, a jump (GOTO, IF) or a loop runs before it, a canned cycle
/// or thread cutting is in force at it, coordinates are set from the tool's place (G92, G52) before it,
/// or a modal value is a macro expression. dialect automatic: chosen from the text (guess_dialect).
/// The approach comes from the interpreter (tape/motion.hpp) run over the blocks before the block: the
/// safe height is the highest Z the program reached by rapid in the work offset in force (on a lathe,
/// the largest X: X clear, then Z, then X at the feed). Refused too where the tool's place at the block
/// is not known: an axis never set absolutely (or lost by a reference return or an offset change), a
/// block before it the interpreter does not simulate, dimensions without a decimal point (worth what the
/// control's least increment makes them), cutter compensation in force, no rapid that gives a height,
/// no feed to go down at; a mill program in G18 with no Y is taken for a lathe's unless lathe is said.
RestartPlan plan_restart(std::string_view text, std::string_view block, Dialect dialect = Dialect::automatic,
                         bool lathe = false);

}  // namespace tape
