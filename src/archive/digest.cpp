// SHA-256 and SHA-512 for bag manifests, from nettle (Debian: libnettle8; SHA-NI where the processor has
// it). nettle is opened with dlopen on the first checksum rather than linked: only tape archive needs it,
// and every other command's start (tape --version's 10 ms) pays for each library linked.
#include <dlfcn.h>
#include <fcntl.h>
#include <nettle/sha2.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>
#include <vector>

#include "common/fd_util.hpp"
#include "tape/archive.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

struct Nettle {
    decltype(&nettle_sha256_init) init256 = nullptr;
    decltype(&nettle_sha256_update) update256 = nullptr;
    decltype(&nettle_sha256_digest) digest256 = nullptr;
    decltype(&nettle_sha512_init) init512 = nullptr;
    decltype(&nettle_sha512_update) update512 = nullptr;
    decltype(&nettle_sha512_digest) digest512 = nullptr;
    std::string why;  // empty when loaded
};

template <typename F>
void find(void* handle, const char* name, F& f, std::string& why) {
    f = reinterpret_cast<F>(dlsym(handle, name));
    if (!f && why.empty()) why = std::string("libnettle.so.8 has no ") + name;
}

Nettle load() {
    Nettle n;
    void* handle = dlopen("libnettle.so.8", RTLD_NOW | RTLD_LOCAL);  // never closed: it serves to the end
    if (!handle) {
        n.why = std::string("the checksums of a bag need nettle, which could not be loaded: ") + dlerror() +
                " (Debian: libnettle8)";
        return n;
    }
    find(handle, "nettle_sha256_init", n.init256, n.why);
    find(handle, "nettle_sha256_update", n.update256, n.why);
    find(handle, "nettle_sha256_digest", n.digest256, n.why);
    find(handle, "nettle_sha512_init", n.init512, n.why);
    find(handle, "nettle_sha512_update", n.update512, n.why);
    find(handle, "nettle_sha512_digest", n.digest512, n.why);
    return n;
}

const Nettle& nettle() {
    static const Nettle n = load();
    if (!n.why.empty()) throw Error(Errc::io, n.why);
    return n;
}

std::string hex(const std::uint8_t* d, std::size_t n) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string s(2 * n, '0');
    for (std::size_t i = 0; i < n; ++i) s[2 * i] = digits[d[i] >> 4], s[2 * i + 1] = digits[d[i] & 15];
    return s;
}

// Both digests of a stream in one pass: the bytes are read once.
class Hasher {
public:
    Hasher() : n_(nettle()) {
        n_.init256(&a_);
        n_.init512(&b_);
    }
    void update(const std::uint8_t* data, std::size_t size) {
        n_.update256(&a_, size, data);
        n_.update512(&b_, size, data);
        bytes_ += size;
    }
    Digests finish() {
        std::uint8_t a[SHA256_DIGEST_SIZE], b[SHA512_DIGEST_SIZE];
        n_.digest256(&a_, sizeof a, a);
        n_.digest512(&b_, sizeof b, b);
        return {hex(a, sizeof a), hex(b, sizeof b), bytes_};
    }

private:
    const Nettle& n_;
    sha256_ctx a_;
    sha512_ctx b_;
    std::uint64_t bytes_ = 0;
};

}  // namespace

Digests digest_bytes(std::span<const std::uint8_t> bytes) {
    Hasher h;
    h.update(bytes.data(), bytes.size());
    return h.finish();
}

Digests digest_file(const std::string& path) {
    Hasher h;
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) io_fail(path);
    std::vector<std::uint8_t> buf(1 << 20);
    for (;;) {
        ssize_t got = ::read(fd, buf.data(), buf.size());
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            int e = errno;
            ::close(fd);
            errno = e;
            io_fail(path);
        }
        if (got == 0) break;
        h.update(buf.data(), static_cast<std::size_t>(got));
    }
    ::close(fd);
    return h.finish();
}

}  // namespace tape
