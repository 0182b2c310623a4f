// What serial settings mean to the kernel: the raw-mode termios. Kept out of the public headers, so
// that a program using the library does not get <termios.h> and its macros (B9600, ECHO, ...).
#pragma once

#include <termios.h>

#include "tape/serial_settings.hpp"

namespace tape {

/// The raw-mode termios for settings (no echo, no line editing, no kernel flow control: tape does
/// XON/XOFF itself so that it sees every DC1/DC3; CRTSCTS for rtscts). Throws Error(Errc::usage)
/// for a baud rate termios has no constant for.
termios make_termios(const SerialSettings& settings);

}  // namespace tape
