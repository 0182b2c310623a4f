// serial:PATH?settings — a POSIX serial port (or a pseudo-terminal) in raw mode. XON/XOFF is done by
// tape, not by the kernel, so that every DC1/DC3 is seen; RTS/CTS by the UART (CRTSCTS).
#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include "device_backends.hpp"
#include "serial_termios.hpp"
#include "tape/error.hpp"
#include "transport_posix.hpp"

namespace tape {
namespace {

class SerialModem : public ModemLines {
public:
    explicit SerialModem(int fd) : fd_(fd) {}
    bool cts() override {
        int bits = 0;
        return ::ioctl(fd_, TIOCMGET, &bits) == 0 && (bits & TIOCM_CTS);
    }
    void set_rts(bool on) override {
        int bit = TIOCM_RTS;
        ::ioctl(fd_, on ? TIOCMBIS : TIOCMBIC, &bit);
    }

private:
    int fd_;
};

class SerialTransport : public Transport {
public:
    explicit SerialTransport(SerialSettings s) : s_(std::move(s)) {
        fd_ = posix::open_line(s_.path, name());
        termios t = make_termios(s_);
        if (::tcsetattr(fd_, TCSANOW, &t) != 0) {
            int saved = errno;
            ::close(fd_);
            errno = saved;
            posix::fail(name(), "cannot apply the line settings");
        }
        int bits = 0;
        if (::ioctl(fd_, TIOCMGET, &bits) == 0) modem_ = std::make_unique<SerialModem>(fd_);
        if (s_.flow == Flow::rtscts && !modem_) {
            ::close(fd_);
            throw Error(Errc::usage, name() + ": flow=rtscts, but this device has no modem lines");
        }
    }
    ~SerialTransport() override { ::close(fd_); }

    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
        return posix::read_fd(fd_, buffer, timeout, name());
    }
    void write(std::span<const std::uint8_t> bytes) override { posix::write_fd(fd_, bytes, name()); }
    void drain() override {
        if (::tcdrain(fd_) != 0 && errno != ENOTTY) posix::fail(name(), "cannot drain");
    }
    ModemLines* modem() override { return modem_.get(); }
    Flow flow() const override { return s_.flow; }
    double line_rate() const override { return s_.chars_per_second(); }
    bool seven_bit() const override { return s_.data_bits == 7; }
    std::string name() const override { return "serial:" + s_.path; }

private:
    SerialSettings s_;
    int fd_ = -1;
    std::unique_ptr<SerialModem> modem_;
};

}  // namespace

std::unique_ptr<Transport> open_serial_device(std::string_view rest, DeviceUse, bool) {
    return std::make_unique<SerialTransport>(parse_serial_settings(rest));
}

}  // namespace tape
