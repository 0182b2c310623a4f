// The tape codes a command offers with --code, from the library's list (tape::all_codes).
#pragma once

#include <CLI/CLI.hpp>

namespace cli {

/// Widens the --code option that add_code_options() put on sub to every code of the library: ISO, EIA,
/// the 5-track codes and the Elliott telecodes (with auto first when with_auto), with help saying which
/// of them detection finds.
void widen_code_option(CLI::App* sub, bool with_auto);

/// The help of --code for all codes.
std::string code_option_help(bool with_auto);

}  // namespace cli
