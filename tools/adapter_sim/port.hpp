// The simulated adapter's CDC port: a pseudo-terminal the host opens as adapter:/dev/pts/N.
#pragma once

#include <string>

namespace tapesim {

// The adapter's CDC port: a pseudo-terminal in raw mode, its far end held open so that a host closing
// the port (between runs) does not hang the line up, and optionally a symbolic link to it.
class Port {
public:
    explicit Port(const std::string& link);
    ~Port();
    Port(const Port&) = delete;
    Port& operator=(const Port&) = delete;

    const std::string& path() const { return path_; }
    int fd() const { return master_; }

private:
    std::string link_, path_;
    int master_ = -1, slave_ = -1;
};

}  // namespace tapesim
