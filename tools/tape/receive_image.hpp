// Receiving frames from a device into a tape image (read, receive), nothing already received lost.
#pragma once

#include <string>

#include "tape/dnc.hpp"

namespace cli {

/// Receives frames from device into the image output as they arrive (receive, read): Ctrl-C and a
/// progress line wired here; a device failure ends the program with status 3. Returns how it ended.
tape::ReceiveResult::End receive_into_image(const std::string& device, const std::string& output,
                                            const std::string& format_id, bool force, tape::ReceiveOptions o,
                                            bool progress_forced, const char* verb);

}  // namespace cli
