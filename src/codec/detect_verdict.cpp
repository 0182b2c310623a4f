// The verdict on a tape from its evidence, in words, with advice only where it is known to work.
#include <algorithm>

#include "tape/detect.hpp"
#include "tape/telecode.hpp"

namespace tape {
namespace {

// A reading fits when at most one frame in ten fails it and there are not many stray controls (more than
// one in fifty, and ten at least): a damaged tape still fits, decoding then names each bad frame, but a
// tape of another code read as ISO is full of controls no text holds. It is clean when decoding that way
// finds no bad frame, or one in a thousand, and almost no stray controls.
constexpr std::uint64_t many_controls = 10;
bool too_many_controls(const ReadingFit& f, std::uint64_t frames) {
    return f.controls >= many_controls && f.controls * 50 > frames;
}
bool fits(const ReadingFit& f, std::uint64_t frames) {
    return (f.bad_frames + f.controls) * 10 <= frames && !too_many_controls(f, frames);
}
bool clean(const ReadingFit& f, std::uint64_t frames) {
    return f.bad_frames * 1000 <= frames && f.controls * 20 <= frames;
}
std::uint64_t score(const ReadingFit& f) { return f.bad_frames + f.controls; }

// A run this long of track 8 alone is leader (DEC binary loaders, mark-parity ASCII), not EIA end of blocks.
constexpr std::uint64_t leader_run = 8;

std::string n(std::uint64_t v) { return std::to_string(v); }
std::string frames_text(std::uint64_t v) { return n(v) + (v == 1 ? " frame" : " frames"); }

std::string whole_text(const TapeEvidence& e) {
    return e.whole_tape ? "" : " (in the first " + frames_text(e.frames) + ")";
}

std::string counts_text(const TapeEvidence& e) {
    std::string s = frames_text(e.frames) + ", " + n(e.punched) + " punched: " + n(e.parity.even) + " even, " +
                    n(e.parity.odd) + " odd, " + n(e.parity.mark) + " with track 8; end of block " + n(e.iso_lf) +
                    " LF (ISO), " + n(e.eia_eob) + " track 8 alone (EIA)";
    return s + whole_text(e);
}

Hint hint_for(Reading r) {
    if (r.code != Code::iso) return Hint{Hint::Action::use_code, code_name(r.code)};
    if (r.parity == Parity::even) return Hint{Hint::Action::use_code, "iso"};
    return Hint{Hint::Action::use_iso_parity, parity_name(r.parity)};
}

std::string parity_words(Parity p) {
    switch (p) {
        case Parity::mark:
            return "mark parity (track 8 punched on every frame)";
        case Parity::space:
            return "space parity (track 8 never punched)";
        case Parity::odd:
            return "odd parity on track 8";
        default:
            return std::string(parity_name(p)) + " parity";
    }
}

CodeDetection blank_verdict(CodeDetection d) {
    d.kind = TapeKind::blank;
    d.code = Code::iso;
    d.reason = "blank tape: none of the " + frames_text(d.evidence.frames) + " is punched; read as ISO";
    return d;
}

CodeDetection text_verdict(CodeDetection d) {
    const TapeEvidence& e = d.evidence;
    d.kind = TapeKind::text;
    d.reason = "this is a text program, not a tape image: " + n(e.frames) + " bytes of UTF-8 text in " + n(e.iso_lf) +
               " lines, with no blank leader and no parity on track 8";
    d.hint = Hint{Hint::Action::encode_text};
    return d;
}

CodeDetection five_track_verdict(CodeDetection d) {
    const TapeEvidence& e = d.evidence;
    d.kind = TapeKind::five_track;
    d.reason = "5-track tape: none of the " + n(e.punched) + " punched frames has a hole in tracks 6, 7 or 8; as ISO " +
               n(e.fits[0].bad_frames) + " of them fail even parity, as EIA " + n(e.fits[1].bad_frames) + " fail; " +
               counts_text(e);
    d.hint = Hint{Hint::Action::use_five_track_code};
    return d;
}

// The tape read as a character code that fits it.
CodeDetection reading_verdict(CodeDetection d, const ReadingFit& best, std::uint64_t frames) {
    const TapeEvidence& e = d.evidence;
    Reading r = best.reading;
    d.reading = r;
    d.clean = clean(best, frames);
    std::string damage = best.bad_frames ? ", " + n(best.bad_frames) + " bad frame(s)" : "";
    if (r.code == Code::eia) {
        d.kind = TapeKind::eia;
        d.code = Code::eia;
        d.reason = "EIA: odd parity on track 5 in " + n(e.parity.odd) + " of " + n(e.punched) + " punched frames" +
                   damage + ", end of block " + n(best.end_of_blocks) + " track 8 alone, " + n(e.iso_lf) + " LF (ISO)" +
                   whole_text(e);
    } else if (is_telecode(r.code)) {
        d.kind = TapeKind::telecode;
        d.code = r.code;
        // Decoding with auto takes this code: no advice to give it.
        d.reason = reading_name(r) + ", not ISO: " + n(e.punched - best.bad_frames) + " of " + n(e.punched) +
                   " punched frames are its characters, " + n(best.end_of_blocks) + " newlines; read as ISO " +
                   n(e.fits[0].controls) + " of them would be control characters no text holds" + whole_text(e);
    } else if (r.parity == Parity::even) {
        d.kind = TapeKind::iso;
        d.code = Code::iso;
        d.reason = "ISO: even parity on track 8 in " + n(e.parity.even) + " of " + n(e.punched) + " punched frames" +
                   damage + ", end of block " + n(best.end_of_blocks) + " LF, " + n(e.eia_eob) +
                   " track 8 alone (EIA)" + whole_text(e);
    } else {
        d.kind = TapeKind::ascii;
        d.reason = "neither ISO nor EIA: an ASCII tape with " + parity_words(r.parity) + ": " +
                   n(e.punched - e.parity.misfits(r.parity)) + " of " + n(e.punched) + " punched frames fit it, " +
                   n(best.end_of_blocks) + " line ends (LF)";
        if (!d.clean)
            d.reason += "; but read that way " + n(best.bad_frames) + " frame(s) fail and " + n(best.controls) +
                        " are control characters";
        d.reason += "; " + counts_text(e);
        if (d.clean) d.hint = hint_for(r);
    }
    return d;
}

// A binary loader format explains the tape: its checksums (or RIM's pairs) say so.
CodeDetection binary_verdict(CodeDetection d) {
    const TapeEvidence& e = d.evidence;
    d.kind = TapeKind::binary;
    d.reason = "binary tape, not a character code: " + e.binary->summary() + "; " + counts_text(e);
    return d;
}

// No character code fits: a binary tape, or a code the tool does not know.
CodeDetection no_code_verdict(CodeDetection d, const ReadingFit& best, std::uint64_t frames) {
    const TapeEvidence& e = d.evidence;
    std::string closest = "no character code fits; the closest, " + reading_name(best.reading) + ", fails " +
                          n(score(best)) + " of " + frames_text(frames);
    if (too_many_controls(best, frames) && best.bad_frames * 10 <= frames)
        closest = "not " + reading_name(best.reading) + ": too many control characters (" + n(best.controls) + " of " +
                  frames_text(frames) + " are controls no text holds, such as BEL or ESC)";
    if (score(best) * 2 > frames || e.longest_0x80_run >= leader_run) {
        d.kind = TapeKind::binary;
        d.reason = "binary tape, not a character code: " + closest;
        if (e.longest_0x80_run >= leader_run)
            d.reason += "; " + n(e.longest_0x80_run) +
                        " frames with track 8 alone in a row, the leader of DEC BIN and RIM loader tapes";
        d.reason += "; " + counts_text(e);
        return d;
    }
    d.kind = TapeKind::unknown;
    d.reason = "neither ISO nor EIA: " + closest + "; " + counts_text(e);
    auto ties = std::count_if(e.fits.begin(), e.fits.end(), [&](const auto& f) { return score(f) == score(best); });
    // Two equally close: neither is the one to take; one failing a quarter of the frames or more is noise.
    if (ties == 1 && score(best) * 4 < frames) d.closest = best.reading;
    return d;
}

}  // namespace

std::string_view tape_kind_name(TapeKind k) {
    switch (k) {
        case TapeKind::blank:
            return "blank";
        case TapeKind::iso:
            return "iso";
        case TapeKind::eia:
            return "eia";
        case TapeKind::ascii:
            return "ascii";
        case TapeKind::telecode:
            return "telecode";
        case TapeKind::five_track:
            return "5-track";
        case TapeKind::binary:
            return "binary";
        case TapeKind::text:
            return "text";
        case TapeKind::unknown:
            return "unknown";
    }
    return "unknown";
}

std::string reading_name(Reading r) {
    if (r.code == Code::eia) return "EIA";
    if (is_telecode(r.code)) return TelecodeTable::builtin(r.code).name();
    if (r.parity == Parity::even) return "ISO with even parity";
    return "ASCII with " + std::string(parity_name(r.parity)) + " parity";
}

CodeDetection Detector::result() const {
    CodeDetection d;
    d.evidence = evidence_;
    TapeEvidence& e = d.evidence;
    for (std::size_t i = 0; i < e.fits.size(); ++i) {
        TapeSurvey s = surveyors_[i].result();
        ReadingFit& f = e.fits[i];
        f.bad_frames = s.parity_errors + s.not_in_code;
        f.controls = controls_[i];
        f.end_of_blocks = s.end_of_blocks;
        f.program_starts = s.program_starts;
    }
    e.text = bytes_are_frames_ && text_ok_ && e.iso_lf > 0 && e.punched == e.frames;
    const std::uint64_t frames = std::max<std::uint64_t>(e.significant, 1);
    const ReadingFit* best = &e.fits[0];
    for (const auto& f : e.fits)
        if (score(f) < score(*best)) best = &f;

    if (e.punched == 0) return blank_verdict(std::move(d));
    if (e.text) return text_verdict(std::move(d));
    if (e.five_track == e.punched && !clean(e.fits[0], frames) && !clean(e.fits[1], frames))
        return five_track_verdict(std::move(d));
    if (const BinaryTape* binary = binary_.tape()) {
        e.binary = *binary;
        return binary_verdict(std::move(d));
    }
    if (fits(*best, frames)) return reading_verdict(std::move(d), *best, frames);
    return no_code_verdict(std::move(d), *best, frames);
}

std::string closest_reading_note(const CodeDetection& d) {
    const ReadingFit* fit = &d.evidence.fits[0];
    for (const auto& f : d.evidence.fits)
        if (d.closest && f.reading == *d.closest) fit = &f;
    return "decoded as " + reading_name(fit->reading) + ", the closest code but no sure one: it fails " +
           n(score(*fit)) + " of " + frames_text(std::max<std::uint64_t>(d.evidence.significant, 1)) +
           ", more than one in ten, which a damaged tape of that code seldom has; the text may be of another code";
}

std::optional<Diagnostic> other_reading(const CodeDetection& d, Reading forced) {
    Diagnostic note{.code = Errc::unknown_code, .severity = Severity::note};
    if (d.kind == TapeKind::five_track || d.kind == TapeKind::text || d.kind == TapeKind::binary) {
        note.message = d.reason;
        note.hint = d.hint;
        return note;
    }
    if (!d.reading || !d.clean || *d.reading == forced) return std::nullopt;
    const ReadingFit* fit = nullptr;
    for (const auto& f : d.evidence.fits)
        if (f.reading == *d.reading) fit = &f;
    note.message = "the tape reads cleanly as " + reading_name(*d.reading) + ": " + n(fit ? fit->bad_frames : 0) +
                   " of " + n(d.evidence.significant) + " frames fail it";
    note.hint = hint_for(*d.reading);
    // "--code iso" alone would keep a parity given by hand: name the even parity too.
    if (forced.code == Code::iso && forced.parity != Parity::even && d.reading->parity == Parity::even)
        note.hint = Hint{Hint::Action::use_iso_parity, parity_name(Parity::even)};
    return note;
}

}  // namespace tape
