// Built without toml++: no profile can be read, and saying so is all this backend does.
#include "tape/error.hpp"
#include "tape/machine.hpp"

namespace tape {

MachineProfile parse_machine_profile(std::string_view, std::string_view file) {
    throw Error(Errc::usage, std::string(file) + ": tape was built without toml++, so it reads no machine profiles");
}

}  // namespace tape
