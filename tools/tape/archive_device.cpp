// tape archive create --from: the tape read several times from an adapter straight into the bag's
// data/reads/, forwards and backwards in turn, as tape read reads it (archive_bag.hpp).
#include <filesystem>

#include "archive_bag.hpp"
#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "cli/run.hpp"
#include "receive_image.hpp"

namespace cli {
namespace {

// Only an adapter's reader can be sent back over the tape it has just read; a serial reader would need
// the tape loaded again by hand between reads.
void check_device(const std::string& device) {
    if (!device.starts_with("adapter:") && !device.starts_with("usb:"))
        fail(device, tape::Errc::usage,
             "--from reads the tape forwards and backwards in turn: give an adapter (adapter:PATH or usb:...)");
    if (device.find("direction=") != std::string::npos)
        fail(device, tape::Errc::usage, "--from chooses the direction of each read itself: give the device without it");
}

}  // namespace

std::vector<std::string> device_read_names(unsigned times) {
    std::vector<std::string> names;
    for (unsigned k = 1; k <= times; ++k) names.push_back("reads/read-" + std::to_string(k) + ".ptp");
    return names;
}

void read_from_device(tape::BagWriter& bag, const std::string& device, const std::vector<std::string>& names,
                      double timeout_s) {
    check_device(device);
    std::filesystem::create_directories(bag.staging() + "/data/reads");
    tape::ReceiveOptions o;
    o.idle_timeout = std::chrono::milliseconds(static_cast<long long>(timeout_s * 1000));
    for (std::size_t k = 0; k < names.size(); ++k) {
        // The odd reads go back over the tape the read before went over: each starts where the last ended.
        bool back = k % 2 == 1;
        std::string line =
            back ? device + (device.find('?') == std::string::npos ? "?" : "&") + "direction=reverse" : device;
        say(device, "read " + std::to_string(k + 1) + " of " + std::to_string(names.size()) +
                        (back ? ", backwards to the tape's start" : ", forwards"));
        std::string path = bag.staging() + "/data/" + names[k];
        auto end = receive_into_image(line, path, "raw", false, o, false, "read");
        release_output(path);  // written whole: now a read to restore
        if (end == tape::ReceiveResult::End::stopped) {
            say(device, "stopped: no bag made");
            throw Exit{interrupted_status};
        }
        // A read backwards is turned to the tape's order only when it reached the tape's start.
        if (back && end != tape::ReceiveResult::End::hangup)
            fail(device, tape::Errc::io,
                 "read " + std::to_string(k + 1) + " went backwards and did not reach the tape's start: no bag made");
    }
}

}  // namespace cli
