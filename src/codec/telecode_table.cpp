// Computer makers' 8-track telegraph codes as table data (data/elliott900.tab, data/elliott920.tab).
#include <charconv>
#include <stdexcept>
#include <vector>

#include "table_lines.hpp"
#include "tape/error.hpp"
#include "tape/telecode.hpp"
#include "utf8.hpp"

namespace tape {
namespace detail {
extern const char builtin_elliott900_table_text[];
extern const char builtin_elliott920_table_text[];
}  // namespace detail

namespace {

struct NamedEntry {
    std::string_view name;
    TelecodeTable::Kind kind;
    std::string_view text;
};
constexpr NamedEntry named_entries[] = {
    {"SP", TelecodeTable::Kind::character, " "},  {"HT", TelecodeTable::Kind::character, "\t"},
    {"LF", TelecodeTable::Kind::character, "\n"}, {"CR", TelecodeTable::Kind::character, "\r"},
    {"BS", TelecodeTable::Kind::character, "\b"}, {"BLANK", TelecodeTable::Kind::blank, ""},
    {"DEL", TelecodeTable::Kind::rubout, ""},
};

std::optional<char32_t> one_character(std::string_view s) {
    if (s.empty() || utf8::length(s, 0) != s.size()) return std::nullopt;
    return utf8::decode(s);
}

// A table's text read line by line: the tracks, then the values, then the checks of the whole.
class TableReader {
public:
    void line(const std::vector<std::string>& tokens, const std::string& rest);
    void tracks(const std::vector<std::string>& tokens);
    void value(const std::vector<std::string>& tokens);
    [[noreturn]] void fail(const std::string& why) const {
        throw Error(Errc::bad_table, Position{.line = line_no}, why);
    }

