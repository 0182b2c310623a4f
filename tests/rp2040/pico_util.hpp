// The tape adapter's RP2040 firmware running on an emulated RP2040 (tests/rp2040/pico.mjs, rp2040js),
// its USB CDC port on a pseudo-terminal: a real firmware image, a real host program, the pins wired to
// an emulated ФС-1501, punch or control. Tests skip, saying why, without node, rp2040js or the image.
#pragma once

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "spawn_util.hpp"
#include "test_util.hpp"

namespace pico {

/// Empty when the emulated Pico can run here; else why not.
inline std::string unavailable() {
    std::string dir = std::string(TAPE_SOURCE_DIR) + "/tests/rp2040";
    if (std::string(TAPE_NODE).empty() || !std::filesystem::exists(TAPE_NODE))
        return "no node (bash scripts/install-deps.sh test installs nodejs and rp2040js)";
    if (!std::filesystem::exists(dir + "/node_modules/rp2040js/package.json"))
        return "rp2040js is not installed in tests/rp2040 (bash scripts/install-deps.sh test runs npm ci there)";
    if (!std::filesystem::exists(TAPE_RP2040_ELF))
        return std::string("no firmware image ") + TAPE_RP2040_ELF +
               " (built when arm-none-eabi-g++ is there: bash scripts/install-deps.sh firmware)";
    return "";
}

/// The emulated Pico, started with the runner's options; stopped (SIGTERM: it writes what its units saw
/// into the test's directory) by stop() or at the end.
class Pico {
public:
    Pico(const TempDir& dir, std::vector<std::string> args) : dir_(dir) {
        std::vector<std::string> all = {std::string(TAPE_SOURCE_DIR) + "/tests/rp2040/pico.mjs",
                                        TAPE_RP2040_ELF,
                                        "--out",
                                        dir.path,
                                        "--usb-dump",
                                        dir.file("usb.txt")};
        all.insert(all.end(), args.begin(), args.end());
        pid_ = spawn_to_files(TAPE_NODE, all, dir.file("pico.out"), dir.file("pico.err"));
        // It prints the device string once the host side has enumerated the device.
        eventually(
            [&] {
                std::string out = read_text(dir.file("pico.out"));
                if (out.find('\n') == std::string::npos) return false;
                device = out.substr(0, out.find('\n'));
                return true;
            },
            std::chrono::seconds(30));
    }
    ~Pico() { stop(); }
    Pico(const Pico&) = delete;
    Pico& operator=(const Pico&) = delete;

    bool stop() {
        if (pid_ <= 0) return stopped_;
        ::kill(pid_, SIGTERM);
        auto status = wait_for_exit(pid_, std::chrono::seconds(10));
        if (!status) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
        pid_ = -1;
        return stopped_ = status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0;
    }
    std::string err() const { return read_text(dir_.file("pico.err")); }
    std::string file(const std::string& name) const { return read_text(dir_.file(name)); }
    std::vector<std::uint8_t> bytes(const std::string& name) const {
        std::string s = file(name);
        return {s.begin(), s.end()};
    }

    std::string device;  ///< "adapter:/dev/pts/N", empty when it did not start

private:
    const TempDir& dir_;
    pid_t pid_ = -1;
    bool stopped_ = false;
};

}  // namespace pico
