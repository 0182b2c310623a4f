// tape dnc's configuration file (TOML, read with toml++; see packaging/dnc.toml for a commented sample).
#pragma once

#include <string>

#include "tape/dnc_service.hpp"

namespace cli {

/// Reads the config at path: a [library] table with programs and received, an optional [service]
/// table with runtime_directory, and one [[machine]] table per line with name, device and the
/// settings tape feed and tape receive take. Throws Error(Errc::usage) whose position has the line
/// and whose message names the key and what is wrong (a syntax error, an unknown key, a value of the
/// wrong type or out of range, a machine name or device given twice, a folder that is not there),
/// before any line is opened. Built without toml++: throws Error(Errc::usage) saying so.
tape::dnc::ServiceConfig load_dnc_config(const std::string& path);

}  // namespace cli
