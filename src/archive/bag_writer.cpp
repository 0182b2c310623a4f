// Making a bag in a staging folder beside its target and putting it in place whole (tape/archive.hpp).
#include <fcntl.h>
#include <stdio.h>  // renameat2
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include "archive/bag_files.hpp"
#include "common/fd_util.hpp"
#include "tape/archive.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"

namespace tape {

namespace fs = std::filesystem;

struct BagWriter::State {
    fs::path target, staging;
    bool replace = false;
    bool committed = false;
    std::vector<BagInfoEntry> previous;
};

namespace {

fs::path make_staging(const fs::path& target) {
    fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::string pattern = (parent / ("." + target.filename().string() + ".partial-XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) io_fail("cannot make a folder beside " + target.string());
    std::error_code ec;
    fs::permissions(pattern,
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                        fs::perms::others_exec,
                    ec);
    return pattern;
}

// A payload path as given: relative, '/'-separated, with no empty, "." or ".." part.
void check_payload_path(std::string_view path) {
    bool ok = !path.empty() && path.front() != '/';
    for (const auto& part : fs::path(path)) ok = ok && part != "." && part != ".." && !part.empty();
    if (!ok || path.back() == '/' || path.find("//") != std::string_view::npos)
        throw Error(Errc::usage, "not a payload path: '" + std::string(path) + "'");
}

std::string today_utc() {
    std::time_t t = std::time(nullptr);
    std::tm tm{};
    ::gmtime_r(&t, &tm);
    char buf[16];
    std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
    return buf;
}

void sync_folder(const fs::path& folder) {
    int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // a folder that cannot be opened is still renamed; nothing more to make sure of
    ::fsync(fd);
    ::close(fd);
}

// The payload manifests and what they add up to.
struct Manifests {
    std::string sha256, sha512;
    std::uint64_t octets = 0, files = 0;
};

Manifests payload_manifests(const fs::path& staging) {
    Manifests m;
    for (const std::string& rel : bag::payload_files(staging)) {
        Digests d = digest_file((staging / rel).string());
        std::string name = bag_encoded_path(rel);
        m.sha256 += d.sha256 + "  " + name + "\n";
        m.sha512 += d.sha512 + "  " + name + "\n";
        m.octets += d.bytes;
        ++m.files;
    }
    return m;
}

std::string bag_info_text(const std::vector<BagInfoEntry>& info, const Manifests& m) {
    std::string s;
    bool dated = false;
    for (const auto& e : info) {
        if (e.label == "Payload-Oxum" || e.label == "Bag-Size") continue;
        dated = dated || e.label == "Bagging-Date";
        s += e.label + ": " + e.value + "\n";
    }
    if (!dated) s += "Bagging-Date: " + today_utc() + "\n";
    s += "Payload-Oxum: " + payload_oxum(m.octets, m.files) + "\n";
    return s;
}

// Every tag file in the staging folder's top (the tag manifests excepted), as tagmanifest-sha256.txt lists them.
std::string tag_manifest(const fs::path& staging) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(staging))
        if (e.is_regular_file() && bag::manifest_algorithm(e.path().filename().string(), "tagmanifest-").empty())
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string s;
    for (const auto& n : names) s += digest_file((staging / n).string()).sha256 + "  " + bag_encoded_path(n) + "\n";
    return s;
}

void link_or_copy(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::create_directories(to.parent_path());
    fs::create_hard_link(from, to, ec);
    if (ec) fs::copy_file(from, to);
}

}  // namespace

BagWriter::BagWriter(std::unique_ptr<State> state) : state_(std::move(state)) {}

BagWriter::BagWriter(std::string target, bool replace) : state_(std::make_unique<State>()) {
    state_->target = target;
    state_->replace = replace;
    if (!replace && path_exists(target)) throw Error(Errc::exists, target + " exists (replace it with --force)");
    state_->staging = make_staging(state_->target);
    fs::create_directory(state_->staging / "data");
}

BagWriter BagWriter::update(const std::string& target) {
    if (!fs::is_regular_file(fs::path(target) / "bagit.txt"))
        throw Error(Errc::io, target + " is no bag (it has no bagit.txt)");
    auto s = std::make_unique<State>();
    s->target = target;
    s->replace = true;
    s->staging = make_staging(s->target);
    BagWriter w(std::move(s));
    fs::create_directory(w.state_->staging / "data");
    for (const std::string& rel : bag::payload_files(target))
        link_or_copy(fs::path(target) / rel, w.state_->staging / rel);
    for (const auto& e : fs::directory_iterator(target))
        if (e.is_regular_file() && !bag::written_tag_file(e.path().filename().string()))
            link_or_copy(e.path(), w.state_->staging / e.path().filename());
    if (path_exists(target + "/bag-info.txt")) {
        auto bytes = read_file(target + "/bag-info.txt");
        w.state_->previous =
            parse_bag_info(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    }
    return w;
}

BagWriter::BagWriter(BagWriter&&) noexcept = default;

BagWriter::~BagWriter() {
    if (!state_ || state_->committed) return;
    std::error_code ec;
    fs::remove_all(state_->staging, ec);
}

bool BagWriter::has(std::string_view path) const {
    std::error_code ec;
    return fs::exists(fs::symlink_status(state_->staging / "data" / fs::path(path), ec));
}

void BagWriter::add(std::string_view path, std::string_view bytes) {
    check_payload_path(path);
    if (has(path)) throw Error(Errc::usage, "data/" + std::string(path) + " is already in the bag");
    fs::path to = state_->staging / "data" / fs::path(path);
    fs::create_directories(to.parent_path());
    bag::write_synced(to, bytes);
}

void BagWriter::add_copy(std::string_view path, const std::string& source) {
    auto bytes = read_file(source);
    add(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

const std::vector<BagInfoEntry>& BagWriter::previous_info() const { return state_->previous; }

const std::string& BagWriter::staging() const { return state_->staging.native(); }

void BagWriter::commit(const std::vector<BagInfoEntry>& info) {
    const fs::path& st = state_->staging;
    Manifests m = payload_manifests(st);
    bag::write_synced(st / "bagit.txt", "BagIt-Version: 1.0\nTag-File-Character-Encoding: UTF-8\n");
    bag::write_synced(st / "bag-info.txt", bag_info_text(info, m));
    bag::write_synced(st / "manifest-sha256.txt", m.sha256);
    bag::write_synced(st / "manifest-sha512.txt", m.sha512);
    bag::write_synced(st / "tagmanifest-sha256.txt", tag_manifest(st));
    for (const auto& e : fs::recursive_directory_iterator(st))
        if (e.is_directory()) sync_folder(e.path());
    sync_folder(st);
    const fs::path& target = state_->target;
    if (::renameat2(AT_FDCWD, st.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0) {
        state_->committed = true;
    } else if (errno == EEXIST || errno == ENOTEMPTY) {
        if (!state_->replace) throw Error(Errc::exists, target.string() + " exists (replace it with --force)");
        // The old bag and the new one change places in one step: at no moment is there no bag, or half of one.
        if (::renameat2(AT_FDCWD, st.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0)
            io_fail("cannot put the bag in place of " + target.string());
        state_->committed = true;
        std::error_code ec;
        fs::remove_all(st, ec);  // now the old bag
    } else {
        io_fail("cannot put the bag at " + target.string());
    }
    sync_folder(target.parent_path().empty() ? fs::path(".") : target.parent_path());
}

}  // namespace tape
