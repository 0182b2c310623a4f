// Decoder: 8-track frames -> ISO 7-bit characters (ISO with a parity track, or EIA by table).
// Blank tape and DEL are skipped; bad frames are reported, never repaired.
#include "tape/decode.hpp"

#include <algorithm>
#include <cstring>

#include "swar.hpp"

namespace tape {
namespace {

// ISO with even parity is what nearly every NC tape is. The vector loops below take whole blocks
// while the tape is clean (every frame a character: even parity, no blank, no DEL), stripping track 8;
// they stop before the first block that is not, and iso_even_run() goes through that one a frame at a
// time. Blank and DEL are caught by the byte minimum and maximum of the block (0x00, 0xFF), which
// costs two instructions a vector instead of two compares and two ORs.
// The LFs among the characters are counted on the way (a compare and a subtract a vector), for the
// lines of the messages and the line ends decode reports: no second pass over the text.
using CleanRun = std::size_t (*)(const Frame* in, std::size_t n, char* out, std::uint64_t* newlines);

std::size_t iso_even_clean_sse2(const Frame* in, std::size_t n, char* out, std::uint64_t* newlines) {
    constexpr std::size_t step = 64;
    std::size_t i = 0;
    for (bool go = true; go && i + step <= n;) {
        swar::bytes16 lines{};  // per byte: LFs in these steps, at most 4 a step: 63 steps fit a byte
        for (int steps = 0; steps < 63 && i + step <= n; ++steps, i += step) {
            swar::bytes16 v[4], odd{}, low = ~swar::bytes16{}, high{};
            for (int k = 0; k < 4; ++k) {
                v[k] = swar::load16(in + i + 16 * k);
                odd |= swar::odd_parity16(v[k]);
                low = v[k] < low ? v[k] : low;
                high = v[k] > high ? v[k] : high;
            }
            if (swar::any16(odd | (low == 0) | (high == 0xFF))) {
                go = false;
                break;
            }
            for (int k = 0; k < 4; ++k) {
                swar::bytes16 c = v[k] & 0x7F;
                swar::store16(out + i + 16 * k, c);
                lines -= reinterpret_cast<swar::bytes16>(c == '\n');
            }
        }
        *newlines += swar::byte_sum(lines);
    }
    return i;
}

#ifdef TAPE_SWAR_AVX2
__attribute__((target("avx2"))) std::size_t iso_even_clean_avx2(const Frame* in, std::size_t n, char* out,
                                                                std::uint64_t* newlines) {
    constexpr std::size_t step = 128;
    const __m256i parity = _mm256_load_si256(reinterpret_cast<const __m256i*>(swar::nibble_parity<1>.table));
    const __m256i seven = _mm256_set1_epi8(0x7F), nibble = _mm256_set1_epi8(0x0F), lf = _mm256_set1_epi8('\n');
    const __m256i zero = _mm256_setzero_si256(), ones = _mm256_set1_epi8(-1);
    std::size_t i = 0;
    for (bool go = true; go && i + step <= n;) {
        __m256i lines = zero;  // per byte: LFs in these steps, at most 4 a step: 63 steps fit a byte
        for (int steps = 0; steps < 63 && i + step <= n; ++steps, i += step) {
            __m256i m[4], odd = zero, low = ones, high = zero;
            for (int k = 0; k < 4; ++k) {
                __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(in + i + 32 * k));
                m[k] = _mm256_and_si256(v, seven);  // also the low-nibble index: vpshufb wants bit 7 clear
                __m256i hi = _mm256_and_si256(_mm256_srli_epi16(v, 4), nibble);
                odd = _mm256_or_si256(
                    odd, _mm256_xor_si256(_mm256_shuffle_epi8(parity, m[k]), _mm256_shuffle_epi8(parity, hi)));
                low = _mm256_min_epu8(low, v);
                high = _mm256_max_epu8(high, v);
            }
            __m256i bad =
                _mm256_or_si256(odd, _mm256_or_si256(_mm256_cmpeq_epi8(low, zero), _mm256_cmpeq_epi8(high, ones)));
            if (!_mm256_testz_si256(bad, bad)) {
                go = false;
                break;
            }
            for (int k = 0; k < 4; ++k) {
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + i + 32 * k), m[k]);
                lines = _mm256_sub_epi8(lines, _mm256_cmpeq_epi8(m[k], lf));
            }
        }
        __m256i sums = _mm256_sad_epu8(lines, zero);  // four 64-bit sums
        *newlines += static_cast<std::uint64_t>(_mm256_extract_epi64(sums, 0) + _mm256_extract_epi64(sums, 1) +
                                                _mm256_extract_epi64(sums, 2) + _mm256_extract_epi64(sums, 3));
    }
    return i;
}
#endif

