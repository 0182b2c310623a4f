// An RFC 8493 reader written for the tests alone, from the RFC's text and not from the library: what a
// bag tape archive writes must read so to another tool. Checksums come from coreutils' sha256sum and
// sha512sum, run on each file, so that neither the parser nor the digests are the library's own.
#pragma once

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
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
    std::regex version(R"(^BagIt-Version: [0-9]+\.[0-9]+$)"), encoding(R"(^Tag-File-Character-Encoding: UTF-8$)");
    if (bagit.size() != 2 || !std::regex_match(bagit[0], version) || !std::regex_match(bagit[1], encoding))
        b.errors.push_back("bagit.txt is not the two lines of §2.1.1");
    std::regex label(R"(^([^:\s][^:]*):\s*(.*)$)");
    std::string last;
    for (const auto& l : lines(read_text(dir + "/bag-info.txt"))) {
        std::smatch m;
        if (!l.empty() && (l[0] == ' ' || l[0] == '\t') && !last.empty())
            b.info[last] += " " + l.substr(l.find_first_not_of(" \t"));
        else if (std::regex_match(l, m, label))
            b.info[last = m[1]] = m[2];
        else
            b.errors.push_back("bag-info.txt line '" + l + "'");
    }
    std::regex entry(R"(^([0-9a-fA-F]+)[ \t]+(\S.*)$)"), name(R"(^manifest-([a-z0-9]+)\.txt$)");
    for (const auto& e : fs::directory_iterator(dir)) {
        std::smatch m;
        std::string file = e.path().filename().string();
        if (!std::regex_match(file, m, name)) continue;
        std::string algorithm = m[1];
        for (const auto& l : lines(read_text(e.path().string()))) {
            std::smatch x;
            if (!std::regex_match(l, x, entry)) {
                b.errors.push_back(file + " line '" + l + "'");
                continue;
            }
            std::string path = decode(x[2]);
            b.manifests[algorithm][path] = x[1];
            if (coreutils_sum(algorithm, dir + "/" + path) != std::string(x[1]))
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
