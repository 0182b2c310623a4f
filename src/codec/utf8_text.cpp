#include "tape/utf8_text.hpp"

#include <algorithm>
#include <cstdio>

#include "swar.hpp"
#include "utf8.hpp"

namespace tape {
namespace {

bool allowed_control(unsigned char c) { return c == '\t' || c == '\n' || c == '\r' || c == 0x0E || c == 0x0F; }

// Characters that show as nothing or as a space: a reader of a message could not tell they are there.
bool invisible(char32_t cp) {
    return cp == 0xA0 || cp == 0xAD || cp == 0xFEFF || (cp >= 0x200B && cp <= 0x200F) ||
           (cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2060 && cp <= 0x2064) || (cp >= 0x80 && cp < 0xA0);
}

std::string hex_byte(unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", c);
    return buf;
}

std::string code_point_name(char32_t cp) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(cp));
    return buf;
}

// The first byte at or after from that needs a closer look: not ASCII, or a control character other
// than those a program's text may hold. Sixteen bytes at a time: most texts have none.
std::size_t next_unusual(std::string_view s, std::size_t from) {
    std::size_t i = from;
    for (; i + 16 <= s.size(); i += 16) {
        swar::bytes16 v = swar::load16(s.data() + i);
        swar::bytes16 control = reinterpret_cast<swar::bytes16>(v < 0x20) & reinterpret_cast<swar::bytes16>(v != '\t') &
                                reinterpret_cast<swar::bytes16>(v != '\n') &
                                reinterpret_cast<swar::bytes16>(v != '\r') &
                                reinterpret_cast<swar::bytes16>(v != 0x0E) & reinterpret_cast<swar::bytes16>(v != 0x0F);
        if (swar::any16(control | reinterpret_cast<swar::bytes16>(v >= 0x7F))) break;
    }
    for (; i < s.size(); ++i) {
        auto c = static_cast<unsigned char>(s[i]);
        if (c >= 0x7F || (c < 0x20 && !allowed_control(c))) return i;
    }
    return i;
}

}  // namespace

std::size_t dos_end_of_file_at(std::span<const std::uint8_t> bytes) {
    std::size_t at = bytes.size();
    while (at > 0 && bytes[at - 1] == dos_end_of_file) --at;
    return at;
}

Diagnostic dos_end_of_file_note(const Position& where) {
    return Diagnostic{.code = Errc::bad_text,
                      .where = where,
                      .message = "the text ends with a DOS end-of-file mark (Ctrl-Z): not part of the program",
                      .severity = Severity::note};
}

