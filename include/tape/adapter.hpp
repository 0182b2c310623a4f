// USB tape adapters (docs/adapter-protocol.md): what one says about itself, and a self-test of its
// link. Reading and punching go through the ordinary devices (tape/device.hpp, adapter:PATH).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/dnc.hpp"

namespace tape {

/// An adapter's INFO reply.
struct AdapterInfo {
    int protocol = 0;
    std::string firmware;  ///< "1.2.3"
    std::string serial;
    bool reader = false, punch = false, reverse = false, row_flags = false;
    bool emulate = false;                            ///< stands in for a tape reader toward a control (tape emulate)
    std::vector<int> tracks;                         ///< tape widths it handles, from 5 to 8
    unsigned max_read_rate = 0, max_punch_rate = 0;  ///< frames per second
    unsigned read_buffer = 0, punch_buffer = 0;      ///< rows
};

/// Opens the adapter ("adapter:PATH"), resets it and asks for its info. Blocks up to about a second.
/// Throws Error(Errc::usage) for a device string that names no adapter, Error(Errc::io) when it does
/// not answer or speaks another protocol version.
AdapterInfo adapter_info(std::string_view device);

/// What a link self-test measured.
struct AdapterSelftest {
    std::uint64_t packets = 0;     ///< echoes sent and answered
    std::uint64_t bytes = 0;       ///< payload bytes each way
    std::uint64_t mismatches = 0;  ///< echoes that came back different (each one is a link fault)
    std::uint64_t bad_in = 0;      ///< packets from the adapter that failed their CRC
    std::uint64_t bad_out = 0;     ///< packets of ours the adapter reported as failing theirs
    double seconds = 0;
    double round_trip_ms = 0;  ///< the mean time from an echo sent to its answer
};

/// Sends pseudo-random payloads (from seed) to the adapter's ECHO for duration and checks every answer.
/// Throws as adapter_info does, and Error(Errc::io) when an echo is not answered after retries.
AdapterSelftest adapter_selftest(std::string_view device, std::chrono::milliseconds duration, std::uint32_t seed = 1);

/// An adapter's line settings (CONFIG): how its unit is wired and timed. docs/adapter-protocol.md says
/// what to measure on a unit for each. A CONFIG sets every one at once; the adapter keeps them over a
/// reset, until the next CONFIG or a power-up.
struct AdapterConfig {
    unsigned data_invert = 0;           ///< bit n: data line n is active low (a hole reads as a low level); 0 to 255
    unsigned tracks = 8;                ///< 5 to 8: rows are masked to that many tracks
    bool sprocket_low = false;          ///< the sprocket signal is active low
    bool strobe_falling = false;        ///< sample on the falling edge of the sprocket, not the rising one
    bool drive_pulse = false;           ///< start and stop are pulses of drive_pulse_us, not a level
    bool drive_low = false;             ///< start/stop and direction lines are active low
    bool status_low = false;            ///< tape-out and fault inputs are active low
    bool punch_ready_low = false;       ///< the punch's ready (sync) input is active low
    bool punch_magnet_low = false;      ///< the punch magnets are driven by a low level
    unsigned sample_delay_us = 50;      ///< from the sprocket edge to sampling the data lines; 0 to 5000
    unsigned punch_pulse_us = 2500;     ///< how long the punch magnets are held; 100 to 50000
    unsigned drive_pulse_us = 1000;     ///< start and stop pulse length; 10 to 50000
    unsigned sprocket_timeout_ms = 50;  ///< no sprocket this long while driving: torn tape; 1 to 65535
    unsigned watchdog_ms = 500;         ///< host silent this long: reader and punch stopped; 0 (never) to 65535
};

/// Why a setting is out of its range ("tracks: 9 is not 5 to 8"), or "" when every one is in range.
std::string adapter_config_problem(const AdapterConfig& config);

/// Opens the adapter, resets it and sends config, waiting for its OK. Throws Error(Errc::usage) for a
/// setting out of range (adapter_config_problem) or a device string that names no adapter, and
/// Error(Errc::io) when the adapter does not answer or refuses the settings.
void adapter_configure(std::string_view device, const AdapterConfig& config);

}  // namespace tape

