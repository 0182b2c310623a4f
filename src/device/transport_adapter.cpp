// adapter:PATH?tracks=8&invert=0&watchdog=500 — a tape adapter (firmware/core) on a USB CDC serial port, /dev/ttyACM0,
// or on the pseudo-terminal of tape-adapter-sim. Packets travel COBS-framed on the byte stream; the protocol itself is
// adapter::Session's, shared with the usb: and hid: backends.
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include "adapter_session.hpp"
#include "device_backends.hpp"
#include "device_query.hpp"
#include "serial_termios.hpp"
#include "tape/error.hpp"
#include "transport_posix.hpp"

namespace tape {
namespace {

class CdcPipe : public adapter::PacketPipe {
public:
    explicit CdcPipe(std::string path) : path_(std::move(path)) {
        fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
        if (fd_ < 0) posix::fail(name(), "cannot open");
        SerialSettings s;
        s.path = path_;
        s.baud = 115200;  // a CDC port ignores it; a real UART bridge would use it
        s.flow = Flow::none;
        termios t = make_termios(s);
        if (::tcsetattr(fd_, TCSANOW, &t) != 0 && errno != ENOTTY) {
            int saved = errno;
            ::close(fd_);
            errno = saved;
            posix::fail(name(), "cannot set raw mode");
        }
        // A zero ends whatever partial packet the adapter holds from before: the RESET that follows is read whole.
        std::uint8_t zero = 0;
        write_all({&zero, 1});
    }
    ~CdcPipe() override { ::close(fd_); }

    void send(const tapefw::Packet& p) override {
        std::uint8_t out[tapefw::max_framed];
        write_all({out, tapefw::frame_packet(p, out)});
    }

    std::optional<tapefw::Packet> receive(std::chrono::milliseconds timeout) override {
        auto deadline = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            while (at_ < used_) {
                auto e = decoder_.feed(buffer_[at_++]);
                if (e == tapefw::StreamDecoder::Event::packet) return decoder_.packet();
                if (e == tapefw::StreamDecoder::Event::fault) ++bad_;
            }
            auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
            ReadResult r = posix::read_fd(fd_, buffer_, std::max(left, std::chrono::milliseconds(0)), name());
            if (r.end) throw Error(Errc::io, name() + ": the adapter is gone (unplugged?)");
            at_ = 0;
            used_ = r.count;
            if (r.count == 0 && left.count() <= 0) return std::nullopt;
        }
    }

    std::uint64_t bad_packets() const override { return bad_; }
    std::string name() const override { return "adapter:" + path_; }

private:
    std::string path_;
    int fd_ = -1;
    std::uint8_t buffer_[512];
    std::size_t at_ = 0, used_ = 0;
    tapefw::StreamDecoder decoder_;
    std::uint64_t bad_ = 0;

    void write_all(std::span<const std::uint8_t> bytes) {
        try {
            posix::write_fd(fd_, bytes, name());
        } catch (const Error&) {
            throw Error(Errc::io, name() + ": the adapter is gone (unplugged?)");
        }
    }
};

// The adapter as a Transport: reads are the reader's rows, writes the punch's.
class AdapterTransport : public Transport {
public:
    AdapterTransport(std::unique_ptr<adapter::PacketPipe> pipe, DeviceUse use) : use_(use), session_(std::move(pipe)) {}

    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
        if (use_ == DeviceUse::write) return session_.punch_input(timeout);
        return session_.read(buffer, timeout);
    }
    void write(std::span<const std::uint8_t> bytes) override {
        // A reader being stopped is asked in band by a DC3 on other lines; here the session stops it.
        if (use_ == DeviceUse::read) throw Error(Errc::io, name() + ": opened for reading: nothing is punched");
        session_.punch(bytes);
    }
    void drain() override {
        if (use_ != DeviceUse::read) session_.drain();
    }
    std::string name() const override { return session_.name(); }
    void configure(const tapefw::Config& c) { session_.configure(c); }
    std::vector<std::string> take_notes() override {
        std::vector<std::string> notes;
        const auto& r = session_.recovered();
        for (; noted_ < r.size(); ++noted_)
            notes.push_back("frames " + std::to_string(r[noted_].first) + "-" + std::to_string(r[noted_].second) +
                            " came again after a lost or damaged packet");
        return notes;
    }

private:
    DeviceUse use_;
    adapter::Session session_;
    std::size_t noted_ = 0;
};

}  // namespace

constexpr std::string_view adapter_keys[] = {"tracks", "invert", "watchdog", "sprocket-timeout"};

// The settings are the unit's, for reading and punching; asking the adapter about itself needs none.
std::unique_ptr<adapter::PacketPipe> adapter::open_pipe(std::string_view device) {
    if (!device.starts_with("adapter:"))
        throw Error(Errc::usage, "'" + std::string(device) + "' names no adapter: give adapter:/dev/ttyACM0");
    DeviceQuery q("adapter", device.substr(8), adapter_keys);
    if (q.path().empty()) q.fail("no path, e.g. adapter:/dev/ttyACM0");
    return std::make_unique<CdcPipe>(q.path());
}

std::unique_ptr<Transport> open_adapter_device(std::string_view rest, DeviceUse use, bool) {
    DeviceQuery q("adapter", rest, adapter_keys);
    if (q.path().empty()) q.fail("no path, e.g. adapter:/dev/ttyACM0");
    // The unit's line settings, sent as CONFIG when any is given (the adapter keeps its own otherwise).
    tapefw::Config c;
    c.tracks = static_cast<std::uint8_t>(q.number("tracks", c.tracks));
    if (c.tracks < 5 || c.tracks > 8) q.bad_value("tracks", *q.value("tracks"), "is not 5 to 8");
    unsigned invert = q.number("invert", 0);
    if (invert > 255) q.bad_value("invert", *q.value("invert"), "is no mask of 8 data lines (0 to 255)");
    c.data_invert = static_cast<std::uint8_t>(invert);
    unsigned watchdog = q.number("watchdog", c.watchdog_ms);
    if (watchdog > 65535) q.bad_value("watchdog", *q.value("watchdog"), "is not 0 to 65535 milliseconds");
    c.watchdog_ms = static_cast<std::uint16_t>(watchdog);
    unsigned sprocket = q.number("sprocket-timeout", c.sprocket_timeout_ms);
    if (sprocket < 1 || sprocket > 65535)
        q.bad_value("sprocket-timeout", *q.value("sprocket-timeout"), "is not 1 to 65535 milliseconds");
    c.sprocket_timeout_ms = static_cast<std::uint16_t>(sprocket);
    bool configure = false;
    for (auto key : adapter_keys) configure = configure || q.value(key).has_value();
    auto t = std::make_unique<AdapterTransport>(std::make_unique<CdcPipe>(q.path()), use);
    if (configure) t->configure(c);
    return t;
}

}  // namespace tape