CleanRun pick_iso_even_clean() {
#ifdef TAPE_SWAR_AVX2
    if (swar::has_avx2()) return iso_even_clean_avx2;
#endif
    return iso_even_clean_sse2;
}

std::size_t iso_even_run(const Frame* in, std::size_t n, char* out, std::size_t* written, std::uint64_t* newlines) {
    static const CleanRun clean_run = pick_iso_even_clean();
    constexpr std::size_t step = 64;  // frames taken one by one after a block that is not clean
    std::size_t i = 0, w = 0;
    while (i < n) {
        std::size_t clean = clean_run(in + i, n - i, out + w, newlines);
        i += clean;
        w += clean;
        std::size_t end = i + step < n ? i + step : n;
        for (; i < end; ++i) {
            Frame f = in[i];
            if (f == 0x00 || f == 0xFF) continue;
            if (hole_count(f) & 1) {
                *written = w;
                return i;
            }
            out[w] = static_cast<char>(f & 0x7F);
            *newlines += out[w++] == '\n';
        }
    }
    *written = w;
    return n;
}

std::size_t table_run(const FrameCode& code, const Frame* in, std::size_t n, char* out, std::size_t* written,
                      std::uint64_t* newlines) {
    std::size_t w = 0, i = 0;
    for (; i < n; ++i) {
        FrameKind k = code.kind(in[i]);
        if (k == FrameKind::character) {
            out[w] = code.character(in[i]);
            *newlines += out[w++] == '\n';
        } else if (k != FrameKind::blank && k != FrameKind::rubout)
            break;
    }
    *written = w;
    return i;
}

// Stage two, only when needed: КОИ-7 shifts to UTF-8 and bad-frame sentinels to the marker.
constexpr char bad_sentinel = '\x80';

// The blank runs of a chunk are found before its bad frames: both go in tape order, and none past the
// bad frame decoding stopped at.
void in_tape_order(std::vector<Diagnostic>& d, std::size_t from, bool stopped) {
    auto frame = [](const Diagnostic& x) { return x.where.frame.value_or(0); };
    std::stable_sort(d.begin() + static_cast<std::ptrdiff_t>(from), d.end(),
                     [&](const Diagnostic& a, const Diagnostic& b) { return frame(a) < frame(b); });
    if (!stopped) return;
    auto last_bad = std::find_if(d.rbegin(), d.rend(), [](const Diagnostic& x) { return is_bad_frame(x.code); });
    if (last_bad != d.rend())
        std::erase_if(d,
                      [&](const Diagnostic& x) { return x.code == Errc::blank_frame && frame(x) > frame(*last_bad); });
}

}  // namespace

Diagnostic bad_frame_diagnostic(const FrameCode& code, Frame f, std::uint64_t index, std::uint64_t line) {
    bool parity = code.kind(f) == FrameKind::parity_error;
    std::string what =
        parity ? "parity error" : (code.code() == Code::eia ? "not an EIA character" : "not a character");
    if (code.five_track_table()) what = "not a 5-track frame (tracks 6-8 punched)";
    // The line, not the block: which lines are blocks only the loader knows.
    Position where{.frame = index + 1};
    if (line) where.line = line;
    return Diagnostic{parity ? Errc::parity : Errc::not_in_code, where, what + ", holes " + holes_picture(f)};
}

namespace {

// decode_run, counting the LFs stored.
std::size_t decode_run_counting(const FrameCode& code, std::span<const Frame> frames, char* out, std::size_t* written,
                                std::uint64_t* newlines) {
    if (code.code() == Code::iso && code.parity() == Parity::even)
        return iso_even_run(frames.data(), frames.size(), out, written, newlines);
    return table_run(code, frames.data(), frames.size(), out, written, newlines);
}

}  // namespace

std::size_t decode_run(const FrameCode& code, std::span<const Frame> frames, char* out, std::size_t* written) {
    std::uint64_t newlines = 0;
    return decode_run_counting(code, frames, out, written, &newlines);
}

