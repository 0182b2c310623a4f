// Serial line settings from the settings part of a device string.
#pragma once

#include <string>
#include <string_view>

#include "tape/device.hpp"

namespace tape {

enum class SerialParity { none, even, odd };

struct SerialSettings {
    std::string path;  ///< "/dev/ttyUSB0"
    unsigned baud = 9600;
    int data_bits = 8;  ///< 7 or 8
    SerialParity parity = SerialParity::none;
    int stop_bits = 1;  ///< 1 or 2
    Flow flow = Flow::xonxoff;

    /// Characters per second the line carries: baud / (start + data + parity + stop bits).
    double chars_per_second() const;
};

/// Parses "/dev/ttyUSB0?baud=9600&bits=7&parity=even&stop=2&flow=xonxoff". Throws Error(Errc::usage)
/// naming an unknown key, a key given twice, a value out of its range (listing what is allowed),
/// a baud rate that is no standard rate, or bits=7 without parity.
SerialSettings parse_serial_settings(std::string_view rest);

}  // namespace tape
