// The control socket: a Unix socket in the runtime directory, owner-only, answering "status" with the
// machines' status lines (gpsd's control socket, chronyc). A peer of another user is refused.
#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <thread>
#include <vector>

#include "common/fd_util.hpp"
#include "tape/dnc_service.hpp"
#include "tape/error.hpp"

namespace tape::dnc {
namespace {

constexpr std::string_view status_header = "tape-dnc status 1\n";

sockaddr_un address_of(const std::string& path) {
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    if (path.size() >= sizeof a.sun_path)
        throw Error(Errc::usage, path + ": too long for a socket's path (" + std::to_string(sizeof a.sun_path - 1) +
                                     " characters at most)");
    std::memcpy(a.sun_path, path.c_str(), path.size() + 1);
    return a;
}

int connected_socket(const std::string& path) {
    sockaddr_un a = address_of(path);
    int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) io_fail("cannot make a socket");
    if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
        int saved = errno;
        ::close(fd);
        errno = saved;
        return -1;
    }
    return fd;
}

// The socket's folder: made owner-only when missing; one that is there must be a folder of ours closed
// to others already. A folder the service did not make is never changed (a shared one, /tmp, would be
// closed to every user, or lose its sticky bit).
void owner_only_folder(const std::string& folder) {
    if (::mkdir(folder.c_str(), 0700) == 0) return;
    if (errno != EEXIST) io_fail(folder + ": cannot make the runtime folder");
    struct stat st {};
    if (::lstat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::getuid())
        throw Error(Errc::usage, folder + ": the runtime folder is no folder of this user's");
    if ((st.st_mode & 07077) != 0) {
        char mode[8];
        std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
        throw Error(Errc::usage, folder + ": the runtime folder is open to others (mode " + mode +
                                     "): give runtime_directory a folder of its own, or chmod 0700 it");
    }
}

bool peer_is_us(int fd) {
    ucred cred{};
    socklen_t size = sizeof cred;
    return ::getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &cred, &size) == 0 && (cred.uid == ::getuid() || cred.uid == 0);
}

std::string field(std::string s) {
    for (char& c : s)
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    return s;
}

std::vector<std::string> split(std::string_view line, char by) {
    std::vector<std::string> parts;
    for (std::size_t from = 0;;) {
        auto at = line.find(by, from);
        parts.emplace_back(line.substr(from, at == std::string_view::npos ? line.npos : at - from));
        if (at == std::string_view::npos) return parts;
        from = at + 1;
    }
}

// A peer served at most this long: one that connects and says nothing keeps no other waiting.
constexpr auto peer_deadline = std::chrono::milliseconds(1000);
// Peers served at once; past it the one that came first is let go.
constexpr std::size_t max_peers = 64;
// The longest request read.
constexpr std::size_t max_request = 64;

struct Peer {
    int fd;
    std::chrono::steady_clock::time_point deadline;
    std::string request{};
};

}  // namespace

std::optional<std::string> control_reply(std::string_view request, bool complete,
                                         const std::function<std::string()>& status) {
    auto end = request.find('\n');
    if (end == std::string_view::npos && !complete && request.size() < max_request) return std::nullopt;
    std::string_view line = request.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line == "status" ? status() : std::string();
}

struct ControlSocket::State {
    std::string path;
    int fd = -1;
    std::atomic<bool> stop{false};
    std::thread thread;
    std::function<std::string()> answer;
    std::vector<Peer> peers;