Decoder::Decoder(const DecodeOptions& options)
    : options_(options), code_(FrameCode::make(options.code, options.parity, options.eia_table)) {
    for (int f = 0; f < 256; ++f) {
        rubout_[f] = code_.kind(static_cast<Frame>(f)) == FrameKind::rubout;
        if (state_after(static_cast<Frame>(f)) == Before::end_of_block)
            end_of_block_frame_ = end_of_block_frame_ == -1 ? f : -2;  // -2: several, looked for one by one
    }
    if (is_five_track(options.code) && options.parity != Parity::even)
        throw Error(Errc::usage, "5-track codes carry no parity");
    if (is_five_track(options.code) && options.charset != Charset::ascii)
        throw Error(Errc::usage, "КОИ-7 is a character set of the 7-bit code; МТК-2 has its own Russian register");
    if (is_telecode(options.code) && (options.parity != Parity::even || options.charset != Charset::ascii))
        throw Error(Errc::usage, "the Elliott telecodes have a parity and a character set of their own");
    if (options.unshift_on_space && options.code != Code::ita2)
        throw Error(Errc::usage, "unshift-on-space is a habit of ITA2 teleprinters; for other codes it is not known");
}

std::map<Errc, std::uint64_t> Decoder::unlisted() const {
    std::map<Errc, std::uint64_t> m;
    std::uint64_t limit = options_.max_diagnostics;
    if (limit == 0) return m;
    if (parity_seen_ > limit) m[Errc::parity] = parity_seen_ - limit;
    if (other_seen_ > limit) m[Errc::not_in_code] = other_seen_ - limit;
    if (blank_runs_seen_ > limit) m[Errc::blank_frame] = blank_runs_seen_ - limit;
    return m;
}

// A tape of noise has a bad frame in every other frame: past the limit they are only counted, so that
// messages cannot fill memory.
void Decoder::note_bad(Frame f, std::uint64_t index, std::uint64_t line, DecodeResult& out) {
    std::uint64_t& seen = code_.kind(f) == FrameKind::parity_error ? parity_seen_ : other_seen_;
    ++seen;
    last_bad_ = index;
    if (options_.max_diagnostics == 0 || seen <= options_.max_diagnostics)
        out.diagnostics.push_back(bad_frame_diagnostic(code_, f, index, line));
}

// Only КОИ-7 text, a telecode's text (its characters that are not ASCII) and text with a bad frame marked
// need this second pass; plain text is final as decoded.
void Decoder::finish_text(DecodeResult& out, std::size_t from, std::size_t positions_from) {
    std::string_view added(out.text.data() + from, out.text.size() - from);
    bool positions = options_.positions;
    std::string text;
    std::vector<std::uint64_t> pos;
    text.reserve(added.size() + added.size() / 8);
    for (std::size_t i = 0; i < added.size(); ++i) {
        auto c = static_cast<unsigned char>(added[i]);
        std::string_view piece(&added[i], 1);
        if (c == static_cast<unsigned char>(bad_sentinel)) {
            piece = bad_frame_marker;
        } else if (options_.charset == Charset::koi7 && c == 0x0E) {
            cyrillic_ = true;
            continue;
        } else if (options_.charset == Charset::koi7 && c == 0x0F) {
            cyrillic_ = false;
            continue;
        } else if (cyrillic_ && !koi7_cyrillic(c).empty()) {
            piece = koi7_cyrillic(c);
        } else if (auto wide = code_.wide_character(c); !wide.empty()) {
            piece = wide;
        }
        text += piece;
        if (positions) pos.insert(pos.end(), piece.size(), out.frame_of[positions_from + i]);
    }
    out.text.resize(from);
    out.text += text;
    if (positions) {
        out.frame_of.resize(positions_from);
        out.frame_of.insert(out.frame_of.end(), pos.begin(), pos.end());
    }
}

// Blank runs are found with memchr; the frame before a run and the one after it decide whether the run
// stands inside a block.
void Decoder::note_blanks(std::span<const Frame> frames, std::uint64_t base, DecodeResult& out) {
    std::size_t i = 0, n = frames.size();
    while (i < n) {
        const void* z = std::memchr(frames.data() + i, 0, n - i);
        std::size_t at = z ? static_cast<std::size_t>(static_cast<const Frame*>(z) - frames.data()) : n;
        punched_stretch(frames.subspan(i, at - i), out);
        if (at == n) break;
        std::size_t end = at;
        while (end < n && frames[end] == 0) ++end;
        if (before_blanks_ != Before::nothing && !blank_frames_) blank_from_ = base + at;
        if (before_blanks_ != Before::nothing) blank_frames_ += end - at;
        i = end;
    }
}

