#include "tape/serial_settings.hpp"

#include <charconv>

#include "tape/error.hpp"

namespace tape {
namespace {

struct BaudConstant {
    unsigned baud;
    speed_t constant;
};
constexpr BaudConstant baud_constants[] = {
    {50, B50},     {75, B75},       {110, B110},     {134, B134},     {150, B150},     {200, B200},
    {300, B300},   {600, B600},     {1200, B1200},   {1800, B1800},   {2400, B2400},   {4800, B4800},
    {9600, B9600}, {19200, B19200}, {38400, B38400}, {57600, B57600}, {115200, B115200}, {230400, B230400},
};

[[noreturn]] void bad(std::string_view what) { throw Error(Errc::usage, "serial device: " + std::string(what)); }

unsigned number(std::string_view key, std::string_view value) {
    unsigned n = 0;
    auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc{} || p != value.data() + value.size()) bad(std::string(key) + "=" + std::string(value) + " is not a number");
    return n;
}

}  // namespace

double SerialSettings::chars_per_second() const {
    int bits = 1 + data_bits + (parity == SerialParity::none ? 0 : 1) + stop_bits;
    return static_cast<double>(baud) / bits;
}

SerialSettings parse_serial_settings(std::string_view rest) {
    SerialSettings s;
    auto q = rest.find('?');
    s.path = std::string(rest.substr(0, q));
    if (s.path.empty()) bad("no path, e.g. serial:/dev/ttyUSB0?baud=9600");
    std::string_view query = q == std::string_view::npos ? std::string_view{} : rest.substr(q + 1);
    while (!query.empty()) {
        auto amp = query.find('&');
        std::string_view pair = query.substr(0, amp);
        query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
        if (pair.empty()) continue;
        auto eq = pair.find('=');
        if (eq == std::string_view::npos) bad("'" + std::string(pair) + "' is not key=value");
        std::string_view key = pair.substr(0, eq), value = pair.substr(eq + 1);
        if (key == "baud") {
            s.baud = number(key, value);
        } else if (key == "bits") {
            s.data_bits = static_cast<int>(number(key, value));
            if (s.data_bits != 7 && s.data_bits != 8) bad("bits must be 7 or 8");
        } else if (key == "parity") {
            if (value == "none") s.parity = SerialParity::none;
            else if (value == "even") s.parity = SerialParity::even;
            else if (value == "odd") s.parity = SerialParity::odd;
            else bad("parity must be none, even or odd");
        } else if (key == "stop") {
            s.stop_bits = static_cast<int>(number(key, value));
            if (s.stop_bits != 1 && s.stop_bits != 2) bad("stop must be 1 or 2");
        } else if (key == "flow") {
            if (value == "xonxoff") s.flow = Flow::xonxoff;
            else if (value == "rtscts") s.flow = Flow::rtscts;
            else if (value == "none") s.flow = Flow::none;
            else bad("flow must be xonxoff, rtscts or none");
        } else {
            bad("unknown setting '" + std::string(key) + "' (baud, bits, parity, stop, flow)");
        }
    }
    if (s.data_bits == 7 && s.parity == SerialParity::none) bad("bits=7 needs parity=even or odd (the UART's parity bit stands for track 8)");
    make_termios(s);  // reject a baud rate the system has no constant for, here rather than at open
    return s;
}

termios make_termios(const SerialSettings& s) {
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
    const BaudConstant* found = nullptr;
    for (const auto& b : baud_constants)
        if (b.baud == s.baud) found = &b;
    if (!found) bad("baud=" + std::to_string(s.baud) + " is not a standard rate (50 to 230400)");
    cfsetispeed(&t, found->constant);
    cfsetospeed(&t, found->constant);
    return t;
}

}  // namespace tape
