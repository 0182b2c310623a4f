// tape dnc's configuration read with toml++: every key checked, every mistake named with its line.
#include <sys/stat.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "../device_options.hpp"
#include "../dnc_config.hpp"
#include "common/toml_guard.hpp"
#include "tape/error.hpp"
#include "tape/file_io.hpp"
#include "tape/machine.hpp"
#include "tape/serial_settings.hpp"

namespace cli {
namespace {

using tape::dnc::MachineSettings;
using tape::dnc::ServiceConfig;

// A configuration is a page or two; a bigger file is no configuration (a device, a log named by mistake).
constexpr std::uint64_t max_config_bytes = 1 << 20;

std::uint64_t line_of(const toml::node& n) { return n.source().begin.line; }

[[noreturn]] void bad(std::uint64_t line, const std::string& message) {
    throw tape::Error(tape::Errc::usage, tape::Position{.line = line}, message);
}

// How a value reads in a message.
std::string shown(const toml::node& n) {
    std::ostringstream out;
    if (n.is_string())
        out << '"' << n.value_or(std::string()) << '"';
    else
        n.visit([&out](auto&& v) { out << v; });
    return out.str().substr(0, 60);
}

// One key's value, checked; `what` is "machine 'mill-1': rate" for messages.
struct Value {
    const toml::node& node;
    std::string what;

