// A bash completion script made from the command-line parser itself: it names every subcommand and
// option the program has, and no other, so it cannot fall behind the program.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace cli {

/// The script for `program`: completes its subcommands (nested ones too) and each command's options;
/// an option's value, and any other word, as a file name.
std::string bash_completion(const CLI::App& app, const std::string& program);

/// Adds the hidden flag --bash-completion, which prints that script and ends (for `cmake --install` and
/// packagers; see tape(1), FILES).
void add_bash_completion_flag(CLI::App& app, const std::string& program);

}  // namespace cli
