// adapter:PATH?serial=…&tracks=8&invert=0&watchdog=500 — a tape adapter (firmware/core) on a USB CDC serial port,
// /dev/ttyACM0, or on the pseudo-terminal of tape-adapter-sim. Packets travel COBS-framed on the byte stream. The
// Transport every adapter backend shares (usb:, hid:) is here too: the protocol itself is adapter::Session's.
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>

#include "adapter_session.hpp"
#include "device_backends.hpp"
#include "serial_termios.hpp"
#include "tape/error.hpp"
#include "transport_posix.hpp"

namespace tape {
namespace {

class CdcPipe : public adapter::PacketPipe {
public:
    explicit CdcPipe(std::string path) : path_(std::move(path)) {
        fd_ = posix::open_line(path_, name());
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
            if (r.end) throw adapter::adapter_gone(name());
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
            throw adapter::adapter_gone(name());
        }
    }
};

// What the adapter's row flags say about a frame, in words.
std::string flags_text(std::uint8_t flags) {
    namespace rf = tapefw::row_flag;
    std::string s;
    auto add = [&s](const char* what) { s += (s.empty() ? "" : "; ") + std::string(what); };
    if (flags & rf::no_sprocket) add("read without a sprocket hole (sampled by time)");
    if (flags & rf::timing) add("its sprocket hole came early or late");
    if (flags & rf::marginal) add("a track's level was near its threshold");
    if (s.empty()) add("flagged by the adapter");
    return s;
}

class AdapterTransport : public Transport {
public:
    AdapterTransport(std::unique_ptr<adapter::PacketPipe> pipe, DeviceUse use, tapefw::ReadStart start)
        : use_(use), start_(start), session_(std::move(pipe)) {}

    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
        if (use_ == DeviceUse::write) return session_.punch_input(timeout);
        return session_.read(buffer, timeout, start_);
    }
    bool backwards() const override { return start_.reverse != 0; }
    int tracks() const override { return tracks_; }
    void set_tracks(int tracks) { tracks_ = tracks; }
    FrameDoubts take_doubts() override {
        FrameDoubts out;
        for (const auto& d : session_.take_doubts()) out.runs.push_back({d.first, d.last, flags_text(d.flags)});
        out.unkept = session_.take_unkept_doubts();
        return out;
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
    adapter::Session& session() { return session_; }
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
    tapefw::ReadStart start_;
    adapter::Session session_;
    std::size_t noted_ = 0;
    int tracks_ = 8;
};

// The widest tape the unit takes: what its CONFIG masks rows to, else the widest the adapter names.
int unit_tracks(const tapefw::Info& info, const std::optional<tapefw::Config>& config) {
    if (config) return config->tracks;
    for (int n = 8; n >= 5; --n)
        if (info.tracks & (1 << (n - 5))) return n;
    return 8;
}

std::string cdc_path(const DeviceQuery& q) {
    if (q.path().empty()) q.fail("no path, e.g. adapter:/dev/ttyACM0");
    return q.path();
}

}  // namespace

adapter::Settings adapter::settings_of(const DeviceQuery& q, DeviceUse use) {
    Settings s;
    if (auto serial = q.value("serial")) s.serial = std::string(*serial);
    s.start.reverse = q.choice<std::uint8_t>("direction", 0, {{"forward", 0}, {"reverse", 1}});
    if (use == DeviceUse::write && q.value("direction"))
        q.fail("direction is the reader's, and this device is opened to punch");
    // The unit's line settings, sent as CONFIG when any is given (the adapter keeps its own otherwise);
    // those not given at their defaults, as tape adapter config sends them.
    AdapterConfig c;
    c.tracks = q.number("tracks", c.tracks);
    c.data_invert = q.number("invert", c.data_invert);
    c.watchdog_ms = q.number("watchdog", c.watchdog_ms);
    c.sprocket_timeout_ms = q.number("sprocket-timeout", c.sprocket_timeout_ms);
    if (auto problem = adapter_config_problem(c); !problem.empty()) q.fail(problem);
    bool given = false;
    for (auto key : {"tracks", "invert", "watchdog", "sprocket-timeout"}) given = given || q.value(key);
    if (given) s.config = to_wire(c);
    return s;
}

