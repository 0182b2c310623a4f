// Loading the picture module (picture_module_loader.hpp) with dlopen, and tape/picture.hpp and
// scan_available() through it. The module is looked for where this program's installation keeps it
// (beside the program, as in the build tree and any prefix it was installed to), then where it was
// configured to be installed; TAPE_PICTURE_MODULE names another file, for tests and packagers.
#include "scan/picture_module_loader.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "tape/scan.hpp"

#ifndef TAPE_PICTURE_MODULE_BUILT
#error "CMakeLists.txt says whether the picture module is built, and where it is installed"
#endif

namespace tape::picture_module {
namespace {

struct Loaded {
    const Api* api = nullptr;
    std::string why;  // empty when api is there
};

std::vector<std::string> candidates() {
    if (const char* path = std::getenv("TAPE_PICTURE_MODULE"); path && *path) return {path};
    std::vector<std::string> out;
    std::error_code ec;
    std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) out.push_back((program.parent_path() / ".." / TAPE_PICTURE_MODULE_RELATIVE).lexically_normal().string());
    if (out.empty() || out.front() != TAPE_PICTURE_MODULE_INSTALLED) out.push_back(TAPE_PICTURE_MODULE_INSTALLED);
    return out;
}

Loaded open_module(const std::string& path) {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
        return {nullptr, std::string("cannot load the picture module, which reads and writes pictures through "
                                     "OpenCV: ") +
                             dlerror() +
                             " (it needs OpenCV's core, imgproc and imgcodecs libraries; "
                             "Debian: libopencv-imgcodecs406)"};
    auto entry = reinterpret_cast<const Api* (*)()>(dlsym(handle, "tape_picture_module_api"));
    const Api* table = entry ? entry() : nullptr;
    if (!table || table->abi != abi_version)
        return {nullptr, path + " is not the picture module of this build of tape (reinstall tape)"};
    return {table, ""};  // never closed: its functions serve until the program ends
}

Loaded load() {
    if (!TAPE_PICTURE_MODULE_BUILT)
        return {nullptr,
                "built without OpenCV: reading pictures needs it (install libopencv-imgcodecs-dev and "
                "libopencv-imgproc-dev, or run scripts/install-deps.sh features, then build again)"};
    std::vector<std::string> paths = candidates();
    std::string looked;
    for (const auto& path : paths) {
        if (std::filesystem::exists(path)) return open_module(path);
        looked += (looked.empty() ? "" : ", ") + path;
    }
    return {nullptr, "the picture module is not installed (looked for " + looked + "): reinstall tape"};
}

const Loaded& loaded() {
    static const Loaded module = load();
    return module;
}

}  // namespace

const Api& api() {
    const Loaded& m = loaded();
    if (!m.api) throw Error(Errc::io, m.why);
    return *m.api;
}

const std::string& unavailable_reason() { return loaded().why; }

}  // namespace tape::picture_module

namespace tape {

bool scan_available() { return picture_module::unavailable_reason().empty(); }

std::string_view scan_unavailable_message() { return picture_module::unavailable_reason(); }

std::vector<std::uint8_t> encode_picture(const Picture& picture, std::string_view format, int quality) {
    std::vector<std::uint8_t> out;
    picture_module::call(picture_module::api().encode, picture, format, quality, out);
    return out;
}

Picture decode_picture(std::span<const std::uint8_t> bytes) {
    Picture out;
    picture_module::call(picture_module::api().decode, bytes, out);
    return out;
}

}  // namespace tape
