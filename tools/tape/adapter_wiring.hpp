// tape adapter config's options for the emulate role: how the adapter is wired to a control's
// tape-reader input (sent as a WIRING when any of them is given), and the wiring in words.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "tape/adapter.hpp"

namespace cli {

struct WiringArgs {
    tape::AdapterWiring wiring;
    bool given = false;  ///< some option of the wiring was given
};

/// Adds the wiring options to tape adapter config, in a group of their own.
void add_wiring_options(CLI::App& config, const std::shared_ptr<WiringArgs>& args);
/// Takes what the parse left (which options were given, the tracks shared with the reader).
void finish_wiring(CLI::App& config, WiringArgs& args, unsigned tracks);
std::string wiring_text(const tape::AdapterWiring& w);

}  // namespace cli
