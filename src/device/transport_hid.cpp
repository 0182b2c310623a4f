// hid:1209:0001?serial=…&tracks=8… — a tape adapter on its HID interface, through hidapi (hidraw): one packet
// (firmware/core/packet.hpp) per 64-byte report each way, padded with zeros. No driver to install on any system,
// at the cost of the reports' fixed size. The protocol is adapter::Session's.
#include <hidapi.h>

#include <algorithm>
#include <cwchar>
#include <vector>

#include "adapter_session.hpp"
#include "device_backends.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

std::string narrow(const wchar_t* w) {
    std::string s;
    for (; w && *w; ++w) s += *w < 0x80 ? static_cast<char>(*w) : '?';
    return s;
}

class HidPipe : public adapter::TransferPipe {
public:
    explicit HidPipe(const DeviceQuery& q) {
        adapter::UsbId id = adapter::usb_id("hid", q);
        auto serial = q.value("serial");
        name_ = adapter::device_string("hid", id, serial.value_or(""));
        if (hid_init() != 0) throw Error(Errc::io, name_ + ": cannot start hidapi");
        hid_device_info* list = hid_enumerate(id.vendor, id.product);
        std::string path;
        std::vector<std::string> seen;
        for (hid_device_info* d = list; d; d = d->next) {
            std::string s = narrow(d->serial_number);
            if (!serial || s == *serial) {
                path = d->path;
                break;
            }
            seen.push_back(s.empty() ? "(no serial)" : s);
        }
        hid_free_enumeration(list);
        if (path.empty()) {
            throw adapter::none_attached(name_, id, serial, seen);
        }
        device_ = hid_open_path(path.c_str());
        if (!device_) {
            std::string why = narrow(hid_error(nullptr));
            if (why.find("ermission") != std::string::npos)
                why += " (install udev/70-tape-adapter.rules, see tape-usb(7))";
            throw Error(Errc::io, name_ + ": cannot open " + path + ": " + why);
        }
    }
    ~HidPipe() override { hid_close(device_); }

    void send(const tapefw::Packet& p) override {
        // The report id comes first: 0, as the adapter's reports are not numbered.
        std::uint8_t report[1 + tapefw::report_size] = {};
        tapefw::encode_packet(p, report + 1);
        int n = hid_write(device_, report, sizeof report);
        if (n < 0) throw adapter::adapter_gone(name_, narrow(hid_error(device_)));
    }

    std::string name() const override { return name_; }

protected:
    int receive_transfer(std::uint8_t* in, std::chrono::milliseconds wait) override {
        int n = hid_read_timeout(device_, in, tapefw::report_size, static_cast<int>(wait.count()));
        if (n < 0) throw adapter::adapter_gone(name_, narrow(hid_error(device_)));
        return n;
    }

private:
    std::string name_;
    hid_device* device_ = nullptr;
};

}  // namespace

std::unique_ptr<adapter::PacketPipe> open_hid_pipe(const DeviceQuery& q) { return std::make_unique<HidPipe>(q); }

}  // namespace tape
