// tape/scan.hpp and tape/picture.hpp in a build without OpenCV: the functions are there and say what is missing, as
// libusb's null backend does, so that `tape scan` is a command of every build.
#include "tape/error.hpp"
#include "tape/picture.hpp"
#include "tape/scan.hpp"

namespace tape {

bool scan_available() { return false; }

std::string_view scan_unavailable_message() {
    return "built without OpenCV: reading pictures needs it (install libopencv-imgcodecs-dev and "
           "libopencv-imgproc-dev, or run scripts/install-deps.sh all, then build again)";
}

ScanResult scan_images(std::span<const std::string>, const ScanOptions&) {
    throw Error(Errc::io, std::string(scan_unavailable_message()));
}

std::vector<std::uint8_t> encode_picture(const Picture&, std::string_view, int) {
    throw Error(Errc::io, std::string(scan_unavailable_message()));
}

Picture decode_picture(std::span<const std::uint8_t>) {
    throw Error(Errc::io, std::string(scan_unavailable_message()));
}

}  // namespace tape