    [[noreturn]] void wrong(const std::string& must) const {
        bad(line_of(node), what + ": " + must + ", not " + shown(node));
    }
    std::string text() const {
        if (!node.is_string()) wrong("must be a string in quotes");
        return *node.value<std::string>();
    }
    bool flag() const {
        if (!node.is_boolean()) wrong("must be true or false");
        return *node.value<bool>();
    }
    double number(double min, double max, const std::string& unit) const {
        auto v = node.is_number() ? node.value<double>() : std::nullopt;
        if (!v || !std::isfinite(*v) || *v < min || *v > max)
            wrong("must be a number from " + number_text(min) + " to " + number_text(max) + unit);
        return *v;
    }
    std::int64_t whole(std::int64_t min, std::int64_t max) const {
        auto v = node.is_integer() ? node.value<std::int64_t>() : std::nullopt;
        if (!v || *v < min || *v > max)
            wrong("must be a whole number from " + std::to_string(min) + " to " + std::to_string(max));
        return *v;
    }
    std::string choice(std::initializer_list<std::string_view> allowed) const {
        std::string v = node.is_string() ? *node.value<std::string>() : std::string();
        if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return v;
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        wrong("must be one of " + list);
    }
    std::uint8_t byte() const {  // 0x11, or a one-character string
        if (node.is_string() && node.value<std::string>()->size() == 1)
            return static_cast<std::uint8_t>((*node.value<std::string>())[0]);
        return static_cast<std::uint8_t>(whole(0, 255));
    }
    static std::string number_text(double v) {
        std::ostringstream out;
        out << v;
        return out.str();
    }
};

std::chrono::milliseconds seconds(const Value& v, double max) {
    return std::chrono::milliseconds(std::llround(v.number(0, max, " seconds") * 1000));
}

// Checks a device string as opening would, without opening it: a known prefix, serial settings.
void check_device(const Value& v, const std::string& device) {
    auto colon = device.find(':');
    std::string prefix = device.substr(0, colon);
    auto backends = tape::device_backends();
    if (colon == std::string::npos ||
        std::none_of(backends.begin(), backends.end(), [&](const auto& b) { return b.prefix == prefix; }))
        v.wrong("must be a device string such as \"serial:/dev/ttyS0?baud=9600\"");
    if (prefix == "serial") {
        try {
            tape::parse_serial_settings(std::string_view(device).substr(colon + 1));
        } catch (const tape::Error& e) {
            bad(line_of(v.node), v.what + ": " + e.what());
        }
    }
}

// The keys of receiving, flow and answering.
void more_machine_key(const std::string& key, const Value& v, MachineSettings& m) {
    if (key == "block_delay") {
        m.block_delay = std::chrono::milliseconds(v.whole(0, static_cast<std::int64_t>(max_delay_ms)));
    } else if (key == "flow") {
        std::string f = v.choice({"xonxoff", "rtscts", "none"});
        m.flow = f == "xonxoff" ? tape::Flow::xonxoff : f == "rtscts" ? tape::Flow::rtscts : tape::Flow::none;
    } else if (key == "wait_xon") {
        m.wait_xon = v.flag();
    } else if (key == "xon_timeout") {
        m.xon_timeout = seconds(v, max_timeout_s);
    } else if (key == "xon" || key == "xoff") {
        (key == "xon" ? m.xon : m.xoff) = v.byte();
    } else if (key == "burst") {
        m.burst = static_cast<std::size_t>(v.whole(1, 256));
    } else if (key == "receive_timeout") {
        m.receive_timeout = seconds(v, max_timeout_s);
        if (m.receive_timeout.count() < 100) v.wrong("must be from 0.1 seconds up");
    } else if (key == "max_punch_out") {
        m.max_punch_out = static_cast<std::uint64_t>(v.whole(1024, std::int64_t{1} << 32));
    } else if (key == "answer_unknown") {
        m.answer_unknown = v.flag();
    } else if (key == "lathe") {
        m.lathe = v.flag();
    } else {
        bad(line_of(v.node),
            v.what.substr(0, v.what.rfind(':')) + ": unknown key '" + key +
                "' (known: name, machine, device, code, parity, leader, trailer, crlf, percent, dialect, "
                "rate, delay, block_delay, flow, wait_xon, xon_timeout, xon, xoff, burst, "
                "receive_timeout, max_punch_out, answer_unknown, lathe)");
    }
}

void machine_key(const std::string& key, const Value& v, MachineSettings& m) {
    if (key == "name") {
        m.name = v.text();
        bool ok = !m.name.empty() && m.name.size() <= 32 && std::all_of(m.name.begin(), m.name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
        });
        if (!ok) v.wrong("must be 1 to 32 letters, digits, '-' or '_' (it names files)");
    } else if (key == "device") {
        m.device = v.text();
        check_device(v, m.device);
    } else if (key == "code") {
        m.code = v.choice({"iso", "eia"}) == "eia" ? tape::Code::eia : tape::Code::iso;
    } else if (key == "parity") {
        m.parity = *tape::parse_parity(v.choice({"even", "odd", "mark", "space", "none"}));
    } else if (key == "leader" || key == "trailer") {
        (key == "leader" ? m.leader : m.trailer) = static_cast<std::size_t>(v.whole(0, tape::max_blank_frames));
    } else if (key == "crlf") {
        m.crlf = v.flag();
    } else if (key == "percent") {
        m.percent = v.flag();
    } else if (key == "dialect") {
        m.dialect = *tape::parse_dialect(v.choice({"auto", "gost", "fanuc", "linuxcnc"}));
    } else if (key == "rate") {
        m.rate = v.number(0, max_rate, " frames per second (0: the line's speed)");
        if (m.rate > 0 && m.rate < min_rate) v.wrong("must be 0 or from 0.1 frames per second up");
    } else if (key == "delay") {
        double ms = v.number(1, max_delay_ms, " milliseconds between characters");
        m.rate = 1000.0 / ms;
    } else {
        more_machine_key(key, v, m);
    }
}

// machine = "NAME": the profile's line settings (code, parity, dialect, flow, DC1 wait, reader speed) and
// whether it is a lathe (a restart's approach), which the [[machine]]'s own keys then override. Its
// serial settings (baud, bits, stop) go into the device string once the device key is read.
tape::MachineLine profile_settings(const Value& v, MachineSettings& m) {
    tape::MachineProfile p;
    std::string name = v.text();
    try {
        p = tape::load_machine(name);
    } catch (const tape::Error& e) {
        bad(line_of(v.node), v.what + ": " + e.what());
    }
    const tape::MachineLine& l = p.line;
    if (l.code) m.code = *l.code;
    if (l.parity) m.parity = *l.parity;
    m.dialect = p.dialect;
    if (l.flow) m.flow = *l.flow;
    m.wait_xon = l.dc_codes;
    if (l.reader_frames_per_second > 0) m.rate = l.reader_frames_per_second;
    m.lathe = p.kind == tape::MachineKind::lathe;
    return l;
}

MachineSettings read_machine(const toml::table& t, std::size_t index) {
    MachineSettings m;
    m.line = line_of(t);
    if (auto name = t["name"].value<std::string>()) m.name = *name;
    std::string who = "machine " + (m.name.empty() ? "#" + std::to_string(index + 1) : "'" + m.name + "'");
    std::optional<tape::MachineLine> profile_line;
    if (const toml::node* profile = t.get("machine"))
        profile_line = profile_settings(Value{*profile, who + ": machine"}, m);
    for (auto&& [key, node] : t)
        if (key.str() != "machine")
            machine_key(std::string(key.str()), Value{node, who + ": " + std::string(key.str())}, m);
    if (m.name.empty()) bad(m.line, who + ": no name (name = \"mill-1\")");
    if (m.device.empty()) bad(m.line, who + ": no device (device = \"serial:/dev/ttyS0?baud=9600\")");
    if (profile_line) m.device = tape::device_with_machine_line(m.device, *profile_line);
    if ((m.xon & 0x7F) == (m.xoff & 0x7F)) bad(m.line, who + ": xon and xoff are the same character");
    return m;
}

std::string folder(const toml::table& t, const std::string& key, bool writable) {
    const toml::node* n = t.get(key);
    if (!n) bad(line_of(t), "library: no " + key + " folder (" + key + " = \"/srv/tape/" + key + "\")");
    Value v{*n, "library: " + key};
    std::string path = v.text();
    if (path.empty() || ::access(path.c_str(), writable ? (W_OK | X_OK) : (R_OK | X_OK)) != 0)
        v.wrong(std::string("must be a folder that is there and ") + (writable ? "writable" : "readable"));
    return path;
}

void read_library(const toml::table& t, ServiceConfig& c) {
    for (auto&& [key, node] : t)
        if (key.str() != "programs" && key.str() != "received")
            bad(line_of(node), "library: unknown key '" + std::string(key.str()) + "' (known: programs, received)");
    c.library.programs = folder(t, "programs", false);
    c.library.received = folder(t, "received", true);
}

void read_service(const toml::table& t, ServiceConfig& c) {
    for (auto&& [key, node] : t) {
        if (key.str() != "runtime_directory")
            bad(line_of(node), "service: unknown key '" + std::string(key.str()) + "' (known: runtime_directory)");
        c.runtime_directory = Value{node, "service: runtime_directory"}.text();
    }
}

const toml::table& table_of(const toml::node& n, const std::string& what) {
    if (!n.is_table()) bad(line_of(n), what + " must be a table ([" + what + "])");
    return *n.as_table();
}

void read_machines(const toml::node& n, ServiceConfig& c) {
    if (!n.is_array_of_tables()) bad(line_of(n), "machine must be tables, one [[machine]] per line");
    const auto& machines = *n.as_array();
    for (std::size_t i = 0; i < machines.size(); ++i) {
        MachineSettings m = read_machine(*machines[i].as_table(), i);
        for (const auto& other : c.machines) {
            if (other.name == m.name) bad(m.line, "machine '" + m.name + "' is named twice");
            if (other.device == m.device)
                bad(m.line, "machine '" + m.name + "': device " + m.device + " is machine '" + other.name + "''s too");
        }
        c.machines.push_back(std::move(m));
    }
}

// The file's text: a regular file (SIGHUP reads it again) of a size a configuration has.
std::string config_text(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw tape::Error(tape::Errc::usage,
                          "a folder: --config names the configuration file (/etc/tape/dnc.toml; "
                          "packaging/dnc.toml is a sample)");
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw tape::Error(tape::Errc::usage, std::string(S_ISFIFO(st.st_mode) ? "a FIFO" : "no regular file") +
                                                 ": tape dnc reads its configuration again on SIGHUP, so it must be "
                                                 "a file");
    std::vector<std::uint8_t> bytes = tape::read_file(path, max_config_bytes);
    return std::string(bytes.begin(), bytes.end());
}

toml::table parsed(std::string_view text, const std::string& path) {
    tape::reject_bare_non_ascii(text, path);  // before toml++, which 3.3.0 cannot be trusted with it
    try {
        return toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        bad(e.source().begin.line, std::string(e.description()));
    }
}

}  // namespace

ServiceConfig parse_dnc_config(std::string_view text, const std::string& path) {
    toml::table root = parsed(text, path);
    ServiceConfig c;
    c.path = path;
    for (auto&& [key, node] : root) {
        if (key.str() == "library")
            read_library(table_of(node, "library"), c);
        else if (key.str() == "service")
            read_service(table_of(node, "service"), c);
        else if (key.str() == "machine")
            read_machines(node, c);
        else
            bad(line_of(node),
                "unknown table or key '" + std::string(key.str()) + "' (known: library, service, machine)");
    }
    if (c.library.programs.empty()) bad(1, "no [library] table with programs and received folders");
    if (c.machines.empty()) bad(1, "no [[machine]]: nothing to serve");
    return c;
}

ServiceConfig load_dnc_config(const std::string& path) { return parse_dnc_config(config_text(path), path); }

std::string dnc_control_socket(const std::string& path) {
    toml::table root = parsed(config_text(path), path);
    ServiceConfig c;
    if (const toml::node* service = root.get("service"); service && service->is_table())
        if (const toml::node* dir = service->as_table()->get("runtime_directory"))
            c.runtime_directory = Value{*dir, "service: runtime_directory"}.text();
    return tape::dnc::control_socket_path(c);
}

}  // namespace cli
