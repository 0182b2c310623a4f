// Verifying a bag (RFC 8493 §3): valid when every manifest's every file is there with its checksum, every
// payload file is listed in every payload manifest, and Payload-Oxum, where given, counts the payload.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "archive/bag_files.hpp"
#include "tape/archive.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"

namespace tape {

namespace fs = std::filesystem;

bool BagCheck::valid() const {
    for (const auto& p : problems)
        if (!p.note) return false;
    return true;
}

namespace {

// Digests are made once a file, however many manifests list it.
class Checker {
public:
    Checker(const fs::path& bag, BagCheck& out) : bag_(bag), out_(out) {}

    void problem(std::string id, std::string file, std::uint64_t line, std::string message, bool note = false) {
        out_.problems.push_back({std::move(id), std::move(file), line, std::move(message), note});
    }

    std::optional<std::string> text(const std::string& name) {
        std::error_code ec;
        if (!fs::is_regular_file(bag_ / name, ec)) return std::nullopt;
        try {
            auto bytes = read_file((bag_ / name).string());
            return std::string(bytes.begin(), bytes.end());
        } catch (const Error& e) {
            problem("unreadable", name, 0, e.what());
            return std::nullopt;
        }
    }

    const Digests* digests(const std::string& rel) {
        auto it = cache_.find(rel);
        if (it != cache_.end()) return &it->second;
        try {
            return &cache_.emplace(rel, digest_file((bag_ / rel).string())).first->second;
        } catch (const Error& e) {
            problem("unreadable", rel, 0, e.what());
            return nullptr;
        }
    }

    /// Checks each line of a manifest; returns the files it lists.
    std::set<std::string> manifest(const std::string& name, const std::string& algorithm, bool payload) {
        std::set<std::string> listed;
        auto t = text(name);
        if (!t) return listed;
        std::size_t width = algorithm == "sha256" ? 64 : 128;
        std::uint64_t n = 0;
        for (std::string_view line : tag_file_lines(*t)) {
            ++n;
            if (line.empty()) continue;
            std::size_t gap = line.find_first_of(" \t");
            std::size_t start = gap == std::string_view::npos ? gap : line.find_first_not_of(" \t", gap);
            std::string sum(line.substr(0, gap));
            if (start == std::string_view::npos || sum.size() != width ||
                sum.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
                problem("bad-manifest-line", name, n, "not a checksum and a file name: '" + std::string(line) + "'");
                continue;
            }
            std::string rel = bag_decoded_path(line.substr(start));
            if (rel.starts_with("*")) rel.erase(0, 1);  // sha256sum's binary mark, as bagit-python reads it
            file_line(name, n, rel, sum, algorithm, payload, listed);
        }
        return listed;
    }

private:
    void file_line(const std::string& name, std::uint64_t n, const std::string& rel, std::string sum,
                   const std::string& algorithm, bool payload, std::set<std::string>& listed) {
        fs::path p = fs::path(rel).lexically_normal();
        if (p.is_absolute() || p.empty() || *p.begin() == ".." || (payload && !rel.starts_with("data/"))) {
            problem("bad-path", name, n, "'" + rel + "' is not " + (payload ? "under data/" : "inside the bag"));
            return;
        }
        listed.insert(p.generic_string());
        std::error_code ec;
        if (!fs::is_regular_file(fs::symlink_status(bag_ / p, ec))) {
            problem(payload ? "file-missing" : "tag-file-missing", rel, 0,
                    name + " lists it, and it is not in the bag");
            return;
        }
        const Digests* d = digests(p.generic_string());
        if (!d) return;
        for (char& c : sum) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const std::string& have = algorithm == "sha256" ? d->sha256 : d->sha512;
        if (have != sum)
            problem(payload ? "checksum-mismatch" : "tag-checksum-mismatch", rel, 0,
                    "its " + algorithm + " is " + have + ", " + name + " line " + std::to_string(n) + " says " + sum);
    }

