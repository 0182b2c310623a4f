// libFuzzer target: the adapter settings of a device string (adapter:PATH?serial=...&tracks=...&...).
// The first byte picks the backend and the use, the rest is the string after "BACKEND:". Nothing is
// opened: a string is either refused as a usage error or gives settings every adapter can take. And a
// serial string of any bytes, put into a device string as `tape devices` writes it, selects exactly
// that serial and nothing else.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "device/adapter_session.hpp"
#include "device/device_query.hpp"
#include "tape/adapter.hpp"
#include "tape/error.hpp"

namespace {

void settings(std::string_view backend, std::string_view rest, tape::DeviceUse use) {
    try {
        tape::DeviceQuery q(backend, rest, tape::adapter::settings_keys);
        tape::adapter::Settings s = tape::adapter::settings_of(q, use);
        if (backend != "adapter") tape::adapter::usb_id(backend, q);
        if (use == tape::DeviceUse::write && s.start.reverse) __builtin_trap();
        if (s.config && (s.config->tracks < 5 || s.config->tracks > 8)) __builtin_trap();
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::usage) __builtin_trap();
    }
}

void serial_round_trip(std::string_view serial) {
    std::string device = tape::adapter::device_string("usb", {0x1209, 0x0001}, serial);
    std::string_view rest = std::string_view(device).substr(4);
    tape::DeviceQuery q("usb", rest, tape::adapter::settings_keys);
    if (q.path() != "1209:0001") __builtin_trap();
    auto got = q.value("serial");
    if (serial.empty() ? got.has_value() : (!got || *got != serial)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static constexpr std::string_view backends[] = {"adapter", "usb", "hid"};
    std::string_view backend = backends[data[0] % 3];
    auto use = static_cast<tape::DeviceUse>((data[0] / 3) % 3);
    std::string_view rest(reinterpret_cast<const char*>(data + 1), size - 1);
    settings(backend, rest, use);
    serial_round_trip(rest);
    return 0;
}
