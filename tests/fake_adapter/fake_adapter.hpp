// A tape adapter in the test process: the firmware core (tapefw::Engine) with a simulated reader and
// punch (tapesim::SimHardware) on a clock running `speed` times real time, behind one of the three
// links the host's backends speak:
//   cdc: a pseudo-terminal, COBS on a byte stream            -> adapter:/dev/pts/N?serial=S
//   usb: a umockdev USB device, vendor bulk endpoints (usbfs) -> usb:1209:0001?serial=S
//   hid: a umockdev hidraw node with a report descriptor      -> hid:1209:0001?serial=S
// The USB transfer is the only double: umockdev stands for the kernel's usbfs and hidraw, the
// firmware core answers. Programs linked with umockdev's preload library (and child processes
// started with it in LD_PRELOAD) see the devices; others see nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "adapter_sim/fault_filter.hpp"
#include "adapter_sim/sim_hardware.hpp"

namespace fake {

/// pico: the RP2040 firmware on an emulated Pico (tests/rp2040/pico_util.hpp), not made by Adapter.
enum class Link { cdc, usb, hid, pico };
const char* link_name(Link link);

struct Options {
    Link link = Link::usb;
    std::string serial = "FAKE0001";
    double speed = 20;
    std::vector<std::uint8_t> tape{};  ///< in the reader
    tapesim::SimOptions sim{};
    tapesim::Faults faults{};
    std::uint64_t unplug_after = 0;  ///< unplugged once this many rows are read (0: never)
};

class Adapter {
public:
    explicit Adapter(Options options);
    ~Adapter();
    Adapter(const Adapter&) = delete;
    Adapter& operator=(const Adapter&) = delete;

    /// The device string the host opens it by.
    const std::string& device() const;
    void unplug();
    /// What the punch punched so far.
    std::vector<std::uint8_t> punched() const;
    /// What the control (Options::sim.control) took so far, and its findings (SimControl::stats_json).
    std::vector<std::uint8_t> control_taken() const;
    std::string control_stats() const;
    std::uint64_t rows_read() const;
    /// Requests the host made that no host should make of this device (an ioctl it has no business
    /// with, a transfer on an endpoint that is not there): each in words. Tests expect none.
    std::vector<std::string> unexpected() const;
    /// Puts garbage on the line to the host, as noise would: bytes on the stream (cdc), a transfer that
    /// is no packet (usb, hid).
    void send_garbage();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Empty when umockdev's devices can be used in this process; else why not.
std::string umockdev_unavailable();

/// LD_PRELOAD for a child process that is to see the fake adapters: umockdev's preload library, after
/// AddressSanitizer's runtime when this program has one (that runtime must be the first library loaded).
std::string child_preload();

}  // namespace fake
