// The payload files of a bag folder and the names of its tag files.
#include "archive/bag_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "common/fd_util.hpp"

namespace tape::bag {

std::vector<std::string> payload_files(const std::filesystem::path& folder, std::vector<std::string>* others) {
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    fs::path data = folder / "data";
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(data, ec))) return out;
    for (auto it = fs::recursive_directory_iterator(data, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        fs::file_status st = it->symlink_status(ec);
        if (fs::is_directory(st)) continue;
        std::string rel = it->path().lexically_relative(folder).generic_string();
        if (fs::is_regular_file(st))
            out.push_back(rel);
        else if (others)
            others->push_back(rel);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string manifest_algorithm(std::string_view name, std::string_view prefix) {
    constexpr std::string_view suffix = ".txt";
    if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix)) return "";
    return std::string(name.substr(prefix.size(), name.size() - prefix.size() - suffix.size()));
}

bool written_tag_file(std::string_view name) {
    return name == "bagit.txt" || name == "bag-info.txt" || !manifest_algorithm(name, "manifest-").empty() ||
           !manifest_algorithm(name, "tagmanifest-").empty();
}

void write_synced(const std::filesystem::path& path, std::string_view data) {
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) io_fail(path.string());
    bool ok = write_all(fd, data) && ::fsync(fd) == 0;
    int e = errno;
    ::close(fd);
    if (!ok) {
        errno = e;
        io_fail(path.string());
    }
}

}  // namespace tape::bag
