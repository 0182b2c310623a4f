// What a signal does to a run: an output's temporary file removed, or a device run stopped cleanly.
#pragma once

#include <atomic>

namespace cli {

/// SIGINT, SIGTERM, SIGHUP and SIGQUIT remove an output's temporary file, then end the run as the
/// signal would. Device runs replace this with their own stop flag.
void install_output_cleanup();

/// Set by SIGINT, SIGTERM or SIGHUP once install_interrupt_handler() ran; device runs stop cleanly on it.
std::atomic<bool>& interrupted();
void install_interrupt_handler();

}  // namespace cli
