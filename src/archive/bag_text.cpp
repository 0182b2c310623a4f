// The text of a bag's tag files (RFC 8493 §2.1.3, §2.2.2): lines ended by LF, CR or CR LF, file paths
// with '%', CR and LF percent-encoded, and bag-info.txt's "Label: value" lines with their continuations.
#include <cctype>

#include "tape/archive.hpp"

namespace tape {

std::string bag_encoded_path(std::string_view path) {
    std::string s;
    s.reserve(path.size());
    for (char c : path) {
        if (c == '%')
            s += "%25";
        else if (c == '\r')
            s += "%0D";
        else if (c == '\n')
            s += "%0A";
        else
            s += c;
    }
    return s;
}

namespace {

// The character a %XX the RFC names stands for, or 0 for any other.
char encoded_char(std::string_view xx) {
    auto up = [](char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); };
    std::string u{up(xx[0]), up(xx[1])};
    return u == "25" ? '%' : u == "0D" ? '\r' : u == "0A" ? '\n' : 0;
}

bool blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

bool same_label(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

}  // namespace

std::string bag_decoded_path(std::string_view encoded) {
    std::string s;
    for (std::size_t i = 0; i < encoded.size(); ++i) {
        char c = i + 2 < encoded.size() && encoded[i] == '%' ? encoded_char(encoded.substr(i + 1, 2)) : 0;
        if (c) {
            s += c;
            i += 2;
        } else {
            s += encoded[i];
        }
    }
    return s;
}

std::vector<std::string_view> tag_file_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n' && text[i] != '\r') continue;
        lines.push_back(text.substr(start, i - start));
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        start = i + 1;
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
}

std::vector<BagInfoEntry> parse_bag_info(std::string_view text, std::vector<std::uint64_t>* bad_lines) {
    std::vector<BagInfoEntry> out;
    std::uint64_t n = 0;
    for (std::string_view line : tag_file_lines(text)) {
        ++n;
        if (trimmed(line).empty()) continue;
        if (blank(line.front()) && !out.empty()) {  // a continuation of the value before
            out.back().value += " " + std::string(trimmed(line));
            continue;
        }
        std::size_t colon = line.find(':');
        if (colon == std::string_view::npos || colon == 0 || blank(line.front())) {
            if (bad_lines) bad_lines->push_back(n);
            continue;
        }
        out.push_back({std::string(trimmed(line.substr(0, colon))), std::string(trimmed(line.substr(colon + 1)))});
    }
    return out;
}

std::optional<std::string> bag_info_value(const std::vector<BagInfoEntry>& info, std::string_view label) {
    for (const auto& e : info)
        if (same_label(e.label, label)) return e.value;
    return std::nullopt;
}

std::string payload_oxum(std::uint64_t octets, std::uint64_t files) {
    return std::to_string(octets) + "." + std::to_string(files);
}

}  // namespace tape
