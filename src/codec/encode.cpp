// Encoder: text program -> 8-track frames in ISO (parity on track 8) or EIA (by table).
#include "tape/encode.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "swar.hpp"
#include "tape/error.hpp"
#include "tape/label.hpp"
#include "tape/utf8_text.hpp"
#include "utf8.hpp"

namespace tape {
namespace {

// ISO with even parity: track 8 is the parity of the other seven. The vector loops take whole blocks
// of 7-bit characters and stop before the first block with a byte they leave to the caller: above 0x7F,
// and with `plain` (the Encoder's one pass over ASCII text) also NUL, CR and DEL, counting the newlines
// (for messages) on the way. NUL and DEL are caught by the byte minimum and maximum of the block.
using IsoEvenRun = std::size_t (*)(const char* in, std::size_t n, Frame* out, std::size_t* newlines);

template <bool plain>
std::size_t iso_even_sse2(const char* in, std::size_t n, Frame* out, std::size_t* newlines) {
    constexpr std::size_t step = 64;
    std::size_t i = 0;
    for (bool go = true; go && i + step <= n;) {
        swar::bytes16 lines{};  // per byte: newlines in these blocks, 4 a block: 63 blocks fit a byte
        for (int blocks = 0; blocks < 63 && i + step <= n; ++blocks, i += step) {
            swar::bytes16 v[4], low = ~swar::bytes16{}, high{}, cr{}, nl{};
            for (int k = 0; k < 4; ++k) {
                v[k] = swar::load16(in + i + 16 * k);
                high = v[k] > high ? v[k] : high;
                if constexpr (plain) {
                    low = v[k] < low ? v[k] : low;
                    cr |= reinterpret_cast<swar::bytes16>(v[k] == '\r');
                    nl -= reinterpret_cast<swar::bytes16>(v[k] == '\n');
                }
            }
            swar::bytes16 stop = high & 0x80;
            if constexpr (plain) stop |= (low == 0) | reinterpret_cast<swar::bytes16>(high == 0x7F) | cr;
            if (swar::any16(stop)) {
                go = false;
                break;
            }
            for (int k = 0; k < 4; ++k) swar::store16(out + i + 16 * k, v[k] | swar::parity_track16(v[k]));
            lines += nl;
        }
        if constexpr (plain) *newlines += swar::byte_sum(lines);
    }
    return i;
}

#ifdef TAPE_SWAR_AVX2
template <bool plain>
__attribute__((target("avx2"))) std::size_t iso_even_avx2(const char* in, std::size_t n, Frame* out,
                                                          std::size_t* newlines) {
    constexpr std::size_t step = 128;
    const __m256i track8 = _mm256_load_si256(reinterpret_cast<const __m256i*>(swar::nibble_parity<0x80>.table));
    const __m256i nibble = _mm256_set1_epi8(0x0F), del = _mm256_set1_epi8(0x7F);
    const __m256i cr_byte = _mm256_set1_epi8('\r'), lf_byte = _mm256_set1_epi8('\n');
    const __m256i zero = _mm256_setzero_si256(), ones = _mm256_set1_epi8(-1);
    std::size_t i = 0, count = 0;
    for (bool go = true; go && i + step <= n;) {
        __m256i lines = zero;  // per byte: newlines in these blocks, 4 a block: 63 blocks fit a byte
        for (int blocks = 0; blocks < 63 && i + step <= n; ++blocks, i += step) {
            __m256i v[4], low = ones, high = zero, cr = zero, nl = zero;
            for (int k = 0; k < 4; ++k) {
                v[k] = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(in + i + 32 * k));
                high = _mm256_max_epu8(high, v[k]);
                if constexpr (plain) {
                    low = _mm256_min_epu8(low, v[k]);
                    cr = _mm256_or_si256(cr, _mm256_cmpeq_epi8(v[k], cr_byte));
                    nl = _mm256_sub_epi8(nl, _mm256_cmpeq_epi8(v[k], lf_byte));
                }
            }
            __m256i stop = high;  // bit 7 of the maximum: a byte above 0x7F
            if constexpr (plain)  // the maximum at least DEL, the minimum NUL, or a CR
                stop = _mm256_or_si256(_mm256_cmpeq_epi8(_mm256_max_epu8(high, del), high),
                                       _mm256_or_si256(_mm256_cmpeq_epi8(low, zero), cr));
            if (!_mm256_testz_si256(stop, plain ? ones : _mm256_set1_epi8(-128))) {
                go = false;
                break;
            }
            for (int k = 0; k < 4; ++k) {
                // Bit 7 is clear in every byte here, so v indexes the low-nibble table as it is.
                __m256i hi = _mm256_and_si256(_mm256_srli_epi16(v[k], 4), nibble);
                __m256i parity = _mm256_xor_si256(_mm256_shuffle_epi8(track8, v[k]), _mm256_shuffle_epi8(track8, hi));
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + i + 32 * k), _mm256_or_si256(v[k], parity));
            }
            lines = _mm256_add_epi8(lines, nl);
        }
        if constexpr (plain) {
            __m256i sums = _mm256_sad_epu8(lines, zero);  // four 64-bit sums
            count += static_cast<std::size_t>(_mm256_extract_epi64(sums, 0) + _mm256_extract_epi64(sums, 1) +
                                              _mm256_extract_epi64(sums, 2) + _mm256_extract_epi64(sums, 3));
        }
    }
    if constexpr (plain) *newlines += count;
    return i;
}
#endif

