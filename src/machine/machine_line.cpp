// A machine profile's serial line settings put into a device string (tape feed, tape emulate and the
// DNC service's machine = key take them alike).
#include "device/device_query.hpp"
#include "device/serial_keys.hpp"
#include "tape/machine.hpp"

namespace tape {

// The string's settings are read as the serial backend reads them (so a bad one is refused here as it
// would be when the port is opened); the profile's fill the keys it does not give.
std::string device_with_machine_line(const std::string& device, const MachineLine& l) {
    constexpr std::string_view prefix = "serial:";
    if (!device.starts_with(prefix)) return device;
    DeviceQuery given("serial", std::string_view(device).substr(prefix.size()), serial_keys);
    std::string out = device;
    auto add = [&](std::string_view key, const std::string& value) {
        if (given.value(key)) return;
        out += (out.find('?') == std::string::npos ? "?" : "&") + std::string(key) + "=" + value;
    };
    if (l.baud) add("baud", std::to_string(l.baud));
    if (l.data_bits) add("bits", std::to_string(l.data_bits));
    if (l.stop_bits) add("stop", std::to_string(l.stop_bits));
    if (l.flow) add("flow", *l.flow == Flow::xonxoff ? "xonxoff" : *l.flow == Flow::rtscts ? "rtscts" : "none");
    bool seven_bits = given.value("bits") ? given.value("bits") == "7" : l.data_bits == 7;
    bool even_or_odd = l.parity == Parity::even || l.parity == Parity::odd;
    if (seven_bits && even_or_odd) add("parity", std::string(parity_name(*l.parity)));
    return out;
}

}  // namespace tape