    // Every peer from one thread, none waited for: each is read when it has something to say.
    void serve() {
        while (!stop) {
            std::vector<pollfd> fds{{fd, POLLIN, 0}};
            for (const auto& p : peers) fds.push_back({p.fd, POLLIN, 0});
            if (::poll(fds.data(), fds.size(), 100) < 0) continue;
            auto now = std::chrono::steady_clock::now();
            for (std::size_t i = peers.size(); i-- > 0;)
                if ((fds[i + 1].revents && read_from(peers[i])) || now >= peers[i].deadline) let_go(i);
            if (fds[0].revents & POLLIN) accept_peers(now);
        }
        while (!peers.empty()) let_go(peers.size() - 1);
    }
    void accept_peers(std::chrono::steady_clock::time_point now) {
        for (int peer; (peer = ::accept4(fd, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK)) >= 0;) {
            if (!peer_is_us(peer)) {
                ::close(peer);
                continue;
            }
            if (peers.size() >= max_peers) let_go(0);
            peers.push_back(Peer{peer, now + peer_deadline});
        }
    }
    // Reads what the peer sent; true when it is done with (answered, gone, or asking for nothing).
    bool read_from(Peer& p) {
        char buf[max_request];
        ssize_t n = ::read(p.fd, buf, max_request - p.request.size());
        if (n < 0) return errno != EAGAIN && errno != EINTR;
        p.request.append(buf, static_cast<std::size_t>(n));
        auto reply = control_reply(p.request, n == 0, answer);
        if (!reply) return false;
        if (!reply->empty()) {
            ::fcntl(p.fd, F_SETFL, 0);  // the answer written whole, within the peer's deadline
            timeval t{.tv_sec = 1, .tv_usec = 0};
            ::setsockopt(p.fd, SOL_SOCKET, SO_SNDTIMEO, &t, sizeof t);
            write_all(p.fd, *reply);
        }
        return true;
    }
    void let_go(std::size_t i) {
        ::close(peers[i].fd);
        peers.erase(peers.begin() + static_cast<std::ptrdiff_t>(i));
    }
};

ControlSocket::ControlSocket(const std::string& path, std::function<std::string()> answer)
    : s_(std::make_unique<State>()) {
    s_->path = path;
    s_->answer = std::move(answer);
    owner_only_folder(path.substr(0, path.rfind('/')));
    if (int other = connected_socket(path); other >= 0) {
        ::close(other);
        throw Error(Errc::usage, path + ": another tape dnc answers there already");
    }
    ::unlink(path.c_str());  // a socket left by a service that died
    sockaddr_un a = address_of(path);
    s_->fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);  // accepted until none waits
    if (s_->fd < 0) io_fail("cannot make a socket");
    mode_t old = ::umask(0177);  // the socket 0600: read and written by its owner only
    int bound = ::bind(s_->fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
    ::umask(old);
    if (bound != 0 || ::listen(s_->fd, 8) != 0) {
        int saved = errno;
        ::close(s_->fd);
        errno = saved;
        io_fail(path + ": cannot listen there");
    }
    s_->thread = std::thread([s = s_.get()] { s->serve(); });
}

ControlSocket::~ControlSocket() {
    s_->stop = true;
    s_->thread.join();
    ::close(s_->fd);
    ::unlink(s_->path.c_str());
}

std::string query_control_socket(const std::string& path, std::chrono::milliseconds timeout) {
    int fd = connected_socket(path);
    if (fd < 0) io_fail(path + ": no tape dnc answers there");
    std::string reply;
    write_all(fd, "status\n");
    char buf[4096];
    for (;;) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0) break;
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n <= 0) break;
        reply.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    if (!reply.starts_with(status_header)) throw Error(Errc::io, path + ": the answer is no tape dnc status");
    return reply;
}

std::string status_lines(const std::vector<MachineStatus>& machines) {
    std::string out(status_header);
    for (const auto& m : machines)
        out += field(m.name) + '\t' + field(m.device) + '\t' + std::string(line_state_name(m.state)) + '\t' +
               field(m.program) + '\t' + std::to_string(m.frames) + '\t' + std::to_string(m.total) + '\t' +
               std::to_string(m.sent) + '\t' + std::to_string(m.filed) + '\t' + std::to_string(m.failed) + '\t' +
               field(m.last) + '\n';
    return out;
}

std::vector<MachineStatus> parse_status_lines(std::string_view text) {
    std::vector<MachineStatus> all;
    if (!text.starts_with(status_header)) return all;
    text.remove_prefix(status_header.size());
    for (const auto& line : split(text, '\n')) {
        auto f = split(line, '\t');
        if (f.size() != 10) continue;
        MachineStatus m{.name = f[0], .device = f[1]};
        for (LineState s : {LineState::opening, LineState::listening, LineState::receiving, LineState::sending,
                            LineState::waiting, LineState::stopped})
            if (line_state_name(s) == f[2]) m.state = s;
        m.program = f[3];
        m.frames = std::strtoull(f[4].c_str(), nullptr, 10);
        m.total = std::strtoull(f[5].c_str(), nullptr, 10);
        m.sent = std::strtoull(f[6].c_str(), nullptr, 10);
        m.filed = std::strtoull(f[7].c_str(), nullptr, 10);
        m.failed = std::strtoull(f[8].c_str(), nullptr, 10);
        m.last = f[9];
        all.push_back(std::move(m));
    }
    return all;
}

}  // namespace tape::dnc
