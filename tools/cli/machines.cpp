// --machine for the commands that read a machine profile.
#include "cli/machines.hpp"

#include "cli/messages.hpp"

namespace cli {

CLI::Option* add_machine_option(CLI::App* sub, std::string& name, const std::string& what) {
    return sub->add_option("--machine", name, "Machine profile, by name (tape machines lists them) or path: " + what)
        ->option_text("NAME|PATH");
}

std::optional<tape::MachineProfile> machine_or_fail(const std::string& name, const std::string& what) {
    if (name.empty()) return std::nullopt;
    try {
        return tape::load_machine(name);
    } catch (const tape::Error& e) {
        // The message names the profile's file and line itself.
        fail("", e.code(), what + ": " + e.what());
    }
}

}  // namespace cli
