// The settings a serial: device string takes, read by the serial backend and completed from a machine
// profile's line (tape::device_with_machine_line).
#pragma once

#include <string_view>

namespace tape {

inline constexpr std::string_view serial_keys[] = {"baud", "bits", "parity", "stop", "flow"};

}  // namespace tape
