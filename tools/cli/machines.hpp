// --machine NAME|PATH for the commands that read a machine profile (tape/machine.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "tape/machine.hpp"

namespace cli {

/// Adds --machine to sub, into name.
CLI::Option* add_machine_option(CLI::App* sub, std::string& name, const std::string& what);
/// The profile named (nullopt for ""): a profile that is not there or does not read is a usage error,
/// said with its file, line and key.
/// what: the option or command named in the message.
std::optional<tape::MachineProfile> machine_or_fail(const std::string& name, const std::string& what = "--machine");

}  // namespace cli
