// attached_ports: USB serial ports and tape adapters from sysfs, so that several are told apart by serial.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/protocol.hpp"
#include "tape/adapter.hpp"

namespace tape {
namespace {

namespace fs = std::filesystem;

std::string first_line(const fs::path& p) {
    std::ifstream in(p);
    std::string line;
    std::getline(in, line);
    return line;
}

std::uint16_t hex16(const std::string& s) {
    try {
        return static_cast<std::uint16_t>(std::stoul(s, nullptr, 16));
    } catch (const std::exception&) {
        return 0;
    }
}

}  // namespace

std::vector<AttachedPort> attached_ports(const std::string& sysfs_root, const std::string& dev_root) {
    std::vector<AttachedPort> ports;
    std::error_code ec;
    fs::path ttys = fs::path(sysfs_root) / "class" / "tty";
    for (const auto& entry : fs::directory_iterator(ttys, ec)) {
        fs::path device = fs::canonical(entry.path() / "device", ec);
        if (ec) {
            ec.clear();
            continue;  // a virtual terminal: no device behind it
        }
        // The USB device is the first parent with an idVendor (the interface is below it).
        fs::path usb = device;
        while (!usb.empty() && usb != usb.root_path() && !fs::exists(usb / "idVendor", ec)) usb = usb.parent_path();
        if (usb.empty() || usb == usb.root_path()) continue;
        AttachedPort p;
        p.vendor = hex16(first_line(usb / "idVendor"));
        p.product = hex16(first_line(usb / "idProduct"));
        p.serial = first_line(usb / "serial");
        std::string maker = first_line(usb / "manufacturer"), product = first_line(usb / "product");
        p.description = maker + (maker.empty() || product.empty() ? "" : " ") + product;
        p.adapter = p.vendor == tapefw::usb_vendor_id && p.product == tapefw::usb_product_id;
        p.device = std::string(p.adapter ? "adapter:" : "serial:") + dev_root + "/" + entry.path().filename().string();
        ports.push_back(std::move(p));
    }
    std::sort(ports.begin(), ports.end(), [](const auto& a, const auto& b) { return a.device < b.device; });
    return ports;
}

}  // namespace tape
