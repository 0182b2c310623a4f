// The adapter's USB descriptors (USB 2.0 chapter 9; CDC 1.20 and its PSTN subclass for ACM): one
// configuration with a CDC communication interface (ACM, no AT-command protocol, an interrupt IN
// endpoint for notifications) and a CDC data interface (bulk IN and OUT, 64 bytes), under this
// project's vendor and product id (firmware/core/protocol.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace rp2040::usbdesc {

inline constexpr std::uint8_t ep_notify = 0x83, ep_data_in = 0x81, ep_data_out = 0x02;
inline constexpr std::uint16_t max_packet = 64;
inline constexpr std::uint8_t string_manufacturer = 1, string_product = 2, string_serial = 3;
inline constexpr const char* manufacturer = "tape project";
inline constexpr const char* product = "tape adapter";

struct Bytes {
    const std::uint8_t* data;
    std::size_t size;
};
Bytes device();
Bytes configuration();
/// String descriptor index (0: the language ids); serial is the serial string. Empty past the last.
/// Built into buffer (UTF-16LE, at most 31 characters).
Bytes string(std::uint8_t index, const char* serial, std::uint8_t (&buffer)[64]);

}  // namespace rp2040::usbdesc
