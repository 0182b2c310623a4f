// libFuzzer target: device strings ("serial:PATH?baud=...&...", "file:PATH", anything else).
// Nothing is opened: a string with a known prefix goes to the parser of its backend only (serial
// settings; a file path needs no parsing), any other string to open_device, which must refuse it
// with Error(usage) before opening anything.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tape/device.hpp"
#include "tape/error.hpp"
#include "tape/serial_settings.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view device(reinterpret_cast<const char*>(data), size);
    auto colon = device.find(':');
    std::string_view prefix = device.substr(0, colon == std::string_view::npos ? 0 : colon);
    bool known = false;
    for (const auto& b : tape::device_backends())
        known = known || (colon != std::string_view::npos && prefix == b.prefix);
    if (!known) {
        try {
            tape::open_device(device, tape::DeviceUse::read);
        } catch (const tape::Error& e) {
            if (e.code() != tape::Errc::usage) __builtin_trap();
            return 0;
        }
        __builtin_trap();  // a string with no known prefix opened something
    }
    if (prefix != "serial") return 0;
    try {
        tape::SerialSettings s = tape::parse_serial_settings(device.substr(colon + 1));
        if (s.path.empty() || (s.data_bits != 7 && s.data_bits != 8) || (s.stop_bits != 1 && s.stop_bits != 2))
            __builtin_trap();
        if (!(s.chars_per_second() > 0)) __builtin_trap();
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::usage) __builtin_trap();
    }
    return 0;
}
