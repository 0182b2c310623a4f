// tape devices: the device backends this tape knows, from the one table, and the USB serial ports and
// tape adapters attached (by serial, so that several are told apart).
#include <cstdio>
#include <cstdlib>

#include "cli/outputs.hpp"
#include "commands.hpp"
#include "tape/adapter.hpp"
#include "tape/device.hpp"
#include "tape/error.hpp"
#include "tape/utf8_text.hpp"

namespace cli {

void add_devices(CLI::App& app) {
    auto probe = std::make_shared<bool>(false);
    auto* sub = app.add_subcommand(
        "devices",
        "List the device backends and their device strings, then the USB serial ports and tape adapters attached");
    sub->add_flag("--probe", *probe,
                  "Ask each tape adapter for its capabilities (this resets it: not while another run uses it)");
    sub->callback([probe] {
        std::string out;
        for (const auto& b : tape::device_backends())
            out += std::string(b.prefix) + "\t" + std::string(b.syntax) + "\n\t" + std::string(b.description) + "\n";
        // TAPE_SYSFS_ROOT and TAPE_DEV_ROOT: another sysfs and /dev, for the tests (--probe reaches a
        // simulator through a link in the one /dev).
        const char* root = std::getenv("TAPE_SYSFS_ROOT");
        const char* dev = std::getenv("TAPE_DEV_ROOT");
        auto ports = tape::attached_ports(root ? root : "/sys", dev ? dev : "/dev");
        out += ports.empty() ? "no USB serial port or tape adapter attached\n" : "attached:\n";
        for (const auto& p : ports) {
            char ids[16];
            std::snprintf(ids, sizeof ids, "%04x:%04x", p.vendor, p.product);
            // The strings are the device's own: what a terminal would act on is spelled out.
            out += tape::visible(p.device) + "\t" + ids +
                   (p.serial.empty() ? "" : " serial " + tape::visible(p.serial)) +
                   (p.description.empty() ? "" : "\t" + tape::visible(p.description)) + "\n";
            if (!p.adapter || !*probe) continue;
            try {
                auto i = tape::adapter_info(p.device);
                out += "\tprotocol " + std::to_string(i.protocol) + ", firmware " + tape::visible(i.firmware) +
                       (i.reader ? ", reader " + std::to_string(i.max_read_rate) + " frames/s" : "") +
                       (i.punch ? ", punch " + std::to_string(i.max_punch_rate) + " rows/s" : "") +
                       (i.emulate ? ", emulates a reader" : "") + "\n";
            } catch (const tape::Error& e) {
                out += "\tno answer: " + tape::visible(e.what()) + "\n";
            }
        }
        write_output("-", out, false, false);
    });
}

}  // namespace cli
