#include "common/module_loader.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace tape::modules {
namespace {

// "the picture module" of "the picture module, which reads ...".
std::string module_name(const ModuleSpec& spec) {
    std::string what = spec.what;
    return what.substr(0, what.find(','));
}

std::vector<std::string> candidates(const ModuleSpec& spec) {
    if (const char* path = std::getenv(spec.env); path && *path) return {path};
    std::vector<std::string> out;
    std::error_code ec;
    std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) out.push_back((program.parent_path() / ".." / spec.relative).lexically_normal().string());
    if (out.empty() || out.front() != spec.installed) out.push_back(spec.installed);
    return out;
}

Opened open_file(const ModuleSpec& spec, const std::string& path) {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) return {nullptr, std::string("cannot load ") + spec.what + ": " + dlerror() + " (" + spec.needs + ")"};
    auto entry = reinterpret_cast<const void* (*)()>(dlsym(handle, spec.symbol));
    const void* table = entry ? entry() : nullptr;
    if (!table) return {nullptr, path + " is not " + module_name(spec) + " of this build of tape (reinstall tape)"};
    return {table, "", path};
}

}  // namespace

Opened open_module(const ModuleSpec& spec) {
    std::vector<std::string> paths = candidates(spec);
    std::string looked;
    for (const auto& path : paths) {
        if (std::filesystem::exists(path)) return open_file(spec, path);
        looked += (looked.empty() ? "" : ", ") + path;
    }
    return {nullptr, module_name(spec) + " is not installed (looked for " + looked + "): reinstall tape"};
}

}  // namespace tape::modules
