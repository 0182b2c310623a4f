// An RFC 8493 reader written for the tests alone, from the RFC's text and not from the library: what a
// bag tape archive writes must read so to another tool. Checksums come from coreutils' sha256sum and
// sha512sum, run on each file, so that neither the parser nor the digests are the library's own.
#pragma once

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "test_util.hpp"

namespace bagit_reader {

/// Lines of a tag file: the RFC allows LF, CR LF and CR as line ends (§2.1.1 and §7.1).
inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::string line;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\r' || text[i] == '\n') {
            out.push_back(line);
            line.clear();
            if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        } else {
            line += text[i];
        }
    }
    if (!line.empty()) out.push_back(line);
    return out;
}

/// §2.1.3: only %25, %0D and %0A stand for something in a manifest's file path.
inline std::string decode(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        std::string x = i + 2 < s.size() ? s.substr(i, 3) : "";
        for (auto& c : x) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if (x == "%25" || x == "%0D" || x == "%0A") {
            out += x == "%25" ? '%' : x == "%0D" ? '\r' : '\n';
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

/// The checksum coreutils gives a file (algorithm "sha256" or "sha512").
inline std::string coreutils_sum(const std::string& algorithm, const std::string& path) {
    std::string cmd = algorithm + "sum -- '" + path + "'";  // the test paths hold no quote
    FILE* p = ::popen(cmd.c_str(), "r");
    if (!p) return "";
    char buf[256] = {};
    std::string out = std::fgets(buf, sizeof buf, p) ? buf : "";
    ::pclose(p);
    if (!out.empty() && out[0] == '\\') out.erase(0, 1);  // coreutils marks a name it had to escape (a line end)
    return out.substr(0, out.find(' '));
}

// The RFC's line shapes, read by hand: GCC 12 warns (maybe-uninitialized) inside std::regex under the
// sanitizers, and warnings are errors there.
inline bool all_of_class(std::string_view s, const char* cls) {
    return !s.empty() && s.find_first_not_of(cls) == std::string_view::npos;
}
// "BagIt-Version: M.N"
inline bool version_line(std::string_view l) {
    const std::string_view head = "BagIt-Version: ";
    if (l.substr(0, head.size()) != head) return false;
    std::string_view v = l.substr(head.size());
    auto dot = v.find('.');
    return dot != std::string_view::npos && all_of_class(v.substr(0, dot), "0123456789") &&
           all_of_class(v.substr(dot + 1), "0123456789");
}
// "Label: value": the label starts with no ':' or blank and holds no ':'.
inline bool label_line(const std::string& l, std::string& label, std::string& value) {
    auto colon = l.find(':');
    if (l.empty() || colon == 0 || colon == std::string::npos || std::isspace(static_cast<unsigned char>(l[0])))
        return false;
    label = l.substr(0, colon);
    auto start = l.find_first_not_of(" \t", colon + 1);
    value = start == std::string::npos ? "" : l.substr(start);
    return true;
}
// "manifest-ALG.txt", ALG of lowercase letters and digits.
inline bool manifest_name(const std::string& file, std::string& algorithm) {
    const std::string head = "manifest-", tail = ".txt";
    if (file.size() <= head.size() + tail.size() || file.rfind(head, 0) != 0 ||
        file.compare(file.size() - tail.size(), tail.size(), tail) != 0)
        return false;
    algorithm = file.substr(head.size(), file.size() - head.size() - tail.size());
    return all_of_class(algorithm, "abcdefghijklmnopqrstuvwxyz0123456789");
}
// "CHECKSUM PATH": hex digits, blanks, then a path that starts with no blank.
inline bool manifest_entry(const std::string& l, std::string& sum, std::string& path) {
    auto gap = l.find_first_of(" \t");
    if (gap == std::string::npos || !all_of_class(std::string_view(l).substr(0, gap), "0123456789abcdefABCDEF"))
        return false;
    auto start = l.find_first_not_of(" \t", gap);
    if (start == std::string::npos) return false;
    sum = l.substr(0, gap);
    path = l.substr(start);
    return true;
}

struct Bag {
    std::vector<std::string> errors;  ///< empty: valid and complete as the RFC says
    std::map<std::string, std::string> info;
    std::map<std::string, std::map<std::string, std::string>> manifests;  ///< algorithm -> path -> checksum
};

/// Reads and checks the bag at dir by §3: bagit.txt, every payload manifest's lines and files, every file of
/// data/ in every payload manifest, Payload-Oxum.
inline Bag read(const std::string& dir) {
    namespace fs = std::filesystem;
    Bag b;
    auto bagit = lines(read_text(dir + "/bagit.txt"));
    if (bagit.size() != 2 || !version_line(bagit[0]) || bagit[1] != "Tag-File-Character-Encoding: UTF-8")
        b.errors.push_back("bagit.txt is not the two lines of §2.1.1");
    std::string last;
    for (const auto& l : lines(read_text(dir + "/bag-info.txt"))) {
        std::string label, value;
        if (!l.empty() && (l[0] == ' ' || l[0] == '\t') && !last.empty())
            b.info[last] += " " + l.substr(l.find_first_not_of(" \t"));
        else if (label_line(l, label, value))
            b.info[last = label] = value;
        else
            b.errors.push_back("bag-info.txt line '" + l + "'");
    }
    for (const auto& e : fs::directory_iterator(dir)) {
        std::string file = e.path().filename().string(), algorithm;
        if (!manifest_name(file, algorithm)) continue;
        for (const auto& l : lines(read_text(e.path().string()))) {
            std::string sum, written;
            if (!manifest_entry(l, sum, written)) {
                b.errors.push_back(file + " line '" + l + "'");
                continue;
            }
            std::string path = decode(written);
            b.manifests[algorithm][path] = sum;
            if (coreutils_sum(algorithm, dir + "/" + path) != sum)
                b.errors.push_back(file + ": " + path + " has another checksum, or is missing");
        }
    }
    if (b.manifests.empty()) b.errors.push_back("no payload manifest");
    std::uint64_t octets = 0, count = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir + "/data")) {
        if (!e.is_regular_file()) continue;
        std::string rel = e.path().lexically_relative(dir).generic_string();
        octets += e.file_size(), ++count;
        for (const auto& [algorithm, files] : b.manifests)
            if (!files.count(rel)) b.errors.push_back(rel + " not in manifest-" + algorithm + ".txt");
    }
    std::string oxum = std::to_string(octets) + "." + std::to_string(count);
    if (b.info.count("Payload-Oxum") && b.info["Payload-Oxum"] != oxum)
        b.errors.push_back("Payload-Oxum " + b.info["Payload-Oxum"] + ", the payload is " + oxum);
    return b;
}

}  // namespace bagit_reader
