// Machine profiles: lookups in a profile, and finding one by name, alias or path (tape/machine.hpp).
#include "tape/machine.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "tape/error.hpp"
#include "tape/file_io.hpp"

namespace tape {
namespace {

namespace fs = std::filesystem;

std::string lower_ascii(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return s;
}

bool names(const MachineProfile& p, std::string_view wanted) {
    std::string w = lower_ascii(std::string(wanted));
    if (lower_ascii(p.name) == w) return true;
    return std::any_of(p.aliases.begin(), p.aliases.end(),
                       [&](const std::string& a) { return a == wanted || lower_ascii(a) == w; });
}

bool is_path(std::string_view s) {
    return s.find('/') != std::string_view::npos || (s.size() > 5 && s.substr(s.size() - 5) == ".toml");
}

std::vector<fs::path> user_files() {
    std::vector<fs::path> out;
    std::string folder = user_machine_folder();
    std::error_code ec;
    if (folder.empty() || !fs::is_directory(folder, ec)) return out;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.path().extension() == ".toml") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

MachineProfile read_profile_file(const std::string& path) {
    auto bytes = read_file(path, 1 << 20);  // a profile is a few kilobytes
    return parse_machine_profile(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
}

}  // namespace

std::string_view machine_kind_name(MachineKind k) { return k == MachineKind::lathe ? "lathe" : "mill"; }

const MachineCode* MachineProfile::find_code(char address, int code) const {
    for (const auto& c : codes)
        if (c.address == address && c.code == code) return &c;
    return nullptr;
}

const FormatMode* MachineProfile::find_mode(std::string_view mode) const {
    for (const auto& m : modes)
        if (m.name == mode) return &m;
    return nullptr;
}

const MachineAxis* MachineProfile::find_axis(char axis) const {
    for (const auto& a : axes)
        if (a.name == axis) return &a;
    return nullptr;
}

const FeedCode* MachineProfile::find_feed_code(int first_digit) const {
    for (const auto& f : feed_codes)
        if (f.first_digit == first_digit) return &f;
    return nullptr;
}

const SpeedCode* MachineProfile::find_speed_code(int code) const {
    for (const auto& s : speed_codes)
        if (s.code == code) return &s;
    return nullptr;
}

std::string user_machine_folder() {
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::string(x) + "/tape/machines";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.config/tape/machines";
    return "";
}

MachineProfile load_machine(std::string_view wanted) {
    if (wanted.empty()) throw Error(Errc::usage, "--machine: no name given");
    if (is_path(wanted)) return read_profile_file(std::string(wanted));
    for (const auto& f : user_files()) {
        if (f.stem().string() == wanted) return read_profile_file(f.string());
    }
    for (const auto& b : bundled_machines()) {
        MachineProfile p = parse_machine_profile(b.text, "built-in " + std::string(b.name) + ".toml");
        if (names(p, wanted)) {
            p.file = "built-in";
            return p;
        }
    }
    std::string known;
    for (const auto& m : list_machines()) known += (known.empty() ? "" : ", ") + m.name;
    throw Error(Errc::usage, "no machine profile '" + std::string(wanted) + "' (there are: " + known +
                                 "; or give a profile's path)");
}

std::vector<MachineListing> list_machines() {
    std::vector<MachineListing> out;
    for (const auto& f : user_files()) {
        MachineListing m{f.stem().string(), "", f.string(), false, false};
        try {
            m.title = read_profile_file(f.string()).title;
        } catch (const Error& e) {
            std::string why = e.what();  // "FILE: line N: ...": the file is said apart
            if (why.rfind(m.file + ": ", 0) == 0) why.erase(0, m.file.size() + 2);
            m.title = why;
            m.broken = true;
        }
        out.push_back(m);
    }
    for (const auto& b : bundled_machines()) {
        bool hidden = std::any_of(out.begin(), out.end(), [&](const MachineListing& m) { return m.name == b.name; });
        if (hidden) continue;
        MachineProfile p = parse_machine_profile(b.text, "built-in " + std::string(b.name) + ".toml");
        out.push_back(MachineListing{p.name, p.title, "built-in", true, false});
    }
    return out;
}

}  // namespace tape
