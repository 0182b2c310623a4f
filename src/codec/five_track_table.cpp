// 5-track code tables as data (data/ita2.tab, data/mtk2.tab), and the register-following labeler.
#include <vector>

#include "table_lines.hpp"
#include "tape/error.hpp"
#include "tape/five_track.hpp"
#include "utf8.hpp"

namespace tape {
namespace detail {
extern const char builtin_ita2_table_text[];
extern const char builtin_mtk2_table_text[];
}  // namespace detail

namespace {

constexpr std::string_view known_registers[] = {"LTRS", "FIGS", "RUS"};

// "10000" (tracks 1..5 left to right, as charts draw them) -> 0x01.
std::optional<Frame> parse_holes(std::string_view token) {
    if (token.size() != 5) return std::nullopt;
    Frame f = 0;
    for (std::size_t t = 0; t < 5; ++t) {
        if (token[t] == '1')
            f |= static_cast<Frame>(1U << t);
        else if (token[t] != '0')
            return std::nullopt;
    }
    return f;
}

std::string holes_text(Frame f) {
    std::string s;
    for (int t = 0; t < 5; ++t) s += (f >> t) & 1 ? '1' : '0';
    return s;
}

}  // namespace

// A table's text read line by line into the table, then checked whole: the shifts, where each character
// is punched, the aliases. Every complaint names the line it concerns, or none.
class FiveTrackTable::Reader {
public:
    FiveTrackTable t;
    std::uint64_t line_no = 0;

    [[noreturn]] void fail(const std::string& why) const {
        throw Error(Errc::bad_table, Position{.line = line_no}, why);
    }

    void line(const std::vector<std::string>& tokens) {
        if (tokens[0] == "registers") return registers(tokens);
        if (t.registers_ == 0) fail("the registers line must come before the frames");
        if (tokens[0] == "alias") {
            if (tokens.size() != 3) fail("an alias is: alias CHAR OTHER");
            aliases_.emplace_back(tokens[1], tokens[2]);
            alias_lines_.push_back(line_no);
            return;
        }
        frame(tokens);
    }

    void check_shifts();
    void place_characters();
    void apply_aliases();

private:
    // A register's name as a shift entry, or -1.
    int register_of(std::string_view name) const {
        for (int r = 0; r < t.registers_; ++r)
            if (t.register_names_[static_cast<std::size_t>(r)] == name) return r;
        return -1;
    }

    void registers(const std::vector<std::string>& tokens) {
        if (t.registers_ != 0) fail("the registers are given twice");
        if (tokens.size() < 2 || tokens.size() > max_registers + 1) fail("a code has one to three registers");
        for (std::size_t i = 1; i < tokens.size(); ++i) {
            bool known = false;
            for (auto k : known_registers) known |= k == tokens[i];
            if (!known) fail("'" + tokens[i] + "' is no register: LTRS, FIGS or RUS");
            if (register_of(tokens[i]) >= 0) fail("register " + tokens[i] + " is given twice");
            t.register_names_[static_cast<std::size_t>(t.registers_++)] = tokens[i];
        }
    }

    Meaning meaning_of(const std::string& e) const {
        if (e == "SP" || e == "CR" || e == "LF") return {Kind::character, 0, e == "SP" ? " " : e == "CR" ? "\r" : "\n"};
        if (e == "BLANK") return {Kind::blank, 0, ""};
        if (e == "NONE") return {Kind::none, 0, ""};
        if (int s = register_of(e); s >= 0) return {Kind::shift, static_cast<std::uint8_t>(s), ""};
        if (utf8::length(e, 0) == e.size() && utf8::decode(e)) return {Kind::character, 0, e};
        fail("'" + e + "' is neither one character nor SP CR LF BLANK NONE or a register name");
    }

