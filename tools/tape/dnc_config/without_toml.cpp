// tape dnc built without toml++: the command is there and says why it cannot read its configuration.
#include "../dnc_config.hpp"
#include "tape/error.hpp"

namespace cli {

namespace {

[[noreturn]] void without_toml() {
    throw tape::Error(tape::Errc::usage,
                      "built without toml++: tape dnc cannot read its configuration (install libtomlplusplus-dev, "
                      "or run scripts/install-deps.sh features, and build again)");
}

}  // namespace

tape::dnc::ServiceConfig load_dnc_config(const std::string&) { without_toml(); }
tape::dnc::ServiceConfig parse_dnc_config(std::string_view, const std::string&) { without_toml(); }
std::string dnc_control_socket(const std::string&) { without_toml(); }

}  // namespace cli
