// Requests punched out by a control: (PRG=NAME[,NAME...]) and (RESTART=NAME,N50), read from the
// comments of a punch-out's text. Nothing here touches the file system.
#include <algorithm>
#include <cctype>

#include "tape/dnc_request.hpp"

namespace tape::dnc {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// "PRG" in "(PRG=...)", in either case, with blanks before '='; the rest after '=' in value.
bool has_key(std::string_view comment, std::string_view key, std::string_view& value) {
    comment = trim(comment);
    if (comment.size() <= key.size()) return false;
    for (std::size_t i = 0; i < key.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(comment[i])) != key[i]) return false;
    std::string_view rest = trim(comment.substr(key.size()));
    if (rest.empty() || rest.front() != '=') return false;
    value = rest.substr(1);
    return true;
}

std::vector<std::string_view> split(std::string_view list) {
    std::vector<std::string_view> parts;
    for (std::size_t from = 0;;) {
        auto comma = list.find(',', from);
        parts.push_back(trim(list.substr(from, comma == std::string_view::npos ? list.npos : comma - from)));
        if (comma == std::string_view::npos) return parts;
        from = comma + 1;
    }
}

// For the log: what was punched, printable ASCII only, at most 80 characters.
std::string printable(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 80)) out += (c >= 0x20 && c < 0x7F) ? c : '?';
    return out;
}

// What a name looks like in a message: printable, cut short.
std::string shown(std::string_view name) {
    return "'" + printable(name.substr(0, 40)) + (name.size() > 40 ? "...'" : "'");
}

void take_name(Request& r, std::string_view name) {
    std::string problem = name_problem(name);
    if (problem.empty())
        r.names.emplace_back(name);
    else
        r.refused.push_back(shown(name) + ": " + problem);
}

bool is_block_number(std::string_view b) {
    if (b.size() < 2 || b.size() > 10 || (b[0] != 'N' && b[0] != 'n' && b[0] != ':')) return false;
    return std::all_of(b.begin() + 1, b.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Refusals past the first few are counted, not listed: a request of a thousand bad names is a few log lines.
constexpr std::size_t max_refusals_listed = 8;

void take_names(Request& r, std::string_view list) {
    std::size_t empty = 0, unlisted = 0;
    for (auto name : split(list)) {
        if (name.empty()) {
            ++empty;
            continue;
        }
        std::size_t before = r.refused.size();
        take_name(r, name);
        if (r.refused.size() > max_refusals_listed) r.refused.resize(before), ++unlisted;
    }
    if (empty)
        r.refused.push_back(std::to_string(empty) + " empty name" + (empty > 1 ? "s" : "") +
                            " (commas with nothing between them)");
    if (unlisted) r.refused.push_back(std::to_string(unlisted) + " more name(s) refused, not listed");
}

std::optional<Request> request_in(std::string_view comment) {
    std::string_view value;
    Request r;
    r.comment = "(" + printable(comment) + ")";
    if (has_key(comment, "PRG", value)) {
        take_names(r, value);
        return r;
    }
    if (!has_key(comment, "RESTART", value)) return std::nullopt;
    r.kind = Request::Kind::restart;
    auto parts = split(value);
    if (parts.size() != 2 || !is_block_number(parts[1])) {
        r.refused.push_back(shown(value) + ": a restart is (RESTART=NAME,N50): a name and a block number");
        return r;
    }
    take_name(r, parts[0]);
    r.block = std::string(parts[1]);
    return r;
}

// A block around a request that is no program of its own: empty, a lone '%' (with a ГОСТ number), a
// program number (O1234, :1234), a block number, or a program's end (M02, M30, M99) with one or not.
bool envelope_block(std::string block) {
    std::erase_if(block, [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
    for (char& c : block) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    auto digits = [](std::string_view s) {
        return !s.empty() && s.size() <= 8 &&
               std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    std::string_view b = block;
    if (b.empty() || b == "%" || (b[0] == '%' && digits(b.substr(1)))) return true;
    if ((b[0] == 'O' || b[0] == ':') && digits(b.substr(1))) return true;
    if (b[0] == 'N') {
        auto end = std::min(b.find('M'), b.size());
        if (!digits(b.substr(1, end - 1))) return false;
        b.remove_prefix(end);
    }
    if (b.empty()) return true;  // a block number alone
    return b == "M02" || b == "M2" || b == "M30" || b == "M99";
}

// True when text (what stands around a request's comment) holds nothing but envelope blocks.
bool only_envelope(std::string_view text) {
    for (std::size_t from = 0; from <= text.size();) {
        auto end = text.find_first_of("\n;", from);
        if (end == std::string_view::npos) end = text.size();
        if (!envelope_block(std::string(text.substr(from, end - from)))) return false;
        from = end + 1;
    }
    return true;
}

}  // namespace

std::string name_problem(std::string_view name) {
    if (name.empty()) return "an empty name";
    if (name.size() > max_name_length)
        return "over-long (" + std::to_string(name.size()) + " characters; a name has at most " +
               std::to_string(max_name_length) + ")";
    if (name.find('\0') != std::string_view::npos) return "holds a NUL";
    if (name.find('/') != std::string_view::npos || name.find('\\') != std::string_view::npos ||
        name.find("..") != std::string_view::npos)
        return "a path: names are looked up in the library, never followed";
    if (name.front() == '.') return "a hidden file's name";
    for (char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
            return "holds '" + printable({&c, 1}) + "': a name is letters, digits, '_', '-' and '.'";
    return "";
}

std::optional<Request> request_comment_in(std::string_view text, std::size_t* open_at, std::size_t* close_at) {
    for (std::size_t open = text.find('('); open != std::string_view::npos; open = text.find('(', open + 1)) {
        auto close = text.find_first_of(")\n", open + 1);
        if (close == std::string_view::npos) return std::nullopt;
        if (text[close] == '\n') continue;  // an unclosed comment ends with its line
        if (auto r = request_in(text.substr(open + 1, close - open - 1))) {
            if (open_at) *open_at = open;
            if (close_at) *close_at = close;
            return r;
        }
        open = close;
    }
    return std::nullopt;
}

std::optional<Request> parse_request(std::string_view text) {
    std::size_t open = 0, close = 0;
    auto r = request_comment_in(text, &open, &close);
    if (!r || !only_envelope(text.substr(0, open)) || !only_envelope(text.substr(close + 1))) return std::nullopt;
    return r;
}

}  // namespace tape::dnc