// Punched frames between blank runs. Of these only a few decide anything: the first (after blank tape),
// each one after an end of block (the block starts that make the tape's habit), and the last (before
// the next blank run). Once the habit is no blank after an end of block, a block start without blanks
// changes nothing, so the ends of block are not even looked for: a clean tape's stretch costs two steps.
void Decoder::punched_stretch(std::span<const Frame> stretch, DecodeResult& out) {
    auto skip_rubouts = [&](std::size_t k) {
        while (k < stretch.size() && rubout_[stretch[k]]) ++k;
        return k;
    };
    std::size_t first = skip_rubouts(0);
    if (first == stretch.size()) return;  // DEL alone: the tape is as it was before them
    after_blanks(stretch[first], code_.kind(stretch[first]), out);
    std::size_t last = stretch.size() - 1;
    while (rubout_[stretch[last]]) --last;
    for (std::size_t p = next_end_of_block(stretch, first); p < last && !habit_is_no_blank();
         p = next_end_of_block(stretch, p)) {
        p = skip_rubouts(p + 1);  // at most last: a punched frame follows
        before_blanks_ = Before::end_of_block;
        after_blanks(stretch[p], code_.kind(stretch[p]), out);
    }
    before_blanks_ = state_after(stretch[last]);
}

// The first end of block in stretch at or after from, or stretch.size().
std::size_t Decoder::next_end_of_block(std::span<const Frame> stretch, std::size_t from) const {
    if (from >= stretch.size()) return stretch.size();
    if (end_of_block_frame_ >= 0) {
        const void* lf = std::memchr(stretch.data() + from, end_of_block_frame_, stretch.size() - from);
        return lf ? static_cast<std::size_t>(static_cast<const Frame*>(lf) - stretch.data()) : stretch.size();
    }
    while (from < stretch.size() && state_after(stretch[from]) != Before::end_of_block) ++from;
    return from;
}

Decoder::Before Decoder::state_after(Frame f) const {
    if (code_.kind(f) != FrameKind::character) return Before::nothing;
    char c = code_.character(f);
    return static_cast<unsigned char>(c) >= 0x20 ? Before::printable
           : c == '\n'                           ? Before::end_of_block
                                                 : Before::nothing;
}

// The habit is no blank frame at all after an end of block, and no longer run waits to be said.
bool Decoder::habit_is_no_blank() const {
    return !suspect_.frames && habit_seen_ >= habit_.size() &&
           std::all_of(habit_.begin(), habit_.end(), [](std::uint8_t run) { return run == 0; });
}

// The frame after blank tape (or after none): inside a block any blank run is said; after an end of
// block only one longer than the tape's habit there (Elliott tapes put one blank after each LF, so five
// mean four characters lost), and only once the next two blocks keep the habit: a tape whose habit
// changes (a section punched by another hand) is not damaged.
void Decoder::after_blanks(Frame f, FrameKind kind, DecodeResult& out) {
    char c = kind == FrameKind::character ? code_.character(f) : '\0';
    bool printable = kind == FrameKind::character && static_cast<unsigned char>(c) >= 0x20;
    if (before_blanks_ == Before::printable && blank_frames_)
        blank_run(blank_from_, blank_frames_, "inside a block", out);
    else if (before_blanks_ == Before::end_of_block && printable && c != '%')
        block_start_blanks(out);
    blank_frames_ = 0;
    before_blanks_ = state_after(f);
}

// The run of blank frames that 15 of the last 16 ends of block were followed by, if there is one: such
// a value stands in the first or the second place of the 16.
std::optional<std::uint8_t> Decoder::habit() const {
    if (habit_seen_ < habit_.size()) return std::nullopt;
    for (std::uint8_t candidate : {habit_[0], habit_[1]})
        if (std::count(habit_.begin(), habit_.end(), candidate) + 1 >= static_cast<std::ptrdiff_t>(habit_.size()))
            return candidate;
    return std::nullopt;
}

void Decoder::block_start_blanks(DecodeResult& out) {
    std::uint64_t run = std::min<std::uint64_t>(blank_frames_, 255);
    if (suspect_.frames) {  // a run longer than the habit: said once two more blocks keep the habit
        if (run != suspect_.usual) {
            suspect_ = {};
        } else if (++suspect_.kept == 2) {
            blank_run(suspect_.from, suspect_.frames,
                      "at the start of a block, where this tape has " + std::to_string(suspect_.usual) +
                          " after each end of block",
                      out);
            suspect_ = {};
        }
    }
    if (auto usual = habit(); usual && run > *usual && !suspect_.frames)
        suspect_ = {blank_from_ + *usual, run - *usual, *usual, 0};
    habit_[habit_seen_++ % habit_.size()] = static_cast<std::uint8_t>(run);
}

