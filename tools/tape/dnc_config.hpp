// tape dnc's configuration file (TOML, read with toml++; see packaging/dnc.toml for a commented sample).
#pragma once

#include <string>
#include <string_view>

#include "tape/dnc_service.hpp"

namespace cli {

/// Reads the config at path: a [library] table with programs and received, an optional [service]
/// table with runtime_directory, and one [[machine]] table per line with name, device and the
/// settings tape feed and tape receive take. Throws Error(Errc::usage) whose position has the line
/// and whose message names the key and what is wrong (a syntax error, an unknown key, a value of the
/// wrong type or out of range, a machine name or device given twice, a folder that is not there),
/// before any line is opened. Built without toml++: throws Error(Errc::usage) saying so.
/// A folder, a FIFO or a device is refused by name (SIGHUP reads the file again), as is a file over 1 MiB.
tape::dnc::ServiceConfig load_dnc_config(const std::string& path);
/// The same from the file's text; path names it in the config and in messages.
tape::dnc::ServiceConfig parse_dnc_config(std::string_view text, const std::string& path);

/// The control socket of the service run with the config at path: only [service] runtime_directory is
/// read, nothing else checked, so that tape dnc status works for a file another user could not serve
/// with, or one half edited. Throws Error(Errc::usage) for a file that is no TOML or whose
/// runtime_directory is no string, Error(Errc::io) when it cannot be read.
std::string dnc_control_socket(const std::string& path);

}  // namespace cli
