// Encoder: text program -> 8-track frames in ISO (parity on track 8) or EIA (by table).
#include <cstring>
#include <string>

#include "swar.hpp"
#include "tape/encode.hpp"
#include "tape/error.hpp"
#include "utf8.hpp"

namespace tape {
namespace {

// 64 characters a step while all are 7-bit: track 8 is the parity of the other seven.
std::size_t iso_even_run(const char* in, std::size_t n, Frame* out) {
    constexpr std::size_t step = 64;
    std::size_t i = 0;
    for (; i + step <= n; i += step) {
        swar::bytes16 high{}, v[4];
        for (int k = 0; k < 4; ++k) {
            v[k] = swar::load16(in + i + 16 * k);
            high |= v[k] & 0x80;
        }
        if (swar::any16(high)) break;
        for (int k = 0; k < 4; ++k) swar::store16(out + i + 16 * k, v[k] | swar::parity_track16(v[k]));
    }
    for (; i < n; ++i) {
        auto c = static_cast<unsigned char>(in[i]);
        if (c >= 0x80) return i;
        out[i] = static_cast<Frame>(c | ((hole_count(c) & 1) << 7));
    }
    return n;
}

// Line and column (in characters) of byte offset in text, both from 1.
Position text_position(std::string_view text, std::size_t offset) {
    Position p{.line = 1, .column = 1};
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++*p.line;
            p.column = 1;
        } else if (!utf8::is_continuation(text[i])) {
            ++*p.column;
        }
    }
    return p;
}

[[noreturn]] void cannot_carry(std::string_view text, std::size_t offset, Code code, Charset charset) {
    Position where = text_position(text, offset);
    std::string ch = std::string(utf8::char_at(text, offset));
    std::string shown = static_cast<unsigned char>(ch[0]) < 0x20 ? char_label(ch[0]) : "'" + ch + "'";
    std::string why = shown + " cannot be punched in " + (code == Code::iso ? "ISO" : "EIA") + " code";
    if (static_cast<unsigned char>(ch[0]) >= 0x80) {
        auto cp = utf8::decode(ch);
        if (charset == Charset::ascii && cp && koi7_position(*cp)) why += " (Cyrillic needs --charset koi7)";
        else if (cp && (*cp == U'Ё' || *cp == U'ё')) why += " (КОИ-7 has no Ё: write Е)";
        else if (cp && *cp == U'Ъ') why += " (КОИ-7 has no capital Ъ: write ъ)";
    }
    throw Error(Errc::bad_text, where, why);
}

// Text -> the 7-bit character stream: CR LF becomes LF, КОИ-7 letters get SO/SI shifts.
// Also returns, per character, the byte offset in text it came from (for error positions).
std::string to_seven_bit(std::string_view text, Charset charset, Code code, std::vector<std::size_t>* origin) {
    std::string out;
    out.reserve(text.size());
    bool cyrillic = false;
    auto put = [&](char c, std::size_t from) {
        out += c;
        origin->push_back(from);
    };
    for (std::size_t i = 0; i < text.size();) {
        auto c = static_cast<unsigned char>(text[i]);
        if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') { ++i; continue; }
        if (c < 0x80) {
            bool letter_column = c >= 0x40 && c <= 0x7E;
            if (cyrillic && (letter_column || c == '\n')) { put('\x0F', i); cyrillic = false; }
            put(static_cast<char>(c), i);
            ++i;
            continue;
        }
        std::size_t len = utf8::length(text, i);
        auto cp = utf8::decode(text.substr(i, len));
        auto pos = (charset == Charset::koi7 && cp) ? koi7_position(*cp) : std::nullopt;
        if (!pos) cannot_carry(text, i, code, charset);
        if (!cyrillic) { put('\x0E', i); cyrillic = true; }
        put(static_cast<char>(*pos), i);
        i += len;
    }
    if (cyrillic) put('\x0F', text.size());
    return out;
}

}  // namespace

std::size_t encode_run(const FrameCode& code, std::string_view chars, Frame* out) {
    if (code.code() == Code::iso && code.parity() == Parity::even) return iso_even_run(chars.data(), chars.size(), out);
    for (std::size_t i = 0; i < chars.size(); ++i) {
        auto f = code.frame_for(static_cast<unsigned char>(chars[i]));
        if (!f) return i;
        out[i] = *f;
    }
    return chars.size();
}

std::vector<Frame> encode(std::string_view text, const EncodeOptions& options) {
    FrameCode code = FrameCode::make(options.code, options.parity, options.eia_table);
    std::string converted;
    std::vector<std::size_t> origin;
    std::string_view chars = text;
    bool plain = options.charset == Charset::ascii && text.find('\r') == std::string_view::npos && !options.crlf;
    if (!plain) {
        converted = to_seven_bit(text, options.charset, options.code, &origin);
        if (options.crlf) {
            std::string with_cr;
            std::vector<std::size_t> with_cr_origin;
            for (std::size_t i = 0; i < converted.size(); ++i) {
                if (converted[i] == '\n') {
                    with_cr += '\r';
                    with_cr_origin.push_back(origin[i]);
                }
                with_cr += converted[i];
                with_cr_origin.push_back(origin[i]);
            }
            converted = std::move(with_cr);
            origin = std::move(with_cr_origin);
        }
        chars = converted;
    }
    std::vector<Frame> frames(options.leader + chars.size() + options.trailer, blank_frame);
    std::size_t stop = encode_run(code, chars, frames.data() + options.leader);
    if (stop != chars.size()) cannot_carry(text, plain ? stop : origin[stop], options.code, options.charset);
    return frames;
}

}  // namespace tape