    fs::path bag_;
    BagCheck& out_;
    std::map<std::string, Digests> cache_;
};

void check_bagit_txt(Checker& c) {
    auto t = c.text("bagit.txt");
    if (!t) return c.problem("no-bagit-txt", "bagit.txt", 0, "missing: this folder is no bag");
    auto info = parse_bag_info(*t);
    auto version = bag_info_value(info, "BagIt-Version");
    auto encoding = bag_info_value(info, "Tag-File-Character-Encoding");
    if (info.size() != 2 || !version || !encoding)
        c.problem("bad-bagit-txt", "bagit.txt", 0,
                  "should be two lines, BagIt-Version and Tag-File-Character-Encoding");
    else if (*version != "1.0" && *version != "0.97")
        c.problem("bad-bagit-txt", "bagit.txt", 0, "BagIt-Version " + *version + " is not 1.0 (nor 0.97)", true);
}

void check_bag_info(Checker& c, BagCheck& out) {
    auto t = c.text("bag-info.txt");
    if (!t) return;
    std::vector<std::uint64_t> bad;
    out.info = parse_bag_info(*t, &bad);
    for (auto n : bad) c.problem("bad-bag-info-line", "bag-info.txt", n, "not 'Label: value'");
    auto oxum = bag_info_value(out.info, "Payload-Oxum");
    if (!oxum) return;
    std::size_t dot = oxum->find('.');
    bool digits = dot != std::string::npos && dot > 0 && dot + 1 < oxum->size() &&
                  oxum->find_first_not_of("0123456789.") == std::string::npos &&
                  oxum->find('.', dot + 1) == std::string::npos;
    if (!digits) return c.problem("bad-oxum", "bag-info.txt", 0, "Payload-Oxum '" + *oxum + "' is not OCTETS.COUNT");
    std::string have = payload_oxum(out.octets, out.files);
    if (have != *oxum)
        c.problem("oxum-mismatch", "bag-info.txt", 0,
                  "Payload-Oxum says " + *oxum + " (bytes.files), the payload is " + have);
}

}  // namespace

BagCheck verify_bag(const std::string& path) {
    if (!fs::is_directory(path)) throw Error(Errc::io, path + " is no folder");
    BagCheck out;
    Checker c(path, out);
    check_bagit_txt(c);
    std::vector<std::string> others;
    std::vector<std::string> payload = bag::payload_files(path, &others);
    for (const auto& rel : payload) out.octets += fs::file_size(fs::path(path) / rel), ++out.files;
    for (const auto& o : others)
        c.problem("bad-path", o, 0, "neither a file nor a folder (a link?): no payload can be");
    check_bag_info(c, out);
    std::vector<std::pair<std::string, std::string>> manifests, tag_manifests;  // (name, algorithm)
    for (const auto& e : fs::directory_iterator(path)) {
        std::string name = e.path().filename().string();
        if (auto a = bag::manifest_algorithm(name, "manifest-"); !a.empty()) manifests.emplace_back(name, a);
        if (auto a = bag::manifest_algorithm(name, "tagmanifest-"); !a.empty()) tag_manifests.emplace_back(name, a);
    }
    std::sort(manifests.begin(), manifests.end());
    std::sort(tag_manifests.begin(), tag_manifests.end());
    bool checked = false;
    for (const auto& [name, algorithm] : manifests) {
        if (algorithm != "sha256" && algorithm != "sha512") {
            c.problem("unchecked-algorithm", name, 0, algorithm + " is not checked (only sha256 and sha512 are)", true);
            continue;
        }
        checked = true;
        out.algorithms.push_back(algorithm);
        std::set<std::string> listed = c.manifest(name, algorithm, true);
        for (const auto& rel : payload)
            if (!listed.count(rel)) c.problem("file-unlisted", rel, 0, "in data/ but not listed in " + name);
    }
    if (!checked) c.problem("no-manifest", "", 0, "no payload manifest with sha256 or sha512: nothing is checked");
    for (const auto& [name, algorithm] : tag_manifests) {
        if (algorithm != "sha256" && algorithm != "sha512")
            c.problem("unchecked-algorithm", name, 0, algorithm + " is not checked (only sha256 and sha512 are)", true);
        else
            c.manifest(name, algorithm, false);
    }
    return out;
}

}  // namespace tape
