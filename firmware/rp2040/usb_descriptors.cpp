#include "rp2040/usb_descriptors.hpp"

#include "core/protocol.hpp"

namespace rp2040::usbdesc {
namespace {

constexpr std::uint8_t lo(std::uint16_t v) { return static_cast<std::uint8_t>(v & 0xFF); }
constexpr std::uint8_t hi(std::uint16_t v) { return static_cast<std::uint8_t>(v >> 8); }

constexpr std::uint8_t device_descriptor[18] = {
    18,
    1,  // bLength, DEVICE
    0x00,
    0x02,  // bcdUSB 2.00
    0x02,
    0x00,
    0x00,        // class CDC; subclass and protocol per interface
    max_packet,  // bMaxPacketSize0
    lo(tapefw::usb_vendor_id),
    hi(tapefw::usb_vendor_id),
    lo(tapefw::usb_product_id),
    hi(tapefw::usb_product_id),
    0x00,
    0x01,  // bcdDevice 1.00
    string_manufacturer,
    string_product,
    string_serial,
    1,  // bNumConfigurations
};

constexpr std::uint16_t config_total = 9 + 9 + 5 + 5 + 4 + 5 + 7 + 9 + 7 + 7;
constexpr std::uint8_t config_descriptor[config_total] = {
    9,
    2,
    lo(config_total),
    hi(config_total),
    2,
    1,
    0,
    0x80,
    50,  // 2 interfaces, bus powered, 100 mA
    // Interface 0: CDC communication, abstract control model, no AT-command protocol (0).
    9,
    4,
    0,
    0,
    1,
    0x02,
    0x02,
    0x00,
    0,
    5,
    0x24,
    0x00,
    0x20,
    0x01,  // header functional descriptor, CDC 1.20
    5,
    0x24,
    0x01,
    0x00,
    1,  // call management: none; data interface 1
    4,
    0x24,
    0x02,
    0x02,  // ACM: SET/GET_LINE_CODING, SET_CONTROL_LINE_STATE
    5,
    0x24,
    0x06,
    0,
    1,  // union: master 0, slave 1
    7,
    5,
    ep_notify,
    0x03,
    8,
    0,
    16,  // interrupt IN, 8 bytes, every 16 ms
    // Interface 1: CDC data, bulk OUT and IN.
    9,
    4,
    1,
    0,
    2,
    0x0A,
    0x00,
    0x00,
    0,
    7,
    5,
    ep_data_out,
    0x02,
    lo(max_packet),
    hi(max_packet),
    0,
    7,
    5,
    ep_data_in,
    0x02,
    lo(max_packet),
    hi(max_packet),
    0,
};

constexpr std::uint8_t languages[4] = {4, 3, 0x09, 0x04};  // English (United States)

}  // namespace

Bytes device() { return {device_descriptor, sizeof device_descriptor}; }
Bytes configuration() { return {config_descriptor, sizeof config_descriptor}; }

Bytes string(std::uint8_t index, const char* serial, std::uint8_t (&buffer)[64]) {
    if (index == 0) return {languages, sizeof languages};
    const char* text = index == string_manufacturer ? manufacturer
                       : index == string_product    ? product
                       : index == string_serial     ? serial
                                                    : nullptr;
    if (!text) return {nullptr, 0};
    std::size_t n = 0;
    while (text[n] && n < 31) {
        buffer[2 + 2 * n] = static_cast<std::uint8_t>(text[n]);
        buffer[3 + 2 * n] = 0;
        ++n;
    }
    buffer[0] = static_cast<std::uint8_t>(2 + 2 * n);
    buffer[1] = 3;
    return {buffer, 2 + 2 * n};
}

}  // namespace rp2040::usbdesc
