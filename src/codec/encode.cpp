// Encoder: text program -> 8-track frames in ISO (parity on track 8) or EIA (by table).
#include "tape/encode.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "swar.hpp"
#include "tape/error.hpp"
#include "tape/utf8_text.hpp"
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

// Line and column (in characters) of byte offset in text, both from 1, counted on from base (the
// position of text's first byte).
Position text_position(std::string_view text, std::size_t offset, Position base = {.line = 1, .column = 1}) {
    Position p = base;
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

// The position after text, from the position of its first byte (newlines counted beforehand): the
// column is counted only over the last line, so that the hot path stays fast.
Position advance(Position p, std::string_view text, std::size_t newlines) {
    if (newlines == 0) {
        for (char c : text)
            if (!utf8::is_continuation(c)) ++*p.column;
        return p;
    }
    *p.line += newlines;
    p.column = 1;
    for (char c : text.substr(text.rfind('\n') + 1))
        if (!utf8::is_continuation(c)) ++*p.column;
    return p;
}

[[noreturn]] void cannot_carry(std::string_view text, std::size_t offset, Position base, Code code, Charset charset) {
    Position where = text_position(text, offset, base);
    std::string ch = std::string(utf8::char_at(text, offset));
    auto first = static_cast<unsigned char>(ch[0]);
    std::string shown = first < 0x20 ? char_label(ch[0]) : "'" + visible(ch) + "'";
    std::string why = shown + " cannot be punched in " + (code == Code::iso ? "ISO" : "EIA") + " code";
    if (first == 0x00) why = "a NUL byte in the text: on tape it would be blank tape, so it cannot be punched";
    if (first == 0x7F) why = "a DEL in the text: on tape it is a rubout that readers skip, so it cannot be punched";
    if (first >= 0x80) {
        auto cp = utf8::decode(ch);
        if (charset == Charset::ascii && cp && koi7_position(*cp))
            why += " (Cyrillic needs --charset koi7)";
        else if (cp && (*cp == U'Ё' || *cp == U'ё'))
            why += " (КОИ-7 has no Ё: write Е)";
        else if (cp && *cp == U'Ъ')
            why += " (КОИ-7 has no capital Ъ: write ъ)";
    }
    throw Error(Errc::bad_text, where, why);
}

// How many bytes at the end of text to hold back for the next chunk: a CR that may be half of CR LF,
// or the start of a UTF-8 character whose rest has not come yet.
std::size_t unfinished_tail(std::string_view text) {
    if (text.empty()) return 0;
    if (text.back() == '\r') return 1;
    std::size_t n = 0;
    while (n < text.size() && n < 4 && utf8::is_continuation(text[text.size() - 1 - n])) ++n;
    if (n == text.size()) return 0;
    auto lead = static_cast<unsigned char>(text[text.size() - 1 - n]);
    std::size_t want = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
    return want > n + 1 ? n + 1 : 0;
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

Encoder::Encoder(const EncodeOptions& options)
    : options_(options), code_(FrameCode::make(options.code, options.parity, options.eia_table)) {
    if (options.leader > max_blank_frames || options.trailer > max_blank_frames)
        throw Error(Errc::usage,
                    "a leader or trailer is at most " + std::to_string(max_blank_frames) + " blank frames");
}

// Text -> the 7-bit character stream: CR LF becomes LF (CR LF again with crlf), КОИ-7 letters get
// SO/SI shifts. Also records, per character, the byte offset in text it came from (for errors).
void Encoder::to_seven_bit(std::string_view text) {
    converted_.clear();
    origin_.clear();
    auto put = [&](char c, std::size_t from) {
        if (c == '\n' && options_.crlf) {
            converted_ += '\r';
            origin_.push_back(from);
        }
        converted_ += c;
        origin_.push_back(from);
    };
    for (std::size_t i = 0; i < text.size();) {
        auto c = static_cast<unsigned char>(text[i]);
        if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
            ++i;
            continue;
        }
        if (c < 0x80) {
            bool letter_column = c >= 0x40 && c <= 0x7E;
            if (cyrillic_ && (letter_column || c == '\n')) {
                put('\x0F', i);
                cyrillic_ = false;
            }
            put(static_cast<char>(c), i);
            ++i;
            continue;
        }
        std::size_t len = utf8::length(text, i);
        auto cp = utf8::decode(text.substr(i, len));
        auto pos = (options_.charset == Charset::koi7 && cp) ? koi7_position(*cp) : std::nullopt;
        if (!pos) cannot_carry(text, i, position_, options_.code, options_.charset);
        if (!cyrillic_) {
            put('\x0E', i);
            cyrillic_ = true;
        }
        put(static_cast<char>(*pos), i);
        i += len;
    }
}

void Encoder::encode_piece(std::string_view text, std::vector<Frame>& out) {
    if (!leader_done_) {
        out.insert(out.end(), options_.leader, blank_frame);
        leader_done_ = true;
    }
    swar::TextScan scan = swar::scan_text(text.data(), text.size());
    // NUL and DEL would encode, but read back as blank tape and a rubout: the program would lose them.
    if (scan.special)
        if (auto bad = std::min(text.find('\0'), text.find('\x7F')); bad != std::string_view::npos)
            cannot_carry(text, bad, position_, options_.code, options_.charset);
    std::string_view chars = text;
    bool plain = options_.charset == Charset::ascii && !options_.crlf &&
                 (!scan.special || text.find('\r') == std::string_view::npos);
    if (!plain) {
        to_seven_bit(text);
        chars = converted_;
    }
    std::size_t at = out.size();
    out.resize(at + chars.size());
    std::size_t stop = encode_run(code_, chars, out.data() + at);
    if (stop != chars.size())
        cannot_carry(text, plain ? stop : origin_[stop], position_, options_.code, options_.charset);
    position_ = advance(position_, text, scan.newlines);
}

void Encoder::feed(std::string_view text, std::vector<Frame>& out) {
    std::string joined;
    if (!held_.empty()) {
        // Rare: only where a chunk ended inside a character or after a CR.
        joined = held_ + std::string(text);
        held_.clear();
        text = joined;
    }
    std::size_t keep = unfinished_tail(text);
    encode_piece(text.substr(0, text.size() - keep), out);
    held_ = std::string(text.substr(text.size() - keep));
}

void Encoder::finish(std::vector<Frame>& out) {
    std::string rest = std::move(held_);
    held_.clear();
    encode_piece(rest, out);  // a lone CR at the very end is the CR character; a cut UTF-8 character an error
    if (cyrillic_) {
        converted_ = "\x0F";
        std::size_t at = out.size();
        out.resize(at + 1);
        encode_run(code_, converted_, out.data() + at);
        cyrillic_ = false;
    }
    out.insert(out.end(), options_.trailer, blank_frame);
}

std::vector<Frame> encode(std::string_view text, const EncodeOptions& options) {
    Encoder encoder(options);
    std::vector<Frame> frames;
    frames.reserve(options.leader + text.size() + options.trailer);
    encoder.feed(text, frames);
    encoder.finish(frames);
    return frames;
}

}  // namespace tape