std::unique_ptr<Transport> adapter::open_transport(std::unique_ptr<PacketPipe> pipe, const Settings& s, DeviceUse use) {
    auto t = std::make_unique<AdapterTransport>(std::move(pipe), use, s.start);
    // Refused before anything is read or written, as the adapter would refuse its READ_START.
    if (s.start.reverse && !(t->session().info().capabilities & tapefw::caps::reverse))
        throw Error(Errc::io, t->name() + ": this adapter's reader cannot read backwards (direction=reverse)");
    apply_settings(t->session(), s, use);
    t->set_tracks(unit_tracks(t->session().info(), s.config));
    return t;
}

void adapter::apply_settings(Session& session, const Settings& s, DeviceUse use) {
    // A CDC port's number changes with the order of plugging: the serial tells the adapter meant.
    const tapefw::Info& info = session.info();
    if (s.serial && *s.serial != info.serial)
        throw Error(Errc::io, session.name() + ": this adapter's serial is " + info.serial + ", not " + *s.serial);
    // An adapter without the reader or the punch asked for is refused before any output is created.
    if (use == DeviceUse::read && !(info.capabilities & tapefw::caps::reader))
        throw Error(Errc::io, session.name() + ": this adapter has no reader");
    if (use == DeviceUse::write && !(info.capabilities & tapefw::caps::punch))
        throw Error(Errc::io, session.name() + ": this adapter has no punch");
    if (s.config) session.configure(*s.config);
}

adapter::UsbId adapter::usb_id(std::string_view backend, const DeviceQuery& q) {
    const std::string& path = q.path();
    auto colon = path.find(':');
    UsbId id;
    auto hex = [](std::string_view s, std::uint16_t& out) {
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out, 16);
        return !s.empty() && s.size() <= 4 && ec == std::errc() && end == s.data() + s.size();
    };
    if (colon == std::string::npos || !hex(std::string_view(path).substr(0, colon), id.vendor) ||
        !hex(std::string_view(path).substr(colon + 1), id.product))
        q.fail("'" + std::string(backend) + ":" + path + "' names no vendor:product id in hex, e.g. " +
               std::string(backend) + ":1209:0001");
    return id;
}

Error adapter::adapter_gone(const std::string& name, const std::string& why) {
    return Error(Errc::io, name + ": the adapter is gone (unplugged?)" + (why.empty() ? "" : ": " + why));
}

Error adapter::none_attached(const std::string& name, const UsbId& id, std::optional<std::string_view> serial,
                             const std::vector<std::string>& seen) {
    std::string what =
        "no adapter " + id.text() + (serial ? " with serial " + std::string(*serial) : "") + " is attached";
    if (!seen.empty()) {
        what += " (attached:";
        for (const auto& s : seen) what += " " + s;
        what += ")";
    }
    return Error(Errc::io, name + ": " + what);
}

std::optional<tapefw::Packet> adapter::TransferPipe::receive(std::chrono::milliseconds timeout) {
    auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        std::uint8_t in[tapefw::report_size];
        int n = receive_transfer(in, std::max(left, std::chrono::milliseconds(0)));
        if (n != 0) {
            // A bulk transfer holds the packet alone, a HID report has it padded: decode_report takes both.
            tapefw::Packet p;
            if (n > 0 && tapefw::decode_report(in, static_cast<std::size_t>(n), p) == tapefw::PacketFault::none)
                return p;
            ++bad_;
            continue;
        }
        if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    }
}

std::string adapter::UsbId::text() const {
    char s[10];
    std::snprintf(s, sizeof s, "%04x:%04x", vendor, product);
    return s;
}

std::string adapter::device_string(std::string_view backend, const UsbId& id, std::string_view serial) {
    return std::string(backend) + ":" + id.text() + (serial.empty() ? "" : "?serial=" + percent_encoded(serial));
}

std::unique_ptr<adapter::PacketPipe> open_cdc_pipe(const DeviceQuery& q) {
    return std::make_unique<CdcPipe>(cdc_path(q));
}

}  // namespace tape
