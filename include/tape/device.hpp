// Devices: a small Transport per backend (file, serial), chosen by a device string from one table.
//   file:PATH
//   serial:/dev/ttyUSB0?baud=9600&bits=7&parity=even&stop=2&flow=xonxoff|rtscts|none
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

/// Flow control on a line.
enum class Flow {
    none,
    xonxoff,  ///< DC1 (XON) resume, DC3 (XOFF) pause, in band; done by tape, not by the kernel
    rtscts,   ///< CTS from the other side allows sending; RTS asserted while we accept data
};

/// What one read returned.
struct ReadResult {
    std::size_t count = 0;  ///< bytes stored (0 on time-out or end)
    bool end = false;       ///< the other side hung up, or a file ended: no more will come
};

/// A run of frames a reader itself doubts, alike, counted from 1 in the order they came.
struct FrameDoubt {
    std::uint64_t first = 0, last = 0;
    std::string what;  ///< "read without a sprocket hole (sampled by time)"
};
struct FrameDoubts {
    std::vector<FrameDoubt> runs;
    std::uint64_t unkept = 0;  ///< doubtful frames only counted, beyond the runs a device keeps
};

/// Modem control lines, where a transport has them (serial ports do, files and ptys do not).
class ModemLines {
public:
    virtual ~ModemLines() = default;
    /// True when the other side asserts CTS (it will accept data).
    virtual bool cts() = 0;
    /// Asserts or drops RTS (we will accept data).
    virtual void set_rts(bool on) = 0;
};

/// One open device. All calls may throw Error(Errc::io) naming the device and the system's reason.
class Transport {
public:
    virtual ~Transport() = default;
    /// Reads up to buffer.size() bytes, waiting at most timeout (0: do not wait). Never blocks longer.
    virtual ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) = 0;
    /// Writes all bytes, blocking until the kernel has taken them. Throws when the other side hung up.
    virtual void write(std::span<const std::uint8_t> bytes) = 0;
    /// Waits until everything written has left (tcdrain for serial; flush for files).
    virtual void drain() = 0;
    /// The modem lines, or nullptr when the transport has none.
    virtual ModemLines* modem() { return nullptr; }
    /// Flow control the device string asked for.
    virtual Flow flow() const { return Flow::none; }
    /// Characters per second the line carries (0: as fast as it goes), for pacing.
    virtual double line_rate() const { return 0; }
    /// True when bytes written go out with 7 data bits (the UART adds the parity): track 8 is dropped.
    virtual bool seven_bit() const { return false; }
    /// As given, for messages.
    virtual std::string name() const = 0;
    /// What the transport recovered from on its own since the last call (frames a USB adapter sent
    /// again after a lost or damaged packet), one line each, for a verbose report. Empty for most.
    virtual std::vector<std::string> take_notes() { return {}; }
    /// Frames the device itself doubts since the last call (a tape adapter's row flags: read without a
    /// sprocket hole, mistimed, a level near its threshold). Empty for most.
    virtual FrameDoubts take_doubts() { return {}; }
    /// True when frames come last first: a tape adapter's reader reading backwards.
    virtual bool backwards() const { return false; }
    /// The widest tape the device reads or punches: 8 tracks (any byte) for lines and most units, 5
    /// for a 5-track one (a tape adapter set to tracks=5, a 5-track image file). An output must hold it.
    virtual int tracks() const { return 8; }
};

/// What a backend is opened for.
enum class DeviceUse { read, write, both };

/// One backend: an entry of the table in device.cpp.
struct DeviceBackend {
    std::string_view prefix;  ///< "file", "serial"
    std::string_view description;
    std::string_view syntax;  ///< "file:PATH"
    /// Opens the part after "prefix:". replace: an existing output may be replaced.
    std::unique_ptr<Transport> (*open)(std::string_view rest, DeviceUse use, bool replace);
};

/// The file a "file:" device string's rest names, checked as the file backend checks it (no settings
/// after '?'): for callers that write a whole image to it at once. Throws Error(Errc::usage).
std::string file_device_path(std::string_view rest);

/// All backends, in the order `tape devices` lists them.
std::span<const DeviceBackend> device_backends();

/// Opens "prefix:rest". A string without a known prefix is an error (Errc::usage) listing the prefixes.
std::unique_ptr<Transport> open_device(std::string_view device, DeviceUse use, bool replace = false);

}  // namespace tape
