// Looking a requested name up in the program library: the folder's entries are listed and compared
// with the name, so no name from a line ever becomes a path of its own.
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <map>
#include <mutex>

#include "common/fd_util.hpp"
#include "tape/dnc_request.hpp"
#include "tape/error.hpp"
#include "tape/program.hpp"

namespace tape::dnc {
namespace {

// Enough of a program's start to hold its number.
constexpr std::size_t head_size = 8192;

bool same_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

std::string_view stem(std::string_view file) {
    auto dot = file.rfind('.');
    return dot == std::string_view::npos || dot == 0 ? file : file.substr(0, dot);
}

// "O0012", "o12", ":12", "12" -> "12"; nullopt when name is no program number.
std::optional<std::string> number_digits(std::string_view name) {
    if (!name.empty() && (name[0] == 'O' || name[0] == 'o' || name[0] == ':')) name.remove_prefix(1);
    if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    auto first = name.find_first_not_of('0');
    return std::string(first == std::string_view::npos ? "0" : name.substr(first));
}

std::vector<std::string> regular_files(const std::string& folder) {
    std::vector<std::string> files;
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return files;
    while (dirent* e = ::readdir(dir)) {
        std::string name = e->d_name;
        if (name.empty() || name[0] == '.') continue;
        struct stat st {};
        // A symbolic link is no program of the library: it may point anywhere (/etc/passwd).
        if (::fstatat(::dirfd(dir), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode))
            files.push_back(name);
    }
    ::closedir(dir);
    std::sort(files.begin(), files.end());
    return files;
}

std::string head_of(const std::string& path) {
    std::string text(head_size, '\0');
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return {};
    ssize_t n = ::read(fd, text.data(), text.size());
    ::close(fd);
    text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    return text;
}

std::optional<std::string> program_number(std::string_view text) {
    LoadOptions o;
    o.dialect = guess_dialect(text).dialect;
    LoadedTape tape = load(std::string(text), {}, o);
    for (const auto& p : tape.programs)
        if (p.number) return *p.number;
    return std::nullopt;
}

// The program number of the file at path, read once while its size and time stay the same: a lookup by
// number reads every file of the library, and a shop asks all day.
std::optional<std::string> cached_number(const std::string& path) {
    struct Entry {
        off_t size;
        timespec mtime;
        std::optional<std::string> number;
    };
    static std::mutex mutex;
    static std::map<std::string, Entry> cache;
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    {
        std::lock_guard lock(mutex);
        auto at = cache.find(path);
        if (at != cache.end() && at->second.size == st.st_size && at->second.mtime.tv_sec == st.st_mtim.tv_sec &&
            at->second.mtime.tv_nsec == st.st_mtim.tv_nsec)
            return at->second.number;
    }
    auto number = program_number(head_of(path));
    std::lock_guard lock(mutex);
    cache[path] = Entry{st.st_size, st.st_mtim, number};
    return number;
}

Found one_of(const std::string& folder, const std::vector<std::string>& matches, std::string_view how) {
    if (matches.size() == 1) return {folder + "/" + matches[0], ""};
    return {"", "ambiguous: " + matches[0] + " and " + matches[1] + " both " + std::string(how)};
}

}  // namespace

Found find_program(const std::string& folder, std::string_view name) {
    if (!name_problem(name).empty()) return {"", "not a name"};
    auto files = regular_files(folder);
    std::vector<std::string> exact, either_case, by_number;
    for (const auto& f : files) {
        if (f == name || stem(f) == name) exact.push_back(f);
        if (same_ignoring_case(f, name) || same_ignoring_case(stem(f), name)) either_case.push_back(f);
    }
    if (!exact.empty()) return one_of(folder, exact, "are named so");
    if (!either_case.empty()) return one_of(folder, either_case, "are named so");
    auto wanted = number_digits(name);
    if (!wanted) return {"", "not in the library"};
    for (const auto& f : files) {
        auto number = cached_number(folder + "/" + f);
        if (number && number_digits(*number) == wanted) by_number.push_back(f);
    }
    if (by_number.empty()) return {"", "not in the library"};
    return one_of(folder, by_number, "hold program " + std::string(name));
}

std::string read_program(const std::string& path) {
    // O_NOFOLLOW: a file made a link since it was found is not read through it; O_NONBLOCK: nor a FIFO waited on.
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) io_fail(path + ": cannot open (a symbolic link is never followed)");
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw Error(Errc::io, path + ": no regular file");
    }
    std::string text;
    char buf[65536];
    for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) != 0;) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            int saved = errno;
            ::close(fd);
            errno = saved;
            io_fail(path + ": cannot read");
        }
        text.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return text;
}

std::optional<std::string> program_file_stem(std::string_view text) {
    auto number = program_number(text.substr(0, head_size));
    if (!number) return std::nullopt;
    std::string n = *number;
    if (!n.empty() && n[0] == ':') n[0] = 'O';  // Fanuc's ':1234' is O1234
    if (!name_problem(n).empty()) return std::nullopt;
    return n;
}

}  // namespace tape::dnc
