// A loaded program written out again for a controller's format (ГОСТ 20999-83 §9): explicit or
// implied decimal point, digits and signs as the format wants them.
#pragma once

#include <string>
#include <vector>

#include "tape/error.hpp"
#include "tape/format_spec.hpp"
#include "tape/program.hpp"

namespace tape {

struct MachineProfile;

struct ReformatOptions {
    const FormatSpec* spec = nullptr;  ///< the format to write (required unless machine)
    const FormatSpec* from = nullptr;  ///< the format the program is written in, for implied points
    bool strip_zeros = false;          ///< leave out leading (or trailing) zeros where the format allows
    bool spaces = false;               ///< a space between words
    /// Write for this machine instead of spec: each block in the format its format-changing codes set
    /// (tape/machine_checks.hpp). A word with an explicit point for an axis whose words are pulses
    /// (MachineAxis::mm_per_pulse) cannot be written: millimetres are not converted to pulses.
    const MachineProfile* machine = nullptr;
};

/// The text of tape rewritten for options.spec: label, programs, blocks and the text after each end,
/// in tape order. What cannot be written is reported in findings (rules "spec-skip" and the word's
/// format error as "spec-word", errors; "implied-point", a warning, when a program without --from
/// writes no decimal point at all); a caller should not use the text when an error was found.
std::string reformat(const LoadedTape& tape, const ReformatOptions& options, std::vector<Diagnostic>& findings);

}  // namespace tape
