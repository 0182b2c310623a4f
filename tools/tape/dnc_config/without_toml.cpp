// tape dnc built without toml++: the command is there and says why it cannot read its configuration.
#include "../dnc_config.hpp"
#include "tape/error.hpp"

namespace cli {

tape::dnc::ServiceConfig load_dnc_config(const std::string&) {
    throw tape::Error(tape::Errc::usage,
                      "built without toml++: tape dnc cannot read its configuration (install libtomlplusplus-dev, "
                      "or run scripts/install-deps.sh features, and build again)");
}

}  // namespace cli
