// What tape-adapter-sim is asked for on its command line: the adapter as built, its tape, and the faults
// to inject. Shared by the options (sim_options.cpp), the board (board.cpp) and main.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "adapter_sim/fault_filter.hpp"

namespace CLI {
class App;
}

namespace tapesim {

struct SimArgs {
    std::string reader, punch, serial = "SIM0001", link, control;
    double speed = 1, read_rate = 1500, punch_rate = 150;
    std::uint32_t stop_frames = 1;
    double control_rate = 1500;
    std::uint64_t control_stops = 0, control_rewind_after = 0, control_reverse_after = 0, control_reverse_frames = 10;
    std::uint32_t control_seed = 1;
    std::uint64_t unplug_after = 0, torn_at = 0, chad_full_after = 0;
    std::vector<std::uint64_t> miss_hole_at, no_sprocket_at, mistimed_at, marginal_at;
    unsigned active_low = 0;
    bool torn = false, no_reader = false, no_punch = false, no_reverse = false, at_end = false, loop = false,
         stats = false;
    tapesim::Faults faults;
};

/// Says "tape-adapter-sim: what" and ends the program with the I/O failure status.
[[noreturn]] void die(const std::string& what);

/// The options of the adapter as built (units, line, clock, control) and of the faults, into a.
void add_unit_options(CLI::App& app, SimArgs& a);
void add_fault_options(CLI::App& app, SimArgs& a);

}  // namespace tapesim