std::optional<TextFault> find_text_fault(std::span<const std::uint8_t> bytes) {
    bytes = bytes.first(dos_end_of_file_at(bytes));
    std::string_view s(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::uint64_t line = 1, column = 1;
    for (std::size_t i = 0; i < s.size();) {
        // Plain ASCII up to the next byte worth a look: its lines and columns counted at once.
        std::size_t next = next_unusual(s, i);
        std::string_view plain = s.substr(i, next - i);
        if (std::size_t lines = swar::count_newlines(plain.data(), plain.size())) {
            line += lines;
            column = 1 + (plain.size() - plain.rfind('\n') - 1);
        } else {
            column += plain.size();
        }
        i = next;
        if (i == s.size()) break;
        auto c = static_cast<unsigned char>(s[i]);
        std::string what;
        std::size_t n = 1;
        if (c == 0) {
            what = "a NUL byte";
        } else if (c < 0x80) {
            what = "the control character " + hex_byte(c);
        } else {
            n = utf8::length(s, i);
            if (n == 1 || !utf8::decode(s.substr(i, n)))
                what = "byte 0x" + hex_byte(c).substr(2) + ", which is not UTF-8";
        }
        if (!what.empty()) return TextFault{Position{.line = line, .column = column}, i, what};
        ++column;
        i += n;
    }
    return std::nullopt;
}

Diagnostic byte_order_mark_note() {
    return Diagnostic{.code = Errc::bad_text,
                      .where = Position{.line = 1, .byte = 0},
                      .message = "skipped the UTF-8 byte-order mark (U+FEFF)",
                      .severity = Severity::note};
}

bool is_program_text(std::span<const std::uint8_t> bytes) { return !find_text_fault(bytes); }

std::optional<TextFault> TextChecker::check(std::span<const std::uint8_t> piece) {
    std::vector<std::uint8_t> joined;
    if (!carry_.empty()) {
        joined.swap(carry_);
        joined.insert(joined.end(), piece.begin(), piece.end());
        piece = joined;
    }
    // A character cut by the piece's end is checked with the next piece.
    std::size_t cut = utf8::whole_prefix({reinterpret_cast<const char*>(piece.data()), piece.size()});
    carry_.assign(piece.begin() + static_cast<std::ptrdiff_t>(cut), piece.end());
    auto whole = piece.first(cut);
    // End-of-file marks wait for what follows: the end of the text, or text that makes the first a fault.
    std::size_t marks_at = dos_end_of_file_at(whole);
    if (marks_ && (marks_at > 0 || !carry_.empty())) {
        mark_.what = "the control character \\x1A (Ctrl-Z, the DOS end-of-file mark, with text after it)";
        return mark_;
    }
    if (!marks_) {
        if (auto fault = check_whole(whole.first(marks_at))) return fault;
        mark_ = TextFault{Position{.line = lines_before_ + 1, .column = columns_before_ + 1}, bytes_before_, {}};
    }
    marks_ += whole.size() - marks_at;
    return std::nullopt;
}

std::optional<TextFault> TextChecker::finish() {
    if (marks_ && !carry_.empty()) return check(std::span<const std::uint8_t>{});
    auto fault = check_whole(carry_);
    carry_.clear();
    return fault;
}

std::optional<TextFault> TextChecker::check_whole(std::span<const std::uint8_t> bytes) {
    if (auto fault = find_text_fault(bytes)) {
        if (*fault->where.line == 1) *fault->where.column += columns_before_;
        *fault->where.line += lines_before_;
        fault->offset += bytes_before_;
        return fault;
    }
    std::string_view s(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    auto last_nl = s.rfind('\n');
    std::string_view tail = last_nl == std::string_view::npos ? s : s.substr(last_nl + 1);
    auto chars = static_cast<std::uint64_t>(
        std::count_if(tail.begin(), tail.end(), [](char c) { return !utf8::is_continuation(c); }));
    lines_before_ += swar::count_newlines(s.data(), s.size());
    columns_before_ = last_nl == std::string_view::npos ? columns_before_ + chars : chars;
    bytes_before_ += bytes.size();
    return std::nullopt;
}

bool looks_like_damaged_text(std::span<const std::uint8_t> bytes) {
    auto sample = bytes.first(std::min<std::size_t>(bytes.size(), 65536));
    if (sample.empty() || sample[0] == 0) return false;  // a tape starts with blank leader
    std::string_view s(reinterpret_cast<const char*>(sample.data()), sample.size());
    std::size_t wrong = 0, lines = 0;
    for (std::size_t i = 0; i < s.size();) {
        auto c = static_cast<unsigned char>(s[i]);
        std::size_t n = c < 0x80 ? 1 : utf8::length(s, i);
        if (c < 0x80) {
            lines += c == '\n';
            wrong += (c < 0x20 && !allowed_control(c)) || c == 0x7F;
        } else if (n == 1 || !utf8::decode(s.substr(i, n))) {
            n = 1;
            ++wrong;
        }
        i += n;
    }
    // A raw ISO tape has track 8 punched in about half its frames, none of it UTF-8; a text file
    // damaged in transfer has a stray byte or two.
    return lines > 0 && wrong <= std::max<std::size_t>(2, s.size() / 50) && wrong * 10 <= s.size();
}

std::string visible(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        auto c = static_cast<unsigned char>(s[i]);
        if (c < 0x80) {
            if (c < 0x20 || c == 0x7F)
                out += hex_byte(c);
            else
                out += static_cast<char>(c);
            ++i;
            continue;
        }
        std::size_t n = utf8::length(s, i);
        auto cp = n > 1 ? utf8::decode(s.substr(i, n)) : std::nullopt;
        if (!cp) {
            out += hex_byte(c);
            ++i;
            continue;
        }
        if (invisible(*cp))
            out += code_point_name(*cp);
        else
            out.append(s.substr(i, n));
        i += n;
    }
    return out;
}

}  // namespace tape
