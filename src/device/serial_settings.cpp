#include "tape/serial_settings.hpp"

#include "device_query.hpp"
#include "serial_keys.hpp"
#include "serial_termios.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

struct BaudConstant {
    unsigned baud;
    speed_t constant;
};
constexpr BaudConstant baud_constants[] = {
    {50, B50},     {75, B75},       {110, B110},     {134, B134},     {150, B150},       {200, B200},
    {300, B300},   {600, B600},     {1200, B1200},   {1800, B1800},   {2400, B2400},     {4800, B4800},
    {9600, B9600}, {19200, B19200}, {38400, B38400}, {57600, B57600}, {115200, B115200}, {230400, B230400},
};

const BaudConstant* find_baud(unsigned baud) {
    for (const auto& b : baud_constants)
        if (b.baud == baud) return &b;
    return nullptr;
}

}  // namespace

double SerialSettings::chars_per_second() const {
    int bits = 1 + data_bits + (parity == SerialParity::none ? 0 : 1) + stop_bits;
    return static_cast<double>(baud) / bits;
}

SerialSettings parse_serial_settings(std::string_view rest) {
    DeviceQuery q("serial", rest, serial_keys);
    SerialSettings s;
    s.path = q.path();
    if (s.path.empty()) q.fail("no path, e.g. serial:/dev/ttyUSB0?baud=9600");
    s.baud = q.number("baud", s.baud);
    // Refused here rather than when the port is opened: a usage error, before anything is created.
    if (!find_baud(s.baud)) q.bad_value("baud", *q.value("baud"), "is not a standard rate (50 to 230400)");
    s.data_bits = q.choice("bits", s.data_bits, {{"7", 7}, {"8", 8}});
    s.parity = q.choice("parity", s.parity,
                        {{"none", SerialParity::none}, {"even", SerialParity::even}, {"odd", SerialParity::odd}});
    s.stop_bits = q.choice("stop", s.stop_bits, {{"1", 1}, {"2", 2}});
    s.flow = q.choice("flow", s.flow, {{"xonxoff", Flow::xonxoff}, {"rtscts", Flow::rtscts}, {"none", Flow::none}});
    if (s.data_bits == 7 && s.parity == SerialParity::none)
        q.fail("bits=7 needs parity=even or odd (the UART's parity bit stands for track 8)");
    return s;
}

termios make_termios(const SerialSettings& s) {
    const BaudConstant* baud = find_baud(s.baud);
    if (!baud)
        throw Error(Errc::usage,
                    "serial device: baud=" + std::to_string(s.baud) + " is not a standard rate (50 to 230400)");
    termios t{};
    cfmakeraw(&t);
    t.c_cflag |= CREAD | CLOCAL;
    t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
    t.c_cflag |= s.data_bits == 7 ? CS7 : CS8;
    if (s.parity != SerialParity::none) t.c_cflag |= PARENB;
    if (s.parity == SerialParity::odd) t.c_cflag |= PARODD;
    if (s.stop_bits == 2) t.c_cflag |= CSTOPB;
    if (s.flow == Flow::rtscts) t.c_cflag |= CRTSCTS;
    t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
    if (s.parity != SerialParity::none) t.c_iflag |= INPCK;
    t.c_cc[VMIN] = 0;
    t.c_cc[VTIME] = 0;
    cfsetispeed(&t, baud->constant);
    cfsetospeed(&t, baud->constant);
    return t;
}

}  // namespace tape
