// The reader emulator running on one side of a pseudo-terminal, the controller's side (master) left to
// the benchmark: shared by emulate_bench and adapter_bench's stops on DC3.
#pragma once

#include <pty.h>
#include <unistd.h>

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "tape/device.hpp"
#include "tape/dnc.hpp"
#include "tape/encode.hpp"

/// A tape of at least chars characters of program, with no end of program to rewind at.
inline std::vector<tape::Frame> long_program_tape(std::size_t chars) {
    std::string text = "%\n";
    for (int n = 1; text.size() < chars; ++n)
        text += "N" + std::to_string(n) + " G01 X+" + std::to_string(n) + ".5 F120\n";
    return tape::encode(text, tape::EncodeOptions{.leader = 0, .trailer = 0});
}

class EmulatorOnPty {
public:
    /// Starts emulating tape at rate frames/s; master is -1 when no pseudo-terminal could be had.
    EmulatorOnPty(const std::vector<tape::Frame>& tape, double rate) {
        char name[128];
        if (::openpty(&master, &slave_, name, nullptr, nullptr) != 0) {
            master = -1;
            return;
        }
        line_ = tape::open_device(std::string("serial:") + name + "?baud=115200&flow=xonxoff", tape::DeviceUse::both);
        emulator_ = std::thread([this, &tape, rate] {
            tape::emulate_reader(*line_, tape, tape::EmulatorOptions{.rate = rate, .stop = &stop_});
        });
    }
    ~EmulatorOnPty() {
        stop_ = true;
        if (emulator_.joinable()) emulator_.join();
        line_.reset();
        if (master >= 0) {
            ::close(master);
            ::close(slave_);
        }
    }
    EmulatorOnPty(const EmulatorOnPty&) = delete;
    EmulatorOnPty& operator=(const EmulatorOnPty&) = delete;

    int master = -1;  ///< the controller's side

private:
    int slave_ = -1;
    std::unique_ptr<tape::Transport> line_;
    std::atomic<bool> stop_{false};
    std::thread emulator_;
};