    std::uint64_t line_no = 0;
    std::string name;
    std::array<int, 7> value_tracks{};
    int parity_track = 0;
    std::array<std::optional<TelecodeTable::Entry>, 128> values;
    std::array<std::uint64_t, 128> value_lines{};
    std::vector<std::pair<std::string, std::string>> aliases;
    std::vector<std::uint64_t> alias_lines;
};

int track_number(const std::string& token) {
    int t = 0;
    auto [p, ec] = std::from_chars(token.data(), token.data() + token.size(), t);
    return ec == std::errc{} && p == token.data() + token.size() && t >= 1 && t <= 8 ? t : 0;
}

void TableReader::tracks(const std::vector<std::string>& tokens) {
    if (tokens.size() != 8) fail("'tracks' names the seven tracks of the value, bit 0 first");
    int seen = 0;
    for (std::size_t i = 0; i < 7; ++i) {
        int t = track_number(tokens[i + 1]);
        if (!t) fail("'" + tokens[i + 1] + "' is no track 1-8");
        if (seen & (1 << t)) fail("track " + tokens[i + 1] + " is given twice");
        seen |= 1 << t;
        value_tracks[i] = t;
    }
}

void TableReader::value(const std::vector<std::string>& tokens) {
    unsigned v = 0;
    const std::string& octal = tokens[0];
    auto [p, ec] = std::from_chars(octal.data(), octal.data() + octal.size(), v, 8);
    if (ec != std::errc{} || p != octal.data() + octal.size() || v > 0177)
        fail("'" + octal + "' is neither a keyword nor a code value in octal 000-177");
    if (tokens.size() < 2) fail("value " + octal + " has no character");
    if (values[v]) fail("value " + octal + " is given twice");
    TelecodeTable::Entry e{TelecodeTable::Kind::character, tokens[1], static_cast<std::uint8_t>(v)};
    bool named = false;
    for (const auto& n : named_entries)
        if (n.name == tokens[1]) {
            e.kind = n.kind;
            e.text = std::string(n.text);
            named = true;
        }
    if (!named && !one_character(tokens[1]))
        fail("'" + tokens[1] + "' is neither one character nor SP HT LF CR BS BLANK DEL");
    if ((e.kind == TelecodeTable::Kind::blank) != (v == 0)) fail("blank tape (BLANK) is value 000 and nothing else");
    values[v] = e;
    value_lines[v] = line_no;
}

void TableReader::line(const std::vector<std::string>& tokens, const std::string& rest) {
    const std::string& key = tokens[0];
    if (key == "name") {
        if (rest.empty()) fail("the name is missing");
        name = rest;
    } else if (key == "tracks") {
        tracks(tokens);
    } else if (key == "parity") {
        if (tokens.size() != 2 || !(parity_track = track_number(tokens[1]))) fail("'parity' names one track 1-8");
    } else if (key == "alias") {
        if (tokens.size() < 3) fail("an alias is: alias CHAR OTHER");
        aliases.emplace_back(tokens[1], tokens[2]);
        alias_lines.push_back(line_no);
    } else {
        value(tokens);
    }
}

}  // namespace

TelecodeTable TelecodeTable::parse(std::string_view text) {
    TableReader r;
    TableLines lines(text, TableComments::first_field);
    while (lines.next()) {
        r.line_no = lines.number();
        r.line(lines.fields(), lines.rest());
    }
    r.line_no = 0;
    if (r.name.empty()) r.fail("the table has no name line");
    if (!r.value_tracks[0] || !r.parity_track) r.fail("the table needs a tracks line and a parity line");
    for (int t : r.value_tracks)
        if (t == r.parity_track) r.fail("the parity track is one of the value's tracks");
    if (!r.values[0]) r.fail("the table has no blank tape (000 BLANK)");
    TelecodeTable table;
    table.name_ = r.name;
    table.value_tracks_ = r.value_tracks;
    table.parity_track_ = r.parity_track;
    for (unsigned v = 0; v < 128; ++v) {
        if (!r.values[v]) continue;
        r.line_no = r.value_lines[v];
        Frame f = table.frame_of_value(static_cast<std::uint8_t>(v));
        table.entries_[f] = *r.values[v];
        if (r.values[v]->kind != Kind::character) continue;
        char32_t c = *utf8::decode(r.values[v]->text);
        if (table.frames_.count(c)) r.fail("'" + r.values[v]->text + "' stands at two values");
        table.frames_[c] = f;
        if (r.values[v]->text.size() > 1 || c >= 0x80) table.wide_.push_back(r.values[v]->text);
    }
    if (!table.frames_.count(U'\n')) r.fail("the table has no LF");
    if (table.wide_.size() > 0x7E) r.fail("more than 126 characters that are not ASCII");
    for (std::size_t i = 0; i < r.aliases.size(); ++i) {
        r.line_no = r.alias_lines[i];
        auto c = one_character(r.aliases[i].first), o = one_character(r.aliases[i].second);
        if (!c || !o) r.fail("an alias is one character for another");
        if (table.frames_.count(*c)) r.fail("'" + r.aliases[i].first + "' already stands in the table");
        if (!table.frames_.count(*o)) r.fail("'" + r.aliases[i].second + "' is not in the table");
        table.frames_[*c] = table.frames_[*o];
    }
    return table;
}

const TelecodeTable& TelecodeTable::builtin(Code code) {
    static const TelecodeTable elliott900 = parse(detail::builtin_elliott900_table_text);
    static const TelecodeTable elliott920 = parse(detail::builtin_elliott920_table_text);
    if (code == Code::elliott900) return elliott900;
    if (code == Code::elliott920) return elliott920;
    throw std::logic_error("no telecode table for this code");
}

Frame TelecodeTable::frame_of_value(std::uint8_t value) const {
    unsigned f = 0;
    for (std::size_t bit = 0; bit < 7; ++bit)
        if (value >> bit & 1) f |= 1U << (value_tracks_[bit] - 1);
    if (hole_count(static_cast<Frame>(f)) % 2) f |= 1U << (parity_track_ - 1);
    return static_cast<Frame>(f);
}

std::optional<Frame> TelecodeTable::frame_of(char32_t c) const {
    auto it = frames_.find(c);
    if (it == frames_.end()) return std::nullopt;
    return it->second;
}

}  // namespace tape
