// Code tables as data, and the frame code lookup tables built from them.
#include "tape/code.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <vector>

#include "tape/error.hpp"
#include "tape/five_track.hpp"
#include "tape/telecode.hpp"

namespace tape {
namespace detail {
extern const char builtin_eia_table_text[];
}

namespace {

constexpr std::int16_t none = -1;

struct NamedChar {
    std::string_view name;
    char c;
};
constexpr NamedChar control_names[] = {
    {"NUL", 0x00}, {"BS", 0x08}, {"HT", 0x09}, {"LF", 0x0A}, {"EOB", 0x0A},
    {"CR", 0x0D},  {"SO", 0x0E}, {"SI", 0x0F}, {"SP", 0x20}, {"DEL", 0x7F},
};

std::optional<char> parse_char_name(std::string_view token) {
    if (token.size() == 1 && token[0] > 0x20 && token[0] < 0x7F) return token[0];
    for (const auto& n : control_names)
        if (n.name == token) return n.c;
    return std::nullopt;
}

// "1,2,5", "1-7" or "-" (no holes).
std::optional<Frame> parse_tracks(std::string_view token) {
    if (token == "-") return Frame{0};
    Frame f = 0;
    std::size_t pos = 0;
    while (pos <= token.size()) {
        std::size_t comma = token.find(',', pos);
        std::string_view part = token.substr(pos, comma == std::string_view::npos ? token.npos : comma - pos);
        int lo = 0, hi = 0;
        std::size_t dash = part.find('-');
        auto num = [](std::string_view s, int& out) {
            auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
            return ec == std::errc{} && p == s.data() + s.size() && out >= 1 && out <= 8;
        };
        if (dash == std::string_view::npos) {
            if (!num(part, lo)) return std::nullopt;
            hi = lo;
        } else if (!num(part.substr(0, dash), lo) || !num(part.substr(dash + 1), hi) || hi < lo) {
            return std::nullopt;
        }
        for (int t = lo; t <= hi; ++t) f |= static_cast<Frame>(1U << (t - 1));
        if (comma == std::string_view::npos) break;
        pos = comma + 1;
    }
    return f;
}

constexpr std::string_view ascii_control_names[32] = {
    "NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS",  "HT", "LF",  "VT",  "FF", "CR", "SO", "SI",
    "DLE", "DC1", "DC2", "DC3", "DC4", "NAK", "SYN", "ETB", "CAN", "EM", "SUB", "ESC", "FS", "GS", "RS", "US"};

}  // namespace

std::string_view code_name(Code c) {
    switch (c) {
        case Code::iso:
            return "iso";
        case Code::eia:
            return "eia";
        case Code::ita2:
            return "ita2";
        case Code::mtk2:
            return "mtk2";
        case Code::elliott900:
            return "elliott900";
        case Code::elliott920:
            return "elliott920";
    }
    return "?";
}

std::span<const Code> all_codes() {
    static constexpr Code codes[] = {Code::iso, Code::eia, Code::ita2, Code::mtk2, Code::elliott900, Code::elliott920};
    return codes;
}

std::string_view parity_name(Parity p) {
    switch (p) {
        case Parity::even:
            return "even";
        case Parity::odd:
            return "odd";
        case Parity::mark:
            return "mark";
        case Parity::space:
            return "space";
        case Parity::none:
            return "none";
    }
    return "?";
}

std::optional<Code> parse_code(std::string_view name) {
    for (Code c : all_codes())
        if (code_name(c) == name) return c;
    return std::nullopt;
}

std::optional<Parity> parse_parity(std::string_view name) {
    for (Parity p : {Parity::even, Parity::odd, Parity::mark, Parity::space, Parity::none})
        if (parity_name(p) == name) return p;
    return std::nullopt;
}

std::string char_label(char c) {
    auto u = static_cast<unsigned char>(c);
    if (u < 32) return std::string(ascii_control_names[u]);
    if (u == 0x20) return "SP";
    if (u == 0x7F) return "DEL";
    return std::string(1, c);
}

CodeTable CodeTable::parse(std::string_view text) {
    CodeTable t;
    t.frame_of_char_.fill(none);
    t.char_of_frame_.fill(none);
    std::istringstream in{std::string(text)};
    std::string line;
    std::uint64_t line_no = 0;
    auto fail = [&](const std::string& why) { throw Error(Errc::bad_table, Position{.line = line_no}, why); };
    while (std::getline(in, line)) {
        ++line_no;
        std::istringstream fields(line);
        std::string name, tracks;
        if (!(fields >> name) || name[0] == '#') continue;
        if (!(fields >> tracks)) fail("'" + name + "' has no tracks");
        auto c = parse_char_name(name);
        if (!c) fail("'" + name + "' is neither a printable character nor NUL SP HT LF BS CR SO SI DEL");
        auto f = parse_tracks(tracks);
        if (!f) fail("'" + tracks + "' is not a list of tracks 1-8 such as 1,2,5 or 1-7");
        if (*f != 0 && hole_count(*f) % 2 == 0)
            fail("'" + name + "' has an even number of holes; every EIA frame has odd parity (track 5)");
        if ((*f == 0) != (*c == 0)) fail("blank tape (-) belongs to NUL and to nothing else");
        auto uc = static_cast<unsigned char>(*c);
        if (t.frame_of_char_[uc] != none) fail("'" + name + "' is given twice");
        if (t.char_of_frame_[*f] != none)
            fail("tracks " + tracks + " are already given to " + char_label(static_cast<char>(t.char_of_frame_[*f])));
        t.frame_of_char_[uc] = *f;
        t.char_of_frame_[*f] = uc;
    }
    if (t.frame_of_char_[0x0A] == none) fail("the table has no LF (end of block) entry");
    return t;
}

const CodeTable& CodeTable::builtin_eia() {
    static const CodeTable table = parse(detail::builtin_eia_table_text);
    return table;
}

std::optional<Frame> CodeTable::frame_for(char c) const {
    auto u = static_cast<unsigned char>(c);
    if (u >= 128 || frame_of_char_[u] == none) return std::nullopt;
    return static_cast<Frame>(frame_of_char_[u]);
}

std::optional<char> CodeTable::char_for(Frame f) const {
    if (char_of_frame_[f] == none) return std::nullopt;
    return static_cast<char>(char_of_frame_[f]);
}

FrameCode FrameCode::iso(Parity parity) {
    FrameCode fc;
    fc.frame_.fill(none);
    fc.code_ = Code::iso;
    fc.parity_ = parity;
    for (int f = 0; f < 256; ++f) {
        bool odd_holes = hole_count(static_cast<Frame>(f)) % 2 != 0;
        bool track8 = (f & 0x80) != 0;
        bool good = true;
        switch (parity) {
            case Parity::even:
                good = !odd_holes;
                break;
            case Parity::odd:
                good = odd_holes;
                break;
            case Parity::mark:
                good = track8;
                break;
            case Parity::space:
                good = !track8;
                break;
            case Parity::none:
                break;
        }
        int c = f & 0x7F;
        FrameKind k = FrameKind::character;
        if (f == 0 || (good && c == 0))
            k = FrameKind::blank;  // unpunched tape is blank under any rule
        else if (!good)
            k = FrameKind::parity_error;
        else if (c == 0x7F)
            k = FrameKind::rubout;
        fc.kind_[f] = static_cast<std::int8_t>(k);
        fc.char_[f] = static_cast<std::uint8_t>(c);
    }
    for (int c = 0; c < 128; ++c) {
        bool odd7 = hole_count(static_cast<Frame>(c)) % 2 != 0;
        bool track8 = false;
        switch (parity) {
            case Parity::even:
                track8 = odd7;
                break;
            case Parity::odd:
                track8 = !odd7;
                break;
            case Parity::mark:
                track8 = true;
                break;
            case Parity::space:
            case Parity::none:
                break;
        }
        fc.frame_[c] = static_cast<std::int16_t>(c | (track8 ? 0x80 : 0));
    }
    fc.frame_[0] = 0;  // NUL is blank tape
    return fc;
}

FrameCode FrameCode::eia(const CodeTable& table) {
    FrameCode fc;
    fc.frame_.fill(none);
    fc.code_ = Code::eia;
    fc.parity_ = Parity::odd;
    auto del = table.frame_for(0x7F);
    for (int f = 0; f < 256; ++f) {
        auto frame = static_cast<Frame>(f);
        FrameKind k;
        if (f == 0)
            k = FrameKind::blank;
        else if (del && frame == *del)
            k = FrameKind::rubout;
        else if (hole_count(frame) % 2 == 0)
            k = FrameKind::parity_error;
        else if (table.char_for(frame))
            k = FrameKind::character;
        else
            k = FrameKind::not_in_code;
        fc.kind_[f] = static_cast<std::int8_t>(k);
        fc.char_[f] = static_cast<std::uint8_t>(table.char_for(frame).value_or(0));
    }
    for (int c = 0; c < 128; ++c) {
        auto f = table.frame_for(static_cast<char>(c));
        fc.frame_[c] = f ? static_cast<std::int16_t>(*f) : none;
    }
    return fc;
}

FrameCode FrameCode::five_track(Code code) {
    FrameCode fc;
    fc.code_ = code;
    fc.parity_ = Parity::none;
    fc.five_track_ = code == Code::mtk2 ? &FiveTrackTable::builtin_mtk2() : &FiveTrackTable::builtin_ita2();
    for (int f = 0; f < 256; ++f) {
        FrameKind k = FrameKind::not_in_code;
        if (f < five_track_frames) {
            const auto& m = fc.five_track_->meaning(0, static_cast<Frame>(f));
            k = m.kind == FiveTrackTable::Kind::blank ? FrameKind::blank : FrameKind::character;
            if (m.kind == FiveTrackTable::Kind::character && m.text.size() == 1)
                fc.char_[f] = static_cast<std::uint8_t>(m.text[0]);
        }
        fc.kind_[f] = static_cast<std::int8_t>(k);
    }
    fc.frame_.fill(none);  // text goes through the Encoder, which picks the shifts
    return fc;
}

FrameCode FrameCode::telecode(Code code) {
    using Kind = TelecodeTable::Kind;
    FrameCode fc;
    fc.frame_.fill(none);
    fc.code_ = code;
    fc.parity_ = Parity::even;
    fc.telecode_ = &TelecodeTable::builtin(code);
    const auto& wide = fc.telecode_->wide_characters();
    for (int f = 0; f < 256; ++f) {
        const auto& e = fc.telecode_->entry(static_cast<Frame>(f));
        FrameKind k = e.kind == Kind::blank       ? FrameKind::blank
                      : e.kind == Kind::rubout    ? FrameKind::rubout
                      : e.kind == Kind::character ? FrameKind::character
                                                  : FrameKind::not_in_code;
        if (hole_count(static_cast<Frame>(f)) % 2) k = FrameKind::parity_error;
        fc.kind_[f] = static_cast<std::int8_t>(k);
        if (k != FrameKind::character) continue;
        auto at = std::find(wide.begin(), wide.end(), e.text);
        auto byte = at == wide.end() ? static_cast<unsigned char>(e.text[0]) : 0x81 + (at - wide.begin());
        fc.char_[f] = static_cast<std::uint8_t>(byte);
        fc.frame_[byte] = static_cast<std::int16_t>(f);
    }
    return fc;
}

std::string_view FrameCode::wide_character(unsigned char byte) const {
    if (telecode_ && byte > 0x80 && byte - 0x81U < telecode_->wide_characters().size())
        return telecode_->wide_characters()[byte - 0x81];
    return {};
}

FrameCode FrameCode::make(Code code, Parity parity, const CodeTable* eia_table) {
    if (is_five_track(code)) return five_track(code);
    if (is_telecode(code)) return telecode(code);
    if (code == Code::iso) return iso(parity);
    return eia(eia_table ? *eia_table : CodeTable::builtin_eia());
}

std::optional<Frame> FrameCode::frame_for(unsigned char c) const {
    if (frame_[c] == none) return std::nullopt;
    return static_cast<Frame>(frame_[c]);
}

std::string FrameCode::label(Frame f) const {
    if (five_track_) {
        if (f >= five_track_frames) return "not 5-track";
        std::string all = five_track_->label(0, f);
        for (int r = 1; r < five_track_->registers(); ++r)
            if (auto l = five_track_->label(r, f); l != five_track_->label(0, f)) all += "/" + l;
        return all;
    }
    switch (kind(f)) {
        case FrameKind::character:
            if (auto wide = wide_character(char_[f]); !wide.empty()) return std::string(wide);
            return char_label(character(f));
        case FrameKind::blank:
            return "NUL";
        case FrameKind::rubout:
            return "DEL";
        case FrameKind::parity_error:
            return "parity error";
        case FrameKind::not_in_code:
            return code_ == Code::eia ? "not an EIA character"
                   : telecode_        ? "not in the " + telecode_->name()
                                      : "not an ISO character";
    }
    return "?";
}

}  // namespace tape
