// The device table: every backend, chosen by the prefix of the device string.
#include "device_backends.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

const DeviceBackend backends[] = {
    {"file", "a tape image file: reads its frames, or writes a new image", "file:PATH", open_file_device},
    {"serial", "a serial port or pseudo-terminal, raw mode",
     "serial:PATH?baud=9600&bits=8&parity=none&stop=1&flow=xonxoff|rtscts|none", open_serial_device},
    {"adapter", "a USB tape adapter (reader, punch) on its CDC serial port, or tape-adapter-sim's",
     "adapter:PATH?tracks=8&invert=0&watchdog=500&sprocket-timeout=50", open_adapter_device},
};

}  // namespace

std::span<const DeviceBackend> device_backends() { return backends; }

std::unique_ptr<Transport> open_device(std::string_view device, DeviceUse use, bool replace) {
    auto colon = device.find(':');
    std::string known;
    for (const auto& b : backends) {
        if (colon != std::string_view::npos && device.substr(0, colon) == b.prefix)
            return b.open(device.substr(colon + 1), use, replace);
        known += (known.empty() ? "" : ", ") + std::string(b.prefix) + ":";
    }
    throw Error(Errc::usage, "'" + std::string(device) + "' names no device; a device string starts with " + known);
}

}  // namespace tape
