// The device table: every backend, chosen by the prefix of the device string.
#include <vector>

#include "device_backends.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

using PipeOpener = std::unique_ptr<adapter::PacketPipe> (*)(const DeviceQuery& query);

struct Backend {
    DeviceBackend device;
    /// Tape adapters only: the packet pipe alone, for the adapter's own questions (info, self-test).
    PipeOpener pipe = nullptr;
};

/// The device of an adapter backend: its pipe, with the session and settings all of them share.
template <const std::string_view& prefix, PipeOpener pipe>
std::unique_ptr<Transport> open_adapter(std::string_view rest, DeviceUse use, bool) {
    DeviceQuery query(prefix, rest, adapter::settings_keys);
    adapter::Settings settings = adapter::settings_of(query, use);  // a bad setting before the adapter is opened
    return adapter::open_transport(pipe(query), settings, use);
}

constexpr std::string_view cdc = "adapter", usb = "usb", hid = "hid";

const Backend backends[] = {
    {{"file", "a tape image file: reads its frames, or writes a new image", "file:PATH", open_file_device}},
    {{"serial", "a serial port or pseudo-terminal, raw mode",
      "serial:PATH?baud=9600&bits=8&parity=none&stop=1&flow=xonxoff|rtscts|none", open_serial_device}},
    {{cdc, "a USB tape adapter (reader, punch) on its CDC serial port, or tape-adapter-sim's",
      "adapter:PATH?serial=SERIAL&direction=forward|reverse&tracks=8&invert=0&watchdog=500&sprocket-timeout=50",
      open_adapter<cdc, open_cdc_pipe>},
     open_cdc_pipe},
    {{usb, "a USB tape adapter on its vendor bulk endpoints, through libusb",
      "usb:1209:0001?serial=SERIAL&direction=forward|reverse&tracks=8&invert=0&watchdog=500&sprocket-timeout=50",
      open_adapter<usb, open_usb_pipe>},
     open_usb_pipe},
    {{hid, "a USB tape adapter on its HID interface (hidraw), through hidapi",
      "hid:1209:0001?serial=SERIAL&direction=forward|reverse&tracks=8&invert=0&watchdog=500&sprocket-timeout=50",
      open_adapter<hid, open_hid_pipe>},
     open_hid_pipe},
};

const Backend* find_backend(std::string_view device, std::string& known) {
    auto colon = device.find(':');
    for (const auto& b : backends) {
        if (colon != std::string_view::npos && device.substr(0, colon) == b.device.prefix) return &b;
        known += (known.empty() ? "" : ", ") + std::string(b.device.prefix) + ":";
    }
    return nullptr;
}

}  // namespace

std::span<const DeviceBackend> device_backends() {
    static const std::vector<DeviceBackend> list = [] {
        std::vector<DeviceBackend> v;
        for (const auto& b : backends) v.push_back(b.device);
        return v;
    }();
    return list;
}

std::unique_ptr<Transport> open_device(std::string_view device, DeviceUse use, bool replace) {
    std::string known;
    if (const Backend* b = find_backend(device, known))
        return b->device.open(device.substr(device.find(':') + 1), use, replace);
    throw Error(Errc::usage, "'" + std::string(device) + "' names no device; a device string starts with " + known);
}

namespace {
const Backend& adapter_backend(std::string_view device) {
    std::string known;
    const Backend* b = find_backend(device, known);
    if (!b || !b->pipe)
        throw Error(Errc::usage, "'" + std::string(device) +
                                     "' names no adapter: give adapter:/dev/ttyACM0, usb:1209:0001 or hid:1209:0001");
    return *b;
}
}  // namespace

std::unique_ptr<adapter::PacketPipe> adapter::open_pipe(std::string_view device) {
    const Backend& b = adapter_backend(device);
    return b.pipe(DeviceQuery(b.device.prefix, device.substr(device.find(':') + 1), adapter::settings_keys));
}

std::unique_ptr<adapter::PacketPipe> adapter::open_pipe(std::string_view device, DeviceUse use, Settings& settings) {
    const Backend& b = adapter_backend(device);
    DeviceQuery query(b.device.prefix, device.substr(device.find(':') + 1), adapter::settings_keys);
    settings = settings_of(query, use);  // a bad setting before the adapter is opened
    return b.pipe(query);
}

}  // namespace tape
