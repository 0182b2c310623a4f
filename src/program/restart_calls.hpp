// What a restart sends for the subprograms its rest calls (tape/restart.hpp): the interpreter follows
// calls into the text, and so does the control, so the text restarted keeps what they call.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "tape/program.hpp"

namespace tape {

/// The LinuxCNC o-sub definitions written before block index of p, whole lines as written: sent after
/// the program's start, for the calls after the restart block (a definition runs only when called).
std::string definitions_before(const LoadedTape& tape, const Program& p, std::size_t index);

/// Where the rest of a restart at block index of p ends: p's end, or, when a block from index on calls
/// a subprogram (M98) written after p, the end of the text (the programs after it go with it, as they
/// were on the tape).
std::uint64_t rest_end(const LoadedTape& tape, const Program& p, std::size_t index);

}  // namespace tape