    void frame(const std::vector<std::string>& tokens) {
        auto f = parse_holes(tokens[0]);
        if (!f) fail("'" + tokens[0] + "' is not five holes 0/1 for tracks 1..5, such as 10000");
        std::size_t entries = tokens.size() - 1;
        if (entries != 1 && entries != static_cast<std::size_t>(t.registers_))
            fail("frame " + tokens[0] + " needs one entry for every register, or one for all");
        for (int r = 0; r < t.registers_; ++r) {
            auto ur = static_cast<std::size_t>(r);
            if (given[ur][*f]) fail("frame " + tokens[0] + " is given twice");
            given[ur][*f] = line_no;
            t.meanings_[ur][*f] = meaning_of(tokens[entries == 1 ? 1 : ur + 1]);
        }
    }

public:
    std::array<std::array<std::uint64_t, five_track_frames>, max_registers> given{};  // the line, 0: not given

private:
    std::vector<std::pair<std::string, std::string>> aliases_;
    std::vector<std::uint64_t> alias_lines_;
};

// Shifts: one frame each, the same in every register, so that a reader in any state follows them.
void FiveTrackTable::Reader::check_shifts() {
    for (int r = 0; r < t.registers_; ++r) {
        int found = 0;
        for (Frame f = 0; f < five_track_frames; ++f) {
            line_no = given[static_cast<std::size_t>(r)][f];
            if (!line_no)
                throw Error(Errc::bad_table,
                            "frame " + holes_text(f) + " is not given in register " + std::string(t.register_name(r)));
            const Meaning& m = t.meaning(r, f);
            if (m.kind != Kind::shift) continue;
            for (int other = 0; other < t.registers_; ++other)
                if (t.meaning(other, f).kind != Kind::shift || t.meaning(other, f).shift != m.shift)
                    fail("shift frame " + holes_text(f) + " must mean the same in every register");
            if (m.shift == r) ++found, t.shift_frames_[static_cast<std::size_t>(r)] = f;
        }
        if (found != 1)
            throw Error(Errc::bad_table,
                        "register " + std::string(t.register_name(r)) + " needs exactly one shift frame");
    }
}

// Where each character is punched: in one register, or in all where the frame means it in all.
void FiveTrackTable::Reader::place_characters() {
    for (Frame f = 0; f < five_track_frames; ++f) {
        bool same = true;
        for (int r = 1; r < t.registers_; ++r)
            same &= t.meaning(r, f).kind == t.meaning(0, f).kind && t.meaning(r, f).text == t.meaning(0, f).text;
        for (int r = 0; r < (same ? 1 : t.registers_); ++r) {
            const Meaning& m = t.meaning(r, f);
            if (m.kind != Kind::character) continue;
            line_no = given[static_cast<std::size_t>(r)][f];
            char32_t c = *utf8::decode(m.text);
            if (t.places_.count(c)) fail("'" + m.text + "' stands in two places");
            t.places_[c] = Place{same ? std::nullopt : std::optional<std::uint8_t>(static_cast<std::uint8_t>(r)), f};
        }
    }
    if (!t.places_.count(U'\n')) throw Error(Errc::bad_table, "the table has no LF");
}

void FiveTrackTable::Reader::apply_aliases() {
    for (std::size_t i = 0; i < aliases_.size(); ++i) {
        line_no = alias_lines_[i];
        auto [name, other] = aliases_[i];
        auto c = utf8::length(name, 0) == name.size() ? utf8::decode(name) : std::nullopt;
        auto o = utf8::length(other, 0) == other.size() ? utf8::decode(other) : std::nullopt;
        if (!c || !o) fail("an alias is one character for another");
        if (t.places_.count(*c)) fail("'" + name + "' already stands in the table");
        if (!t.places_.count(*o)) fail("'" + other + "' is not in the table");
        t.places_[*c] = t.places_[*o];
    }
}

FiveTrackTable FiveTrackTable::parse(std::string_view text) {
    Reader r;
    TableLines lines(text, TableComments::any_field);
    while (lines.next()) {
        r.line_no = lines.number();
        r.line(lines.fields());
    }
    r.line_no = lines.number();  // a table without registers is said at its last line
    if (r.t.registers_ == 0) r.fail("the table has no registers line");
    // What is checked from here on is said at the line of the frame it concerns, or at none.
    r.check_shifts();
    r.place_characters();
    r.apply_aliases();
    return std::move(r.t);
}

const FiveTrackTable& FiveTrackTable::builtin_ita2() {
    static const FiveTrackTable table = parse(detail::builtin_ita2_table_text);
    return table;
}

const FiveTrackTable& FiveTrackTable::builtin_mtk2() {
    static const FiveTrackTable table = parse(detail::builtin_mtk2_table_text);
    return table;
}

std::optional<FiveTrackTable::Place> FiveTrackTable::place_of(char32_t c) const {
    auto it = places_.find(c);
    if (it == places_.end()) return std::nullopt;
    return it->second;
}

std::string FiveTrackTable::label(int r, Frame f) const {
    if (f >= five_track_frames) return "not 5-track";
    const Meaning& m = meaning(r, f);
    switch (m.kind) {
        case Kind::character:
            return m.text == " " ? "SP" : m.text == "\r" ? "CR" : m.text == "\n" ? "LF" : m.text;
        case Kind::shift:
            return std::string(register_name(m.shift));
        case Kind::blank:
            return "BLANK";
        case Kind::none:
            return "national";
    }
    return "?";
}

std::string FiveTrackLabeler::next(Frame f) {
    std::string label = table_->label(register_, f);
    if (f < five_track_frames && table_->meaning(register_, f).kind == FiveTrackTable::Kind::shift)
        register_ = table_->meaning(register_, f).shift;
    return label;
}

}  // namespace tape
