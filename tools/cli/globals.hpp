// Options given before or after the subcommand, shared by every subcommand of a program.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "tape/code.hpp"

namespace cli {

/// The largest --eia-table file taken (a table is a few kilobytes of text).
inline constexpr std::uint64_t max_table_bytes = 1 << 20;

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

}  // namespace cli
