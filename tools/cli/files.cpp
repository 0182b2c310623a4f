#include "cli/files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <optional>
#include <vector>

#include "cli/inputs.hpp"
#include "cli/messages.hpp"

namespace cli {
namespace {

struct FileId {
    dev_t device;
    ino_t inode;
    bool operator==(const FileId&) const = default;
};

struct Files {
    std::vector<std::pair<std::string, FileId>> inputs;
    std::vector<std::string> outputs;  ///< where each went (place())
};

Files& files() {
    static Files f;
    return f;
}

// The regular file a path (or "-": the standard stream fd) names, through links; nothing for devices,
// FIFOs and terminals, which may well be read and written at once (a serial line).
std::optional<FileId> regular_file(const std::string& path, int fd) {
    struct stat st {};
    int r = path.empty() || path == "-" ? ::fstat(fd, &st) : ::stat(path.c_str(), &st);
    if (r != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    return FileId{st.st_dev, st.st_ino};
}

// Where a file written to path ends up: its folder resolved, a symbolic link followed (also one to a
// file not there yet, which writing it creates).
std::string place(std::string path) {
    char resolved[PATH_MAX];
    for (int hop = 0; hop < 40; ++hop) {
        if (::realpath(path.c_str(), resolved)) return resolved;
        ssize_t n = ::readlink(path.c_str(), resolved, sizeof resolved - 1);
        if (n < 0) break;
        std::string target(resolved, static_cast<std::size_t>(n));
        auto slash = path.rfind('/');
        path = target.starts_with('/') || slash == std::string::npos ? target : path.substr(0, slash + 1) + target;
    }
    auto slash = path.rfind('/');
    std::string dir = slash == std::string::npos ? "." : path.substr(0, slash + 1);
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    if (!::realpath(dir.c_str(), resolved)) return path;
    return std::string(resolved) + "/" + name;
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    fail(path == "-" ? "stdout" : path, tape::Errc::usage, why);
}

}  // namespace

void note_input(const std::string& path) {
    auto id = regular_file(path, STDIN_FILENO);
    if (!id) return;
    for (const auto& out : files().outputs)
        if (regular_file(out, STDOUT_FILENO) == id)
            refuse(display_name(path), "is also an output of this run: refusing to read what it writes over");
    files().inputs.emplace_back(path, *id);
}

void claim_output(const std::string& path) {
    auto id = regular_file(path, STDOUT_FILENO);
    for (const auto& [in, in_id] : files().inputs)
        if (id == in_id)
            refuse(path, "is also the input " + display_name(in) +
                             ": refusing to write over what is being read; give another file");
    if (path.empty() || path == "-") return;  // standard output takes every piece written to it
    std::string where = place(path);
    for (const auto& out : files().outputs)
        if (out == where || (id && regular_file(out, STDOUT_FILENO) == id))
            refuse(path, "is already written by this run (another of its outputs): give each output its own file");
    files().outputs.push_back(where);
}

void release_output(const std::string& path) { std::erase(files().outputs, place(path)); }

void check_outputs(std::initializer_list<std::pair<std::string_view, std::string>> outputs) {
    for (auto a = outputs.begin(); a != outputs.end(); ++a)
        for (auto b = a + 1; b != outputs.end(); ++b) {
            if (a->second.empty() || b->second.empty() || a->second == "-" || b->second == "-") continue;
            auto id = regular_file(a->second, STDOUT_FILENO);
            if (place(a->second) == place(b->second) || (id && regular_file(b->second, STDOUT_FILENO) == id))
                refuse(b->second, "is given for both " + std::string(a->first) + " and " + std::string(b->first) +
                                      ": give each output its own file");
        }
}

}  // namespace cli
