// Decoder: 8-track frames -> ISO 7-bit characters (ISO with a parity track, or EIA by table).
// Blank tape and DEL are skipped; bad frames are reported, never repaired.
#include <cstring>

#include "swar.hpp"
#include "tape/decode.hpp"

namespace tape {
namespace {

// ISO with even parity is what nearly every NC tape is: check and strip 64 frames a step while the
// tape is clean (no parity error, blank or DEL), 8 a step through the rest.
std::size_t iso_even_run(const Frame* in, std::size_t n, char* out, std::size_t* written) {
    constexpr std::size_t step = 64;
    std::size_t i = 0, w = 0;
    while (i < n) {
        if (i + step <= n) {
            swar::bytes16 bad{}, v[4];
            for (int k = 0; k < 4; ++k) {
                v[k] = swar::load16(in + i + 16 * k);
                bad |= swar::odd_parity16(v[k]) | (v[k] == 0) | (v[k] == 0xFF);
            }
            if (!swar::any16(bad)) {
                for (int k = 0; k < 4; ++k) swar::store16(out + w + 16 * k, v[k] & 0x7F);
                i += step;
                w += step;
                continue;
            }
        }
        std::size_t end = i + step < n ? i + step : n;
        for (; i < end; ++i) {
            Frame f = in[i];
            if (f == 0x00 || f == 0xFF) continue;
            if (hole_count(f) & 1) {
                *written = w;
                return i;
            }
            out[w++] = static_cast<char>(f & 0x7F);
        }
    }
    *written = w;
    return n;
}

std::size_t table_run(const FrameCode& code, const Frame* in, std::size_t n, char* out, std::size_t* written) {
    std::size_t w = 0, i = 0;
    for (; i < n; ++i) {
        FrameKind k = code.kind(in[i]);
        if (k == FrameKind::character) out[w++] = code.character(in[i]);
        else if (k != FrameKind::blank && k != FrameKind::rubout) break;
    }
    *written = w;
    return i;
}

// Stage two, only when needed: КОИ-7 shifts to UTF-8 and bad-frame sentinels to the marker.
constexpr char bad_sentinel = '\x80';

void finish_text(DecodeResult& r, Charset charset) {
    std::string out;
    std::vector<std::uint64_t> pos;
    out.reserve(r.text.size() + r.text.size() / 8);
    bool positions = !r.frame_of.empty();
    bool cyrillic = false;
    for (std::size_t i = 0; i < r.text.size(); ++i) {
        auto c = static_cast<unsigned char>(r.text[i]);
        std::string_view piece(&r.text[i], 1);
        if (c == static_cast<unsigned char>(bad_sentinel)) piece = bad_frame_marker;
        else if (charset == Charset::koi7 && c == 0x0E) { cyrillic = true; continue; }
        else if (charset == Charset::koi7 && c == 0x0F) { cyrillic = false; continue; }
        else if (cyrillic && !koi7_cyrillic(c).empty()) piece = koi7_cyrillic(c);
        out += piece;
        if (positions) pos.insert(pos.end(), piece.size(), r.frame_of[i]);
    }
    r.text = std::move(out);
    if (positions) r.frame_of = std::move(pos);
}

}  // namespace

Diagnostic bad_frame_diagnostic(const FrameCode& code, Frame f, std::uint64_t index) {
    bool parity = code.kind(f) == FrameKind::parity_error;
    std::string what = parity ? "parity error" : (code.code() == Code::eia ? "not an EIA character" : "not a character");
    return Diagnostic{parity ? Errc::parity : Errc::not_in_code, Position{.frame = index + 1},
                      what + ", holes " + holes_picture(f)};
}

std::size_t decode_run(const FrameCode& code, std::span<const Frame> frames, char* out, std::size_t* written) {
    if (code.code() == Code::iso && code.parity() == Parity::even)
        return iso_even_run(frames.data(), frames.size(), out, written);
    return table_run(code, frames.data(), frames.size(), out, written);
}

DecodeResult decode(std::span<const Frame> frames, const DecodeOptions& options) {
    FrameCode code = FrameCode::make(options.code, options.parity, options.eia_table);
    DecodeResult r;
    r.text.resize(frames.size());
    std::size_t w = 0;
    if (options.positions) {
        r.frame_of.resize(frames.size());
        for (std::size_t i = 0; i < frames.size(); ++i) {
            Frame f = frames[i];
            FrameKind k = code.kind(f);
            if (k == FrameKind::blank || k == FrameKind::rubout) continue;
            if (k != FrameKind::character) {
                r.diagnostics.push_back(bad_frame_diagnostic(code, f, i));
                if (!options.keep_going) { r.complete = false; break; }
            }
            r.text[w] = k == FrameKind::character ? code.character(f) : bad_sentinel;
            r.frame_of[w++] = i;
        }
        r.frame_of.resize(w);
    } else {
        std::size_t i = 0;
        while (i < frames.size()) {
            std::size_t got = 0;
            std::size_t stop = i + decode_run(code, frames.subspan(i), r.text.data() + w, &got);
            w += got;
            if (stop == frames.size()) break;
            r.diagnostics.push_back(bad_frame_diagnostic(code, frames[stop], stop));
            if (!options.keep_going) { r.complete = false; break; }
            r.text[w++] = bad_sentinel;
            i = stop + 1;
        }
    }
    r.text.resize(w);
    if (options.charset == Charset::koi7 || !r.diagnostics.empty()) finish_text(r, options.charset);
    return r;
}

}  // namespace tape
