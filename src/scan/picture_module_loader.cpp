// Loading the picture module (picture_module_loader.hpp) as common/module_loader.hpp loads any module, and
// tape/picture.hpp and scan_available() through it; TAPE_PICTURE_MODULE names another file, for tests and
// packagers.
#include "scan/picture_module_loader.hpp"

#include "common/module_loader.hpp"
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

Loaded load() {
    if (!TAPE_PICTURE_MODULE_BUILT)
        return {nullptr,
                "built without OpenCV: reading pictures needs it (install libopencv-imgcodecs-dev and "
                "libopencv-imgproc-dev, or run scripts/install-deps.sh features, then build again)"};
    static const modules::ModuleSpec spec{
        "the picture module, which reads and writes pictures through OpenCV",
        "TAPE_PICTURE_MODULE",
        TAPE_PICTURE_MODULE_RELATIVE,
        TAPE_PICTURE_MODULE_INSTALLED,
        "tape_picture_module_api",
        "it needs OpenCV's core, imgproc and imgcodecs libraries; Debian: libopencv-imgcodecs406"};
    modules::Opened m = modules::open_module(spec);
    auto table = static_cast<const Api*>(m.table);
    if (table && table->abi != abi_version)
        return {nullptr, m.path + " is not the picture module of this build of tape (reinstall tape)"};
    return {table, m.why};
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
