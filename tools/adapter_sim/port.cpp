#include "adapter_sim/port.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "adapter_sim/sim_args.hpp"

namespace tapesim {

Port::Port(const std::string& link) : link_(link) {
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0)
        die(std::string("no pseudo-terminal: ") + std::strerror(errno));
    path_ = ::ptsname(master_);
    slave_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY);
    if (slave_ < 0) die(path_ + ": " + std::strerror(errno));
    termios t{};
    ::tcgetattr(slave_, &t);
    ::cfmakeraw(&t);
    ::tcsetattr(slave_, TCSANOW, &t);
    ::fcntl(master_, F_SETFL, O_NONBLOCK);
    if (!link_.empty()) {
        ::unlink(link_.c_str());
        if (::symlink(path_.c_str(), link_.c_str()) != 0) die(link_ + ": " + std::strerror(errno));
    }
}
Port::~Port() {
    ::close(master_);
    ::close(slave_);
    if (!link_.empty()) ::unlink(link_.c_str());
}

}  // namespace tapesim
