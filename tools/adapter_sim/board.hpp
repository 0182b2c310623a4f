// The simulated board: the USB adapter's firmware core driving the simulated reader and punch, its
// packets to the host passing the fault filter, on a clock `speed` times real time.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "adapter_sim/fault_filter.hpp"
#include "adapter_sim/port.hpp"
#include "adapter_sim/sim_args.hpp"
#include "adapter_sim/sim_hardware.hpp"
#include "core/engine.hpp"

namespace tapesim {

class Board {
public:
    Board(const SimArgs& a, const std::vector<std::uint8_t>& tape);

    /// Runs the board on the port until Ctrl-C or the unplug asked for; what is punched and what the
    /// control takes are appended to their files as they come (when given).
    void run(const Port& port, std::FILE* punched_out, std::FILE* control_out);

    /// The faults injected, on stderr, when there were any.
    void print_faults() const;
    /// One line of name=value pairs on stderr, for the tests and benchmarks to read what the adapter saw.
    void print_stats() const;

private:
    const SimArgs& a_;
    int fd_ = -1;  ///< the port's
    SimHardware hw_;
    tapefw::Identity id_;
    FaultFilter filter_;
    tapefw::Engine engine_;
    std::string out_;  ///< bytes for the host the port has not taken yet
    std::size_t punched_written_ = 0, taken_written_ = 0;
    std::chrono::steady_clock::time_point t0_{};  ///< when the simulated clock started

    std::uint64_t virtual_now() const;
    void take_input();
    void turn();
    void catch_up();
    void write_punched(std::FILE* to);
    void write_taken(std::FILE* to);
    void send_to_host();
    void wait_for_host();
};

}  // namespace tapesim