template <bool plain>
IsoEvenRun pick_iso_even() {
#ifdef TAPE_SWAR_AVX2
    if (swar::has_avx2()) return iso_even_avx2<plain>;
#endif
    return iso_even_sse2<plain>;
}

constexpr std::size_t scalar_step = 64;  // bytes taken one by one after a block the vector loop left

std::size_t iso_even_run(const char* in, std::size_t n, Frame* out) {
    static const IsoEvenRun vector_run = pick_iso_even<false>();
    std::size_t i = 0;
    while (i < n) {
        i += vector_run(in + i, n - i, out + i, nullptr);
        for (std::size_t end = i + scalar_step < n ? i + scalar_step : n; i < end; ++i) {
            auto c = static_cast<unsigned char>(in[i]);
            if (c >= 0x80) return i;
            out[i] = static_cast<Frame>(c | ((hole_count(c) & 1) << 7));
        }
    }
    return n;
}

// Encodes the plain start of text (see above) into out: CR LF as LF, a lone CR as CR. Stops at the
// first NUL, DEL or non-ASCII byte, which the general path then reports or converts. Returns the bytes
// of text taken; *frames = frames stored (fewer by the CRs dropped), *newlines = LFs among the bytes.
std::size_t iso_even_plain(std::string_view text, Frame* out, std::size_t* frames, std::size_t* newlines) {
    static const IsoEvenRun vector_run = pick_iso_even<true>();
    const char* in = text.data();
    std::size_t n = text.size(), i = 0, w = 0;
    *newlines = 0;
    while (i < n) {
        std::size_t got = vector_run(in + i, n - i, out + w, newlines);
        i += got;
        w += got;
        for (std::size_t end = i + scalar_step < n ? i + scalar_step : n; i < end; ++i) {
            auto c = static_cast<unsigned char>(in[i]);
            if (c == '\r' && i + 1 < n && in[i + 1] == '\n') continue;
            if (c == 0x00 || c >= 0x7F) {
                *frames = w;
                return i;
            }
            *newlines += c == '\n';
            out[w++] = static_cast<Frame>(c | ((hole_count(c) & 1) << 7));
        }
    }
    *frames = w;
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

std::string shown_char(std::string_view text, std::size_t offset) {
    std::string ch = std::string(utf8::char_at(text, offset));
    return static_cast<unsigned char>(ch[0]) < 0x20 ? char_label(ch[0]) : "'" + visible(ch) + "'";
}

// The characters after the first one (chars[stop]) the code cannot carry either, up to a limit, each
// with its line and column: all of them said at once, not one a run. origin maps a character of chars
// to its byte in text (empty: the same).
std::string others_uncarried(const FrameCode& code, std::string_view chars, std::size_t stop,
                             std::span<const std::size_t> origin, std::string_view text, Position base) {
    constexpr std::size_t named = 10;
    std::vector<Frame> scratch(chars.size());
    std::string list;
    std::size_t found = 0;
    for (std::size_t i = stop + 1; i < chars.size(); ++i) {
        i += encode_run(code, chars.substr(i), scratch.data());
        if (i >= chars.size()) break;
        std::size_t offset = origin.empty() ? i : origin[i];
        if (utf8::is_continuation(text[offset]) || ++found > named) continue;  // a character once, not a byte
        Position p = text_position(text, offset, base);
        list += (found > 1 ? ", " : "") + shown_char(text, offset) + " (line " + std::to_string(*p.line) + ", column " +
                std::to_string(*p.column) + ")";
    }
    if (found == 0) return "";
    return "; nor can " + list + (found > named ? " and " + std::to_string(found - named) + " more" : "");
}

[[noreturn]] void cannot_carry(std::string_view text, std::size_t offset, Position base, Code code, Charset charset,
                               const std::string& others = "") {
    Position where = text_position(text, offset, base);
    std::string ch = std::string(utf8::char_at(text, offset));
    auto first = static_cast<unsigned char>(ch[0]);
    std::string why =
        shown_char(text, offset) + " cannot be punched in " + (code == Code::iso ? "ISO" : "EIA") + " code" + others;
    if (first == 0x00) why = "a NUL byte in the text: on tape it would be blank tape, so it cannot be punched";
    if (first == 0x7F) why = "a DEL in the text: on tape it is a rubout that readers skip, so it cannot be punched";
    Hint hint;
    if (first >= 0x80) {
        auto cp = utf8::decode(ch);
        if (charset == Charset::ascii && cp && koi7_position(*cp)) {
            why += "; Cyrillic needs the КОИ-7 character set";
            hint = Hint{Hint::Action::use_charset, "koi7"};
        } else if (cp && (*cp == U'Ё' || *cp == U'ё'))
            why += " (КОИ-7 has no Ё: write Е)";
        else if (cp && *cp == U'Ъ')
            why += " (КОИ-7 has no capital Ъ: write ъ)";
    }
    throw Error(Errc::bad_text, where, why, hint);
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
    : options_(options),
      code_(FrameCode::make(options.code, options.parity, options.eia_table)),
      plain_iso_(options.code == Code::iso && options.parity == Parity::even && options.charset == Charset::ascii &&
                 !options.crlf) {
    if (options.leader > max_blank_frames || options.trailer > max_blank_frames)
        throw Error(Errc::usage,
                    "a leader or trailer is at most " + std::to_string(max_blank_frames) + " blank frames");
    if (is_five_track(options.code) && options.parity != Parity::even)
        throw Error(Errc::usage, "5-track codes carry no parity");
    if (is_five_track(options.code) && options.charset != Charset::ascii)
        throw Error(Errc::usage, "КОИ-7 is a character set of the 7-bit code; МТК-2 has its own Russian register");
    if (is_telecode(options.code) && (options.parity != Parity::even || options.charset != Charset::ascii))
        throw Error(Errc::usage, "the Elliott telecodes have a parity and a character set of their own");
    if (!options.label.empty()) {
        label_ = label_frames(options.label, code_);
        std::size_t need = label_.size() + 2 * label_blank_around;
        if (options.leader < need)
            throw Error(Errc::usage, "the label takes " + std::to_string(label_.size()) +
                                         " frames: a leader of at least " + std::to_string(need) + " frames holds it");
    }
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
        std::size_t at = out.size();
        out.insert(out.end(), options_.leader, blank_frame);
        if (!label_.empty())
            std::copy(label_.begin(), label_.end(), out.begin() + static_cast<std::ptrdiff_t>(at + label_blank_around));
        leader_done_ = true;
    }
    if (code_.five_track_table()) {
        encode_five_track(text, out);  // once a piece: ISO and EIA pay nothing
        return;
    }
    if (code_.telecode_table()) {
        encode_telecode(text, out);
        return;
    }
    if (plain_iso_) {
        // The plain start in one pass; the rest (an error, or text from the first NUL, DEL or non-ASCII
        // byte on) goes the general way below, from the position reached.
        std::size_t at = out.size(), frames = 0, newlines = 0;
        out.resize(at + text.size());
        std::size_t took = iso_even_plain(text, out.data() + at, &frames, &newlines);
        out.resize(at + frames);
        position_ = advance(position_, text.substr(0, took), newlines);
        text.remove_prefix(took);
        if (text.empty()) return;
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
        cannot_carry(
            text, plain ? stop : origin_[stop], position_, options_.code, options_.charset,
            others_uncarried(code_, chars, stop, plain ? std::span<const std::size_t>() : origin_, text, position_));
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
    // A byte-order mark at the very start is an editor's, not the program's: skipped (the caller says so).
    if (at_start_ && !text.empty()) {
        if (text.starts_with(utf8_bom)) {
            text.remove_prefix(utf8_bom.size());
            skipped_bom_ = true;
            at_start_ = false;
        } else if (text.size() >= utf8_bom.size() || !utf8_bom.starts_with(text)) {
            at_start_ = false;  // else the start of one, cut by the chunk's end: held below, looked at again
        }
    }
    // DOS end-of-file marks wait: at the end of the text they are not punched; text after them makes
    // them SUB characters. What stands before them is whole (nothing can follow it but marks).
    auto bytes = std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    std::size_t marks_at = dos_end_of_file_at(bytes);
    if (held_marks_ && marks_at > 0) {
        encode_piece(std::string(held_marks_, static_cast<char>(dos_end_of_file)), out);
        held_marks_ = 0;
    }
    if (marks_at < text.size()) {
        encode_piece(text.substr(0, marks_at), out);
        held_marks_ += text.size() - marks_at;
        return;
    }
    std::size_t keep = unfinished_tail(text);
    encode_piece(text.substr(0, text.size() - keep), out);
    held_ = std::string(text.substr(text.size() - keep));
}

void Encoder::finish(std::vector<Frame>& out) {
    if (held_marks_) skipped_marks_ = position_;
    held_marks_ = 0;
    std::string rest = std::move(held_);
    held_.clear();
    encode_piece(rest, out);  // a lone CR at the very end is the CR character; a cut UTF-8 character an error
    if (cyrillic_) {
        static constexpr char shift_in = '\x0F';
        std::size_t at = out.size();
        out.resize(at + 1);
        encode_run(code_, std::string_view(&shift_in, 1), out.data() + at);
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
