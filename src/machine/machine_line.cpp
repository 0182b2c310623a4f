// A machine profile's serial line settings put into a device string (tape feed, tape emulate and the
// DNC service's machine = key take them alike).
#include <algorithm>

#include "tape/machine.hpp"

namespace tape {

namespace {

// The value of key in a device string's query ("baud" in "serial:/dev/x?baud=9600&flow=none"), or nullopt.
std::optional<std::string> query_value(const std::string& device, const std::string& key) {
    auto q = device.find('?');
    for (std::size_t at = q; at != std::string::npos && at < device.size();) {
        std::size_t end = std::min(device.find('&', at + 1), device.size());
        std::string pair = device.substr(at + 1, end - at - 1);
        if (pair.substr(0, pair.find('=')) == key)
            return pair.find('=') == std::string::npos ? "" : pair.substr(pair.find('=') + 1);
        at = end;
    }
    return std::nullopt;
}

}  // namespace

std::string device_with_machine_line(const std::string& device, const MachineLine& l) {
    if (!device.starts_with("serial:")) return device;
    std::string out = device;
    auto add = [&](const std::string& key, const std::string& value) {
        if (query_value(device, key)) return;
        out += (out.find('?') == std::string::npos ? "?" : "&") + key + "=" + value;
    };
    if (l.baud) add("baud", std::to_string(l.baud));
    if (l.data_bits) add("bits", std::to_string(l.data_bits));
    if (l.stop_bits) add("stop", std::to_string(l.stop_bits));
    if (l.flow) add("flow", *l.flow == Flow::xonxoff ? "xonxoff" : *l.flow == Flow::rtscts ? "rtscts" : "none");
    auto bits = query_value(out, "bits");
    bool even_or_odd = l.parity == Parity::even || l.parity == Parity::odd;
    if (bits == "7" && even_or_odd) add("parity", std::string(parity_name(*l.parity)));
    return out;
}

}  // namespace tape
