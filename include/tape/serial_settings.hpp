// Serial line settings from the query part of a device string, and the termios they make.
#pragma once

#include <termios.h>

#include <string>
#include <string_view>

#include "tape/device.hpp"

namespace tape {

enum class SerialParity { none, even, odd };

struct SerialSettings {
    std::string path;                 ///< "/dev/ttyUSB0"
    unsigned baud = 9600;
    int data_bits = 8;                ///< 7 or 8
    SerialParity parity = SerialParity::none;
    int stop_bits = 1;                ///< 1 or 2
    Flow flow = Flow::xonxoff;

    /// Characters per second the line carries: baud / (start + data + parity + stop bits).
    double chars_per_second() const;
};

/// Parses "/dev/ttyUSB0?baud=9600&bits=7&parity=even&stop=2&flow=xonxoff". Unknown keys or values
/// are Error(Errc::usage) naming them and what is allowed.
SerialSettings parse_serial_settings(std::string_view rest);

/// The raw-mode termios for settings (no echo, no line editing, no kernel flow control: tape does
/// XON/XOFF itself so that it sees every DC1/DC3; CRTSCTS for rtscts). Throws Error(Errc::usage)
/// for a baud rate termios has no constant for.
termios make_termios(const SerialSettings& settings);

}  // namespace tape
