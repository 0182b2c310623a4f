// Reads a machine profile (data/machines/README.md) with toml++, strictly: every key known, every value
// checked, codes and table rows given once, and every mistake named with its file, line and key.
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <tuple>

#include "common/toml_guard.hpp"
#include "machine/toml_fields.hpp"
#include "tape/error.hpp"
#include "tape/machine.hpp"

namespace tape {
namespace {

using machine_detail::Fields;

struct Reader {
    std::string_view file;
    MachineProfile& p;

    Fields fields(const toml::table& t, std::string path, const std::string& inherited) {
        Fields f(t, path, file, inherited, &p.sources);
        p.sources[path] = f.source();
        return f;
    }

    void format(const Fields& top);
    void mode(const toml::table& t, std::size_t i, const Fields& parent);
    void codes(const Fields& top);
    void feed(const Fields& top);
    void speed(const Fields& top);
    void axes(const Fields& top);
    void arc(const Fields& top);
    void line(const Fields& top);
};

void Reader::format(const Fields& top) {
    const toml::table* t = top.table("format");
    if (!t) return;
    Fields f = fields(*t, "format", top.source());
    f.only({"spec", "initial_mode", "prefixed", "mode"});
    std::string spec = f.required_text("spec");
    try {
        p.format = parse_format_spec(spec);
    } catch (const Error& e) {
        f.fail("spec", e.what());
    }
    p.prefixed = f.text("prefixed").value_or("");
    for (char c : p.prefixed)
        if (!p.format.find(c)) f.fail("prefixed", std::string("the format has no address ") + c);
    auto modes = f.tables("mode");
    for (std::size_t i = 0; i < modes.size(); ++i) mode(*modes[i], i, f);
    p.initial_mode = f.text("initial_mode").value_or("");
    if (!p.initial_mode.empty() && !p.find_mode(p.initial_mode))
        f.fail("initial_mode", "no [[format.mode]] is named \"" + p.initial_mode + "\"");
}

void Reader::mode(const toml::table& t, std::size_t i, const Fields& parent) {
    Fields f = fields(t, "format.mode[" + std::to_string(i + 1) + "]", parent.source());
    f.only({"name", "addresses", "digits"});
    FormatMode m;
    m.name = f.required_text("name");
    if (p.find_mode(m.name)) f.fail("name", "mode \"" + m.name + "\" is given twice");
    m.addresses = f.required_text("addresses");
    m.digits = static_cast<int>(f.whole("digits", 1, 9).value_or(0));
    if (!m.digits) f.fail("digits", "is required (1 to 9)");
    m.source = f.source();
    m.spec = p.format;
    for (char c : m.addresses) {
        auto w =
            std::find_if(m.spec.words.begin(), m.spec.words.end(), [&](const WordFormat& x) { return x.address == c; });
        if (w == m.spec.words.end() || !w->dimension)
            f.fail("addresses", std::string("the format has no dimension word ") + c);
        w->before = m.digits;
        w->after = 0;
        w->text = std::string(1, c) + (w->sign ? "+" : "") + std::to_string(m.digits) + "0";
    }
    p.modes.push_back(std::move(m));
}

// "G10" -> ('G', 10).
std::pair<char, int> code_of(const Fields& f) {
    std::string c = f.required_text("code");
    bool ok = c.size() >= 2 && c.size() <= 4 && (c[0] == 'G' || c[0] == 'M') &&
              std::all_of(c.begin() + 1, c.end(), [](char d) { return std::isdigit(static_cast<unsigned char>(d)); });
    if (!ok) f.fail("code", "must be G or M and one to three digits (\"G10\", \"M104\"), not \"" + c + "\"");
    return {c[0], std::stoi(c.substr(1))};
}

void Reader::codes(const Fields& top) {
    auto list = top.tables("code");
    for (std::size_t i = 0; i < list.size(); ++i) {
        Fields f(*list[i], "code[" + std::to_string(i + 1) + "]", file, top.source());
        f.only({"code", "meaning", "meaning_ru", "group", "mode"});
        MachineCode c;
        std::tie(c.address, c.code) = code_of(f);
        if (const MachineCode* other = p.find_code(c.address, c.code))
            f.fail("code", std::string(1, c.address) + std::to_string(c.code) + " is given twice (first on line " +
                               std::to_string(other->line) + ")");
        c.meaning = f.required_text("meaning");
        c.meaning_ru = f.text("meaning_ru").value_or("");
        c.group = f.text("group").value_or("");
        c.mode = f.text("mode").value_or("");
        if (!c.mode.empty() && !p.find_mode(c.mode)) f.fail("mode", "no [[format.mode]] is named \"" + c.mode + "\"");
        c.source = f.source();
        c.line = f.line();
        p.codes.push_back(std::move(c));
    }
}

void Reader::feed(const Fields& top) {
    const toml::table* t = top.table("feed");
    if (!t) return;
    Fields f = fields(*t, "feed", top.source());
    f.only({"address", "code"});
    std::string a = f.choice("address", {"F", "E"}).value_or("F");
    p.feed_table_address = a[0];
    auto rows = f.tables("code");
    if (rows.empty()) f.fail("code", "a feed code table needs its rows ([[feed.code]])");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        Fields r(*rows[i], "feed.code[" + std::to_string(i + 1) + "]", file, f.source());
        r.only({"first_digit", "meaning", "meaning_ru", "factor"});
        FeedCode c;
        c.first_digit = static_cast<int>(r.whole("first_digit", 0, 9).value_or(-1));
        if (c.first_digit < 0) r.fail("first_digit", "is required (0 to 9)");
        if (p.find_feed_code(c.first_digit)) r.fail("first_digit", std::to_string(c.first_digit) + " is given twice");
        c.meaning = r.required_text("meaning");
        c.meaning_ru = r.text("meaning_ru").value_or("");
        c.factor = r.number("factor", 0, 1000).value_or(1);
        c.source = r.source();
        p.feed_codes.push_back(std::move(c));
    }
}

void Reader::speed(const Fields& top) {
    const toml::table* t = top.table("speed");
    if (!t) return;
    Fields f = fields(*t, "speed", top.source());
    f.only({"complete", "code"});
    p.speed_table_complete = f.flag("complete").value_or(false);
    auto rows = f.tables("code");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        Fields r(*rows[i], "speed.code[" + std::to_string(i + 1) + "]", file, f.source());
        r.only({"code", "rpm"});
        SpeedCode c;
        c.code = static_cast<int>(r.whole("code", 0, 999).value_or(-1));
        if (c.code < 0) r.fail("code", "is required (0 to 999)");
        if (p.find_speed_code(c.code)) r.fail("code", std::to_string(c.code) + " is given twice");
        c.rpm = r.number("rpm", 0, 100000).value_or(-1);
        if (c.rpm < 0) r.fail("rpm", "is required (revolutions a minute)");
        c.source = r.source();
        p.speed_codes.push_back(c);
    }
}

