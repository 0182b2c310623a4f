// A program's blocks against a machine profile (tape/machine_checks.hpp).
#include "tape/machine_checks.hpp"

#include <algorithm>

namespace tape {
namespace {

bool in(std::string_view set, char c) { return set.find(c) != std::string_view::npos; }

// The digits a whole-number word has in the profile's format, or 0 when it is no such word.
int format_digits(const MachineProfile& p, char address) {
    const WordFormat* f = p.format.find(address);
    return f && !f->dimension ? f->before : 0;
}

// A prefixed word written in full: its first digit and the code after it ("M104": 1, 4).
struct Prefixed {
    int first = 0;
    int code = 0;
};
std::optional<Prefixed> prefixed(const MachineProfile& p, const Word& w) {
    if (!in(p.prefixed, w.address) || w.has_point() || w.sign || w.macro) return std::nullopt;
    std::string d = w.digits();
    if (d.size() < 2 || static_cast<int>(d.size()) != format_digits(p, w.address)) return std::nullopt;
    return Prefixed{d[0] - '0', std::stoi(d.substr(1))};
}

void add(const std::function<void(Finding)>& out, std::string_view rule, const Word& w, const Block& b,
         std::string message) {
    out(program_finding(rule, w.where, b.ordinal, std::move(message)));
}

std::string feed_table_text(const MachineProfile& p) {
    std::string s;
    for (const auto& f : p.feed_codes) s += (s.empty() ? "" : ", ") + std::to_string(f.first_digit);
    return s;
}

void feed_check(const MachineProfile& p, const Word& w, const Block& b, const std::function<void(Finding)>& out) {
    std::string d = w.digits();
    if (w.has_point() || w.macro || d.empty() || static_cast<int>(d.size()) != format_digits(p, w.address)) return;
    if (p.find_feed_code(d[0] - '0')) return;
    add(out, "machine-feed-code", w, b,
        w.text + ": the first digit " + d.substr(0, 1) + " is no mode of " + p.title + "'s feed code table (" +
            feed_table_text(p) + "; " + p.sources.at("feed") + ")");
}

}  // namespace

MachineFormat::MachineFormat(const MachineProfile& p) : p_(&p) { program_start(); }

void MachineFormat::program_start() {
    mode_ = p_->initial_mode.empty() ? nullptr : p_->find_mode(p_->initial_mode);
    selected_by_.clear();
}

const FormatSpec& MachineFormat::block(const Block& b) {
    for (const auto& w : b.words) {
        if (w.address != 'G' || !w.known) continue;
        auto g = w.integer();
        const MachineCode* c = g ? p_->find_code('G', static_cast<int>(*g)) : nullptr;
        if (c && !c->mode.empty()) {
            mode_ = p_->find_mode(c->mode);
            selected_by_ = w.text;
        }
    }
    return mode_ ? mode_->spec : p_->format;
}

std::string MachineFormat::note(const Word& w) const {
    if (!mode_ || !in(mode_->addresses, w.address)) return "";
    std::string by = selected_by_.empty() ? "from the program's start" : selected_by_ + " in effect";
    return " (" + by + ": " + mode_->name + " dimensions, " + std::to_string(mode_->digits) + " digits)";
}

void machine_checks(const MachineProfile& p, const Block& b, const std::function<void(Finding)>& out) {
    for (const auto& w : b.words) {
        if (!w.known) continue;
        if (p.feed_table_address && w.address == p.feed_table_address) feed_check(p, w, b, out);
        auto pre = prefixed(p, w);
        if (!pre) continue;
        if (pre->first > 1)
            add(out, "machine-prefix", w, b,
                w.text + ": the first digit of " + std::string(1, w.address) +
                    " is 0 (at once) or 1 (after the machine's acknowledgement), not " + std::to_string(pre->first) +
                    " (" + p.sources.at("format") + ")");
        else if (w.address == 'S' && p.speed_table_complete && !p.find_speed_code(pre->code))
            add(out, "machine-speed-code", w, b,
                w.text + ": code " + std::to_string(pre->code) + " is not in " + p.title + "'s speed table (" +
                    p.sources.at("speed") + ")");
    }
}

}  // namespace tape
