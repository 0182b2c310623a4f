// attached_ports: USB serial ports and tape adapters (CDC, vendor bulk, HID) from sysfs, so that several are
// told apart by serial.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <tuple>

#include "adapter_session.hpp"
#include "core/protocol.hpp"
#include "tape/adapter.hpp"

namespace tape {
namespace {

namespace fs = std::filesystem;

// A sysfs attribute is at most a page; the strings wanted here are far shorter.
constexpr std::size_t attribute_size = 4096;

// The first line of a sysfs attribute. Only a regular file is read (sysfs attributes are), opened
// without waiting and read up to a page: a FIFO or a link to /dev/zero under another root neither
// blocks nor grows. "" for anything else.
std::string first_line(const fs::path& p) {
    int fd = ::open(p.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return "";
    struct stat st {};
    char buf[attribute_size];
    ssize_t n = -1;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
        do {
            n = ::read(fd, buf, sizeof buf);
        } while (n < 0 && errno == EINTR);
    }
    ::close(fd);
    if (n <= 0) return "";
    std::string text(buf, static_cast<std::size_t>(n));
    return text.substr(0, text.find('\n'));
}

std::uint16_t hex16(const std::string& s) {
    try {
        return static_cast<std::uint16_t>(std::stoul(s, nullptr, 16));
    } catch (const std::exception&) {
        return 0;
    }
}

// The USB device is the first parent with an idVendor (interfaces, ttys and hidraw nodes are below it);
// empty when there is none (a virtual terminal, a Bluetooth HID device).
fs::path usb_device_above(fs::path p) {
    std::error_code ec;
    while (!p.empty() && p != p.root_path() && !fs::exists(p / "idVendor", ec)) p = p.parent_path();
    return p.empty() || p == p.root_path() ? fs::path() : p;
}

AttachedPort describe(const fs::path& usb) {
    AttachedPort p;
    p.vendor = hex16(first_line(usb / "idVendor"));
    p.product = hex16(first_line(usb / "idProduct"));
    p.serial = first_line(usb / "serial");
    std::string maker = first_line(usb / "manufacturer"), product = first_line(usb / "product");
    p.description = maker + (maker.empty() || product.empty() ? "" : " ") + product;
    p.adapter = p.vendor == tapefw::usb_vendor_id && p.product == tapefw::usb_product_id;
    return p;
}

// The nodes of a sysfs class (tty, hidraw) with a USB device behind them: NAME/device leads to it.
template <typename Take>
void for_each_usb_node(const fs::path& class_dir, Take take) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(class_dir, ec)) {
        fs::path usb = usb_device_above(fs::canonical(entry.path() / "device", ec));
        if (ec || usb.empty()) {
            ec.clear();
            continue;  // a virtual terminal, a Bluetooth HID device
        }
        take(entry.path().filename().string(), describe(usb));
    }
}

// Serial ports, tape adapters' CDC ones among them.
void add_serial_ports(const fs::path& sys, const std::string& dev_root, std::vector<AttachedPort>& ports) {
    for_each_usb_node(sys / "class" / "tty", [&](const std::string& name, AttachedPort p) {
        p.device = std::string(p.adapter ? "adapter:" : "serial:") + dev_root + "/" + name;
        ports.push_back(std::move(p));
    });
}

// An adapter's vendor interface (class ff), reached through libusb: bus/usb/devices/B-P:C.I.
void add_vendor_interfaces(const fs::path& sys, std::vector<AttachedPort>& ports) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(sys / "bus" / "usb" / "devices", ec)) {
        fs::path interface = fs::canonical(entry.path(), ec);
        if (ec || first_line(interface / "bInterfaceClass") != "ff") {
            ec.clear();
            continue;
        }
        fs::path usb = usb_device_above(interface);
        if (usb.empty()) continue;
        AttachedPort p = describe(usb);
        if (!p.adapter) continue;  // another maker's vendor interface: no backend of ours speaks to it
        p.device = adapter::device_string("usb", {p.vendor, p.product}, p.serial);
        ports.push_back(std::move(p));
    }
}

// An adapter's HID interface, reached through hidapi.
void add_hid_interfaces(const fs::path& sys, std::vector<AttachedPort>& ports) {
    for_each_usb_node(sys / "class" / "hidraw", [&](const std::string&, AttachedPort p) {
        if (!p.adapter) return;  // keyboards, mice, UPSes
        p.device = adapter::device_string("hid", {p.vendor, p.product}, p.serial);
        ports.push_back(std::move(p));
    });
}

}  // namespace

std::vector<AttachedPort> attached_ports(const std::string& sysfs_root, const std::string& dev_root) {
    std::vector<AttachedPort> ports;
    add_serial_ports(sysfs_root, dev_root, ports);
    add_vendor_interfaces(sysfs_root, ports);
    add_hid_interfaces(sysfs_root, ports);
    // Adapters first, each one's interfaces together under its serial; then the other serial ports.
    std::sort(ports.begin(), ports.end(), [](const auto& a, const auto& b) {
        return std::tuple(!a.adapter, a.adapter ? a.serial : "", a.device) <
               std::tuple(!b.adapter, b.adapter ? b.serial : "", b.device);
    });
    return ports;
}

}  // namespace tape