// A run of blank frames that should hold characters: said once, at its first frame.
void Decoder::blank_run(std::uint64_t from, std::uint64_t n, const std::string& where, DecodeResult& out) {
    std::uint64_t first = from + 1;
    if (++blank_runs_seen_ > options_.max_diagnostics && options_.max_diagnostics) return;
    std::string frames = n == 1 ? "blank frame "
                                : std::to_string(n) + " blank frames (frames " + std::to_string(first) + "-" +
                                      std::to_string(first + n - 1) + ") ";
    std::string message = frames + where + ": a character whose holes were all lost reads as blank tape" +
                          (code_.code() == Code::eia ? " (EIA's 0 1 2 4 8 - and space have a single hole)" : "");
    out.diagnostics.push_back(Diagnostic{
        .code = Errc::blank_frame, .where = {.frame = first}, .message = message, .severity = Severity::warning});
}

bool Decoder::feed(std::span<const Frame> frames, DecodeResult& out) {
    if (stopped_) return false;
    note_trailer(frames);
    if (code_.five_track_table()) {  // once a chunk: ISO and EIA pay nothing
        std::size_t from = out.text.size();
        bool going = feed_five_track(frames, out);
        line_ends_.take(std::string_view(out.text).substr(from));
        return going;
    }
    ChunkStart at{out.text.size(), out.frame_of.size(), out.diagnostics.size()};
    const std::uint64_t lines_before = lines_;
    bool marked = false;  // a bad_sentinel stored: known here, so no search of the text for one
    out.text.resize(at.text + frames.size());
    std::size_t w = options_.positions ? decode_with_positions(frames, out, marked) : decode_runs(frames, out, marked);
    out.text.resize(w);
    line_ends_.take(std::string_view(out.text).substr(at.text), lines_ - lines_before);
    // Every frame a character: no blank tape in the chunk to look for.
    if (!marked && w - at.text == frames.size())
        punched_stretch(frames, out);
    else
        note_blanks(frames, next_index_, out);
    next_index_ += frames.size();
    settle_chunk(out, at, marked);
    return !stopped_;
}

// A frame at a time, each character's frame kept; the LFs counted on the way, for a bad frame's line.
// Returns the end of the text stored (out.text is sized for every frame).
std::size_t Decoder::decode_with_positions(std::span<const Frame> frames, DecodeResult& out, bool& marked) {
    std::size_t w = out.text.size() - frames.size(), p = out.frame_of.size();
    out.frame_of.resize(p + frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
        Frame f = frames[i];
        FrameKind k = code_.kind(f);
        if (k == FrameKind::blank || k == FrameKind::rubout) continue;
        if (k != FrameKind::character) {
            note_bad(f, next_index_ + i, lines_ + 1, out);
            if (!options_.keep_going) {
                stopped_ = true;
                break;
            }
        }
        marked |= k != FrameKind::character;
        char c = k == FrameKind::character ? code_.character(f) : bad_sentinel;
        lines_ += c == '\n';
        out.text[w++] = c;
        out.frame_of[p++] = next_index_ + i;
    }
    out.frame_of.resize(p);
    return w;
}

// Clean runs through the vector loops, which count the LFs they store; a bad frame between them.
std::size_t Decoder::decode_runs(std::span<const Frame> frames, DecodeResult& out, bool& marked) {
    std::size_t w = out.text.size() - frames.size(), i = 0;
    while (i < frames.size()) {
        std::size_t got = 0;
        std::size_t stop = i + decode_run_counting(code_, frames.subspan(i), out.text.data() + w, &got, &lines_);
        w += got;
        if (stop == frames.size()) break;
        note_bad(frames[stop], next_index_ + stop, lines_ + 1, out);
        if (!options_.keep_going) {
            stopped_ = true;
            break;
        }
        out.text[w++] = bad_sentinel;
        marked = true;
        i = stop + 1;
    }
    return w;
}

// A chunk decoded: what it leaves for the tape's end, its findings in tape order, its text finished.
void Decoder::settle_chunk(DecodeResult& out, ChunkStart at, bool marked) {
    if (stopped_) out.complete = false;
    // As decoded: a telecode's character is still its byte.
    if (out.text.size() > at.text) last_char_ = out.text.back();
    if (out.diagnostics.size() > at.diagnostics) in_tape_order(out.diagnostics, at.diagnostics, stopped_);
    if (marked || options_.charset == Charset::koi7 || code_.telecode_table()) finish_text(out, at.text, at.positions);
}

DecodeResult decode(std::span<const Frame> frames, const DecodeOptions& options) {
    Decoder decoder(options);
    DecodeResult r;
    decoder.feed(frames, r);
    decoder.finish(r);
    r.unlisted = decoder.unlisted();
    return r;
}

}  // namespace tape
