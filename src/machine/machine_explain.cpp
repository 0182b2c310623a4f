// What the G, M, F, S and T words of a block mean on a machine (tape/machine_checks.hpp).
#include <cmath>
#include <sstream>

#include "tape/code_tables.hpp"
#include "tape/machine_checks.hpp"

namespace tape {
namespace {

struct Say {
    bool russian;
    std::string operator()(std::string_view en, std::string_view ru) const { return std::string(russian ? ru : en); }
};

std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

std::string mm_per_min(Say say) { return say(" mm/min", " мм/мин"); }

// "F2000: 4 digits where F5 takes 5, not read", or "" when the word has the format's digits.
std::string digits_off(const MachineProfile& p, const Word& w, Say say) {
    const WordFormat* f = p.format.find(w.address);
    if (!f || f->dimension || w.has_point() || static_cast<int>(w.digits().size()) == f->before) return "";
    return w.text + say(": ", ": ") + std::to_string(w.digits().size()) + say(" digit(s) where ", " цифр(ы), а ") +
           f->text + say(" takes ", " требует ") + std::to_string(f->before) + say(": not read", ": не прочитано");
}

std::string feed(const MachineProfile& p, const Word& w, Say say) {
    if (std::string off = digits_off(p, w, say); !off.empty()) return off;
    std::string d = w.digits();
    if (d.size() < 2) return "";
    const FeedCode* c = p.find_feed_code(d[0] - '0');
    if (!c) return w.text + say(": mode ", ": режим ") + d.substr(0, 1) + say(" is not in the table", " не из таблицы");
    std::string out = w.text + " " + (say.russian && !c->meaning_ru.empty() ? c->meaning_ru : c->meaning);
    if (c->factor > 0) return out + ": " + number(std::stod(d.substr(1)) * c->factor) + mm_per_min(say);
    std::string rates;
    for (const auto& [axis, rate] : p.rapid_mm_per_min)
        rates += (rates.empty() ? ": " : ", ") + std::string(1, axis) + " " + number(rate) + mm_per_min(say);
    return out + rates;
}

std::string acknowledged(int first, Say say) {
    return first ? say(", after the machine's acknowledgement", ", после сигнала станка о выполнении") : "";
}

std::string speed(const MachineProfile& p, const Word& w, int first, int code, Say say) {
    const SpeedCode* s = p.find_speed_code(code);
    std::string out = w.text + say(" speed code ", " код скорости ") + std::to_string(code);
    if (s) return out + ": " + number(s->rpm) + say(" rev/min", " об/мин") + acknowledged(first, say);
    return out +
           (p.speed_table_complete
                ? say(", not in the speed table", ", нет в таблице скоростей")
                : say(", not in the profile's part of the speed table", ", нет в известной части таблицы скоростей")) +
           acknowledged(first, say);
}

std::string code_meaning(const MachineProfile& p, const Word& w, Say say) {
    if (w.has_point() || w.sign || w.macro || w.digits().empty() || w.digits().size() > 4) return "";
    std::string d = w.digits();
    int first = 0, code = std::stoi(d);
    const WordFormat* f = p.format.find(w.address);
    bool pre = p.prefixed.find(w.address) != std::string::npos && f && static_cast<int>(d.size()) == f->before;
    if (pre && d.size() >= 2 && d[0] <= '1') first = d[0] - '0', code = std::stoi(d.substr(1));
    if (w.address == 'T' && pre)
        return w.text + say(" tool ", " инструмент ") + std::to_string(code) + acknowledged(first, say);
    if (w.address == 'T') return "";
    if (w.address == 'S') return pre ? speed(p, w, first, code, say) : digits_off(p, w, say);
    if (const MachineCode* c = p.find_code(w.address, code))
        return w.text + " " + (say.russian && !c->meaning_ru.empty() ? c->meaning_ru : c->meaning) +
               acknowledged(first, say);
    Block one;  // a code the profile has not: its dialect's table may name it
    one.words.push_back(w);
    return explain_codes(one, p.dialect, p.kind == MachineKind::lathe ? Machine::lathe : Machine::mill, say.russian);
}

}  // namespace

std::string explain_machine_codes(const Block& b, const MachineProfile& p, bool russian) {
    Say say{russian};
    std::string out;
    for (const auto& w : b.words) {
        if (!w.known || w.macro) continue;
        std::string e;
        if (p.feed_table_address && w.address == p.feed_table_address)
            e = feed(p, w, say);
        else if (w.address == 'G' || w.address == 'M' || w.address == 'S' || w.address == 'T')
            e = code_meaning(p, w, say);
        if (!e.empty()) out += (out.empty() ? "" : ", ") + e;
    }
    return out;
}

}  // namespace tape
