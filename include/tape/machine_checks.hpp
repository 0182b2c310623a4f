// What a machine profile says about a program: the word format its blocks are held to as format-changing
// codes switch it (the Н22-1М's G10 "long dimensions"), its feed, speed and prefixed words, and what
// each code means on the machine.
#pragma once

#include <functional>
#include <string>

#include "tape/machine.hpp"
#include "tape/program.hpp"

namespace tape {

/// The word format of a profile block by block. Fed a program's blocks in order; a copy keeps the mode
/// where it was made (restore keeps one where each damaged block begins).
class MachineFormat {
public:
    explicit MachineFormat(const MachineProfile& p);
    /// A new program starts in the profile's initial mode.
    void program_start();
    /// Takes block b's format-changing codes into account (they act in their own block) and returns the
    /// format its words are held to.
    const FormatSpec& block(const Block& b);
    /// " (G10 in effect: long dimensions, 6 digits)" for a word the mode's digits apply to, else "".
    std::string note(const Word& w) const;

private:
    const MachineProfile* p_;
    const FormatMode* mode_ = nullptr;
    std::string selected_by_;  // "G10", or "" for the initial mode
};

/// The profile's checks of a block beyond the word format, each finding given to out: a feed word's
/// first digit outside the feed code table (machine-feed-code), a prefixed word's first digit other
/// than 0 or 1 (machine-prefix), a speed code outside a complete speed table (machine-speed-code).
/// Words whose digit count is off the format are left to the format's check: what their digits mean
/// is not known.
void machine_checks(const MachineProfile& p, const Block& b, const std::function<void(Finding)>& out);

/// What each G, M, F, S and T word of block b means on the machine ("G10 linear interpolation, long
/// dimensions (6 digits), M104 spindle counter-clockwise after the machine's acknowledgement"); G and
/// M codes the profile does not have are named by its dialect's table when it names them. Russian
/// with russian where the profile has it.
std::string explain_machine_codes(const Block& b, const MachineProfile& p, bool russian);

}  // namespace tape
