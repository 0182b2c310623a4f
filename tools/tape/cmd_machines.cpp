// tape machines: the machine profiles there are, and one of them with where each value comes from.
#include <sstream>

#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "tape/machine.hpp"

namespace cli {
namespace {

struct MachinesArgs {
    std::string name;
};

std::string padded(const std::string& s, std::size_t width) {
    return s + std::string(s.size() < width ? width - s.size() : 1, ' ');
}

std::string num(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

void list() {
    std::string out;
    for (const auto& m : tape::list_machines())
        out += padded(m.name, 14) + (m.broken ? m.file + " does not read: " + m.title : m.title) +
               (m.bundled || m.broken ? "" : "  (" + m.file + ")") + "\n";
    write_output("-", out, false, false);
}

// "  key: value  [source]": every value with where it comes from, and the Russian documentation's name
// for it under it where the profile has one.
std::string row(const std::string& key, const std::string& value, const std::string& source,
                const std::string& russian = "") {
    std::string under = "\n  " + std::string(22, ' ');
    return "  " + padded(key + ":", 22) + value + (russian.empty() ? "" : under + "ru: " + russian) +
           (source.empty() ? "" : under + "source: " + source) + "\n";
}

std::string source_of(const tape::MachineProfile& p, const std::string& key) {
    auto at = p.sources.find(key);
    return at == p.sources.end() ? "" : at->second;
}

std::string format_part(const tape::MachineProfile& p) {
    if (p.format.words.empty()) return row("format", "not known", "");
    std::string out = row("format", p.format.text, source_of(p, "format"));
    for (const auto& m : p.modes)
        out += row("  mode " + m.name,
                   m.addresses + ": " + std::to_string(m.digits) + " digits" +
                       (m.name == p.initial_mode ? " (at the program's start)" : ""),
                   m.source);
    if (!p.prefixed.empty())
        out += row("  first digit 0 or 1", p.prefixed + " (1: after the machine's acknowledgement)", "");
    return out;
}

std::string codes_part(const tape::MachineProfile& p) {
    std::string out;
    for (const auto& c : p.codes) {
        std::string code = std::string(1, c.address) + (c.code < 10 ? "0" : "") + std::to_string(c.code);
        std::string more = c.group.empty() ? "" : " [" + c.group + (c.mode.empty() ? "" : ", " + c.mode) + "]";
        out += row(code, c.meaning + more, c.source, c.meaning_ru);
    }
    for (const auto& f : p.feed_codes)
        out += row(std::string(1, p.feed_table_address) + " first digit " + std::to_string(f.first_digit),
                   f.meaning + (f.factor > 0 ? ", x" + num(f.factor) : ""), f.source, f.meaning_ru);
    for (const auto& s : p.speed_codes)
        out += row("S code " + std::to_string(s.code), num(s.rpm) + " rev/min", s.source);
    if (!p.speed_codes.empty() && !p.speed_table_complete)
        out += row("speed table", "incomplete: other codes may be the machine's", source_of(p, "speed"));
    return out;
}

std::string axes_part(const tape::MachineProfile& p) {
    std::string out;
    for (const auto& a : p.axes) {
        std::string v = a.mm_per_pulse > 0 ? num(a.mm_per_pulse) + " mm a unit" : "words in mm";
        if (a.min_mm && a.max_mm) v += ", travel " + num(*a.min_mm) + " to " + num(*a.max_mm) + " mm";
        if (auto r = p.rapid_mm_per_min.find(a.name); r != p.rapid_mm_per_min.end())
            v += ", rapid " + num(r->second) + " mm/min";
        out += row("axis " + std::string(1, a.name), v, a.source);
    }
    if (p.arc_tolerance_mm > 0 || p.arc_tolerance_relative > 0)
        out += row("arc tolerance",
                   num(p.arc_tolerance_mm) + " mm or " + num(p.arc_tolerance_relative * 100) + " % of the radius",
                   source_of(p, "arc"));
    return out;
}

std::string line_part(const tape::MachineProfile& p) {
    const tape::MachineLine& l = p.line;
    std::string v;
    auto add = [&](const std::string& s) { v += (v.empty() ? "" : ", ") + s; };
    if (l.code) add(std::string(tape::code_name(*l.code)));
    if (l.parity) add(std::string(tape::parity_name(*l.parity)) + " parity");
    if (l.baud) add(std::to_string(l.baud) + " baud");
    if (l.data_bits) add(std::to_string(l.data_bits) + " data bits");
    if (l.stop_bits) add(std::to_string(l.stop_bits) + " stop bits");
    if (l.flow)
        add(*l.flow == tape::Flow::xonxoff  ? "XON/XOFF"
            : *l.flow == tape::Flow::rtscts ? "RTS/CTS"
                                            : "no flow control");
    if (l.dc_codes) add("DC codes (waits for DC1)");
    if (l.reader_frames_per_second > 0) add("reader " + num(l.reader_frames_per_second) + " frames/s");
    return v.empty() ? "" : row("line", v, l.source);
}

void show(const std::string& name) {
    tape::MachineProfile p = *machine_or_fail(name, "machines show");
    std::string aliases;
    for (const auto& a : p.aliases) aliases += (aliases.empty() ? "" : ", ") + a;
    std::string out = p.name + ": " + p.title + " (" + p.file + ")\n";
    if (!aliases.empty()) out += row("aliases", aliases, "");
    out += row("kind", std::string(tape::machine_kind_name(p.kind)), source_of(p, "kind"));
    if (p.kind == tape::MachineKind::lathe)
        out += row("X words", p.diameter_programming ? "diameters" : "radii", source_of(p, "diameter_programming"));
    out += row("dialect", std::string(tape::dialect_name(p.dialect)), source_of(p, "dialect"));
    out += format_part(p) + codes_part(p) + axes_part(p) + line_part(p);
    write_output("-", out, false, false);
}

}  // namespace

void add_machines(CLI::App& app) {
    auto a = std::make_shared<MachinesArgs>();
    auto* sub = app.add_subcommand("machines", "List the machine profiles (built-in and ~/.config/tape/machines/)");
    auto* show_sub = sub->add_subcommand("show", "Print one machine profile with where each value comes from");
    show_sub->add_option("name", a->name, "Profile name, alias or path")->required();
    show_sub->callback([a] { show(a->name); });
    sub->callback([sub] {
        if (sub->get_subcommands().empty()) list();
    });
}

}  // namespace cli
