// usb:1209:0001?serial=…&tracks=8… — a tape adapter on its vendor-class interface, through libusb: one packet
// (firmware/core/packet.hpp) per bulk transfer each way, no COBS. The protocol is adapter::Session's.
#include <libusb.h>

#include <algorithm>
#include <vector>

#include "adapter_session.hpp"
#include "device_backends.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

constexpr unsigned send_timeout_ms = 1000;

class UsbPipe : public adapter::TransferPipe {
public:
    explicit UsbPipe(const DeviceQuery& q) : id_(adapter::usb_id("usb", q)) {
        auto serial = q.value("serial");
        name_ = adapter::device_string("usb", id_, serial.value_or(""));
        check(libusb_init(&ctx_), "cannot start libusb");
        try {
            open(serial);
        } catch (...) {
            if (handle_) libusb_close(handle_);
            libusb_exit(ctx_);
            throw;
        }
    }
    ~UsbPipe() override {
        // Released before closing: a claimed interface would keep the kernel's driver off it.
        libusb_release_interface(handle_, interface_);
        libusb_close(handle_);
        libusb_exit(ctx_);
    }

    void send(const tapefw::Packet& p) override {
        std::uint8_t out[tapefw::max_packet];
        int n = static_cast<int>(tapefw::encode_packet(p, out));
        int done = 0;
        int r = libusb_bulk_transfer(handle_, out_ep_, out, n, &done, send_timeout_ms);
        if (r == LIBUSB_ERROR_TIMEOUT) throw Error(Errc::io, name_ + ": the adapter takes no packets (time-out)");
        check(r, "cannot send a packet");
        if (done != n) throw Error(Errc::io, name_ + ": the adapter took part of a packet");
    }

    std::string name() const override { return name_; }

protected:
    int receive_transfer(std::uint8_t* in, std::chrono::milliseconds wait) override {
        // libusb takes 0 as no time-out at all: a poll asks for the shortest wait instead.
        unsigned ms = static_cast<unsigned>(std::max<std::int64_t>(1, wait.count()));
        int got = 0;
        int r = libusb_bulk_transfer(handle_, in_ep_, in, static_cast<int>(tapefw::report_size), &got, ms);
        if (r == LIBUSB_ERROR_OVERFLOW) return -1;  // more than one packet's bytes: not ours
        if (r != 0 && r != LIBUSB_ERROR_TIMEOUT) check(r, "cannot receive a packet");
        return got;
    }

private:
    adapter::UsbId id_;
    std::string name_;
    libusb_context* ctx_ = nullptr;
    libusb_device_handle* handle_ = nullptr;
    int interface_ = -1;
    unsigned char in_ep_ = 0, out_ep_ = 0;

    void check(int r, const std::string& what) const {
        if (r >= 0) return;
        if (r == LIBUSB_ERROR_NO_DEVICE) throw adapter::adapter_gone(name_);
        if (r == LIBUSB_ERROR_ACCESS)
            throw Error(Errc::io,
                        name_ + ": " + what + ": no permission (install udev/70-tape-adapter.rules, see tape-usb(7))");
        if (r == LIBUSB_ERROR_BUSY) throw Error(Errc::io, name_ + ": " + what + ": another program has it open");
        throw Error(Errc::io, name_ + ": " + what + ": " + libusb_strerror(r));
    }

    // The serial string of an opened device, or empty when it has none it will tell.
    static std::string serial_of(libusb_device_handle* h, const libusb_device_descriptor& d) {
        if (d.iSerialNumber == 0) return {};
        unsigned char text[128];
        int n = libusb_get_string_descriptor_ascii(h, d.iSerialNumber, text, sizeof text);
        return n > 0 ? std::string(reinterpret_cast<char*>(text), static_cast<std::size_t>(n)) : std::string();
    }

    void open(std::optional<std::string_view> serial) {
        libusb_device** list = nullptr;
        ssize_t count = libusb_get_device_list(ctx_, &list);
        if (count < 0) check(static_cast<int>(count), "cannot list USB devices");
        std::vector<std::string> seen;
        int refused = 0;
        libusb_device* chosen = nullptr;
        for (ssize_t i = 0; i < count && !chosen; ++i) {
            libusb_device_descriptor d{};
            if (libusb_get_device_descriptor(list[i], &d) != 0) continue;
            if (d.idVendor != id_.vendor || d.idProduct != id_.product) continue;
            libusb_device_handle* h = nullptr;
            int r = libusb_open(list[i], &h);
            if (r != 0) {
                refused = r;
                continue;
            }
            std::string s = serial_of(h, d);
            if (!serial || s == *serial) {
                chosen = list[i];
                handle_ = h;
            } else {
                seen.push_back(s.empty() ? "(no serial)" : s);
                libusb_close(h);
            }
        }
        libusb_free_device_list(list, 1);  // the handle keeps its device
        if (!chosen) {
            if (refused) check(refused, "cannot open the adapter");
            throw adapter::none_attached(name_, id_, serial, seen);
        }
        find_interface(libusb_get_device(handle_));
        // The kernel may have bound a driver to the interface; it goes back when the interface is released.
        int r = libusb_set_auto_detach_kernel_driver(handle_, 1);
        if (r != 0 && r != LIBUSB_ERROR_NOT_SUPPORTED) check(r, "cannot detach the kernel's driver");
        check(libusb_claim_interface(handle_, interface_), "cannot claim the adapter's interface");
    }

    // The vendor-class interface with one bulk endpoint each way (an adapter may also offer CDC and HID).
    void find_interface(libusb_device* dev) {
        libusb_config_descriptor* config = nullptr;
        check(libusb_get_active_config_descriptor(dev, &config), "cannot read the adapter's configuration");
        for (int i = 0; i < config->bNumInterfaces && interface_ < 0; ++i) {
            if (config->interface[i].num_altsetting < 1) continue;
            const libusb_interface_descriptor& alt = config->interface[i].altsetting[0];
            if (alt.bInterfaceClass != LIBUSB_CLASS_VENDOR_SPEC) continue;
            unsigned char in = 0, out = 0;
            for (int e = 0; e < alt.bNumEndpoints; ++e) {
                const libusb_endpoint_descriptor& ep = alt.endpoint[e];
                if ((ep.bmAttributes & LIBUSB_TRANSFER_TYPE_MASK) != LIBUSB_TRANSFER_TYPE_BULK) continue;
                ((ep.bEndpointAddress & LIBUSB_ENDPOINT_IN) ? in : out) = ep.bEndpointAddress;
            }
            if (in && out) {
                interface_ = alt.bInterfaceNumber;
                in_ep_ = in;
                out_ep_ = out;
            }
        }
        libusb_free_config_descriptor(config);
        if (interface_ < 0)
            throw Error(Errc::io,
                        name_ + ": the device has no vendor interface with bulk endpoints: is it a tape adapter?");
    }
};

}  // namespace

std::unique_ptr<adapter::PacketPipe> open_usb_pipe(const DeviceQuery& q) { return std::make_unique<UsbPipe>(q); }

}  // namespace tape