void Reader::axes(const Fields& top) {
    auto list = top.tables("axis");
    for (std::size_t i = 0; i < list.size(); ++i) {
        Fields f(*list[i], "axis[" + std::to_string(i + 1) + "]", file, top.source());
        f.only({"name", "mm_per_pulse", "min_mm", "max_mm", "rapid_mm_per_min"});
        MachineAxis a;
        std::string name = f.required_text("name");
        if (name.size() != 1 || std::string_view("XYZUVWABC").find(name[0]) == std::string_view::npos)
            f.fail("name", "must be one of X Y Z U V W A B C, not \"" + name + "\"");
        a.name = name[0];
        if (p.find_axis(a.name)) f.fail("name", "axis " + name + " is given twice");
        Fields named(*list[i], "axis." + name, file, f.source(), &p.sources);
        p.sources["axis." + name] = f.source();
        a.mm_per_pulse = named.number("mm_per_pulse", 0, 10).value_or(0);
        a.min_mm = named.number("min_mm", -1e6, 1e6);
        a.max_mm = named.number("max_mm", -1e6, 1e6);
        if (a.min_mm && a.max_mm && *a.min_mm >= *a.max_mm) f.fail("max_mm", "must be above min_mm");
        if (auto r = named.number("rapid_mm_per_min", 1, 1e6)) p.rapid_mm_per_min[a.name] = *r;
        a.source = f.source();
        p.axes.push_back(a);
    }
}

