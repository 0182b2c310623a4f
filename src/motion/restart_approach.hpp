// The approach of a restart (tape/restart.hpp): where the tool must stand when the restart block runs,
// from the interpreter run over the blocks before it, and the blocks that take it there safely.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tape/dialect.hpp"
#include "tape/program.hpp"

namespace tape {

struct ApproachInput {
    const Program* program = nullptr;
    std::size_t index = 0;  ///< the restart block's index in program->blocks
    Dialect dialect = Dialect::gost;
    bool lathe = false;
    std::string feed;           ///< the F word in force as written ("F100."), empty when none
    bool inverse_time = false;  ///< G93 in force: an F is per block, none can be carried to the approach
};

/// The approach blocks, in the program's units and in G90: retract (mill: Z to the highest Z reached by
/// rapid; lathe: X to the largest), rapid to the start point across, feed to it at the F in force.
/// Throws Error(Errc::usage) where the tool's place at the block is not known from the text.
std::vector<std::string> restart_approach(const ApproachInput& in);

}  // namespace tape