namespace tape {

/// A USB serial port or a tape adapter's interface found in sysfs: a tape adapter (by its vendor and
/// product id) or another serial port.
struct AttachedPort {
    std::string
        device;  ///< "adapter:/dev/ttyACM0", "usb:1209:0001?serial=S", "hid:1209:0001?serial=S", "serial:/dev/ttyUSB0"
    std::uint16_t vendor = 0, product = 0;
    std::string serial;       ///< the USB serial string ("" when it has none)
    std::string description;  ///< manufacturer and product strings
    bool adapter = false;     ///< 1209:0001, a tape adapter
};

/// Under sysfs_root (/sys), each without opening anything: the USB serial ports (class/tty/NAME/device,
/// up to the USB device with its idVendor), named under dev_root (/dev); and the tape adapters' vendor
/// interfaces (bus/usb/devices, class ff) and HID interfaces (class/hidraw). An adapter offering several
/// interfaces is listed once for each. Adapters first, by serial, then the other ports, by device.
std::vector<AttachedPort> attached_ports(const std::string& sysfs_root = "/sys", const std::string& dev_root = "/dev");

}  // namespace tape

namespace tape {

/// True for a device string of a USB tape adapter backend (adapter:, usb:, hid:).
bool is_adapter_device(std::string_view device);

/// tape emulate through a USB tape adapter wired to a control's tape-reader input (the emulate role):
/// the adapter strobes the frames toward the control while its start line is on and obeys its stop
/// itself; this side keeps the adapter's queue full and follows, by the frame counter, every frame the
/// control took. At the end of a program (the block with M02/M30) the tape is rewound to its '%' stop,
/// given again once the control has stopped; a control's rewind line rewinds there too, its direction
/// line reads backwards from where the tape stands. Runs until options.stop is set; progress is called
/// a few times a second. options.rate, flow, start, stop_code, search and rewind are the serial line's
/// and not used: the frame rate is the adapter's wiring (adapter_configure_emulation). Throws
/// Error(Errc::usage) for a device string that names no adapter, Error(Errc::io) for an adapter without
/// the role, gone, silent, or stopped by its watchdog (the host was silent).
EmulatorResult adapter_emulate(std::string_view device, std::span<const Frame> tape, const EmulatorOptions& options,
                               const std::function<void(const LineProgress&)>& progress = {});

/// How an adapter is wired to a control's tape-reader input, and its timing (the WIRING message). The
/// adapter keeps it over a reset, as the line settings. Pins are the board's own numbers (GPIO n).
struct AdapterWiring {
    std::vector<unsigned> data_pins{0, 1, 2, 3, 4, 5, 6, 7};  ///< track 1 first; as many as tracks
    unsigned strobe_pin = 8;
    unsigned run_pin = 9;                   ///< the control's start/stop line
    std::optional<unsigned> reverse_pin{};  ///< its direction line, where the interface has one
    std::optional<unsigned> rewind_pin{};   ///< its rewind line, where the interface has one
    unsigned data_invert = 0;               ///< bit n: data line n is driven low for a hole
    unsigned tracks = 8;                    ///< 5 to 8
    bool strobe_low = false, run_low = false, reverse_low = false, rewind_low = false;
    unsigned braking = 1;  ///< frames the control may still see after its stop, 0 to 2
    unsigned rate = 1500;  ///< frames per second, 1 to 4000
    unsigned strobe_us = 100, setup_us = 50, hold_us = 50;
    unsigned start_delay_us = 1000;  ///< from the control's start to the first frame's slot
};

/// Why a wiring cannot work, or "" when it can.
std::string adapter_wiring_problem(const AdapterWiring& wiring);

/// Opens the adapter, resets it and sends the wiring, waiting for its OK. Throws as adapter_configure.
void adapter_configure_emulation(std::string_view device, const AdapterWiring& wiring);

}  // namespace tape
