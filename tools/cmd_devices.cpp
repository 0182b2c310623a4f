// tape devices: the device backends this tape knows, from the one table.
#include "cli_common.hpp"
#include "commands.hpp"
#include "tape/device.hpp"

namespace cli {

void add_devices(CLI::App& app) {
    auto* sub = app.add_subcommand("devices", "List the device backends and their device strings");
    sub->callback([] {
        std::string out;
        for (const auto& b : tape::device_backends())
            out += std::string(b.prefix) + "\t" + std::string(b.syntax) + "\n\t" + std::string(b.description) + "\n";
        write_output("-", out, false, false);
    });
}

}  // namespace cli