void Reader::arc(const Fields& top) {
    const toml::table* t = top.table("arc");
    if (!t) return;
    Fields f = fields(*t, "arc", top.source());
    f.only({"tolerance_mm", "tolerance_relative"});
    p.arc_tolerance_mm = f.number("tolerance_mm", 0, 10).value_or(0);
    p.arc_tolerance_relative = f.number("tolerance_relative", 0, 0.5).value_or(0);
}

void Reader::line(const Fields& top) {
    const toml::table* t = top.table("line");
    if (!t) return;
    Fields f = fields(*t, "line", top.source());
    f.only({"code", "parity", "baud", "data_bits", "stop_bits", "flow", "dc_codes", "reader_frames_per_second"});
    MachineLine& l = p.line;
    if (auto c = f.choice("code", {"iso", "eia"})) l.code = parse_code(*c);
    if (auto c = f.choice("parity", {"even", "odd", "mark", "space", "none"})) l.parity = parse_parity(*c);
    l.baud = static_cast<unsigned>(f.whole("baud", 50, 115200).value_or(0));
    l.data_bits = static_cast<int>(f.whole("data_bits", 7, 8).value_or(0));
    l.stop_bits = static_cast<int>(f.whole("stop_bits", 1, 2).value_or(0));
    if (auto c = f.choice("flow", {"xonxoff", "rtscts", "none"}))
        l.flow = *c == "xonxoff" ? Flow::xonxoff : *c == "rtscts" ? Flow::rtscts : Flow::none;
    l.dc_codes = f.flag("dc_codes").value_or(false);
    l.reader_frames_per_second = f.number("reader_frames_per_second", 1, 10000).value_or(0);
    l.source = f.source();
}

void read_top(Reader& r, const toml::table& root) {
    MachineProfile& p = r.p;
    Fields top(root, "", r.file, "", &p.sources);
    top.only({"name", "title", "aliases", "kind", "diameter_programming", "dialect", "format", "code", "feed", "speed",
              "axis", "arc", "line"});
    if (top.source().empty()) top.fail("source", "is required: where the profile's values come from");
    p.sources["machine"] = top.source();
    p.name = top.required_text("name");
    bool ok = p.name.size() <= 32 && std::all_of(p.name.begin(), p.name.end(), [](char c) {
                  return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
                         c == '-' || c == '_';
              });
    if (!ok) top.fail("name", "must be 1 to 32 lowercase letters, digits, '-' or '_'");
    p.title = top.text("title").value_or(p.name);
    p.aliases = top.texts("aliases");
    p.kind = top.choice("kind", {"lathe", "mill"}).value_or("mill") == "lathe" ? MachineKind::lathe : MachineKind::mill;
    if (!top.has("kind")) top.fail("kind", "is required (\"lathe\" or \"mill\")");
    p.diameter_programming = top.flag("diameter_programming").value_or(false);
    if (p.diameter_programming && p.kind != MachineKind::lathe)
        top.fail("diameter_programming", "only a lathe programs diameters");
    p.dialect = *parse_dialect(top.choice("dialect", {"gost", "fanuc", "linuxcnc", "none"}).value_or("gost"));
    r.format(top);
    r.codes(top);
    r.feed(top);
    r.speed(top);
    r.axes(top);
    r.arc(top);
    r.line(top);
}

}  // namespace

MachineProfile parse_machine_profile(std::string_view text, std::string_view file) {
    try {
        reject_bare_non_ascii(text, file);
    } catch (const Error& e) {
        auto line = e.where().line.value_or(0);
        throw Error(Errc::usage, e.where(), std::string(file) + ": line " + std::to_string(line) + ": " + e.what());
    }
    toml::table root;
    try {
        root = toml::parse(text, std::string(file));
    } catch (const toml::parse_error& e) {
        auto line = e.source().begin.line;
        throw Error(Errc::usage, Position{.line = line},
                    std::string(file) + ": line " + std::to_string(line) + ": " + std::string(e.description()));
    }
    MachineProfile p;
    p.file = std::string(file);
    Reader r{file, p};
    read_top(r, root);
    return p;
}

}  // namespace tape
