// Gathering the evidence for a verdict on a tape: every reading tried at once over the same frames.
#include "tape/detect.hpp"

#include <algorithm>
#include <cstring>

namespace tape {
namespace {

constexpr std::array<Reading, 6> readings = {Reading{Code::iso, Parity::even}, Reading{Code::eia, Parity::odd},
                                             Reading{Code::iso, Parity::mark}, Reading{Code::iso, Parity::space},
                                             Reading{Code::iso, Parity::odd},  Reading{Code::elliott920, Parity::even}};

// Control characters that turn up on tapes of text: blank and rubout, BS, HT, LF, FF, CR, the КОИ-7
// shifts SO/SI and the Teletype's reader and punch controls DC1-DC4. Any other (BEL, ESC...) in
// quantity means the frames are not text at all.
bool text_control(char c) {
    switch (c) {
        case 0x00:
        case 0x08:
        case 0x09:
        case 0x0A:
        case 0x0C:
        case 0x0D:
        case 0x0E:
        case 0x0F:
        case 0x11:
        case 0x12:
        case 0x13:
        case 0x14:
        case 0x7F:
            return true;
        default:
            return static_cast<unsigned char>(c) >= 0x20;
    }
}

}  // namespace

Detector::Detector(const CodeTable* eia_table, bool bytes_are_frames)
    : bytes_are_frames_(bytes_are_frames), text_ok_(bytes_are_frames) {
    for (std::size_t i = 0; i < readings.size(); ++i) {
        evidence_.fits[i].reading = readings[i];
        surveyors_.emplace_back(FrameCode::make(readings[i].code, readings[i].parity, eia_table));
    }
}

// Counted from one tally of the frames' values for every reading; only what depends on the order of the
// frames (runs of 0x80, КОИ-7 shifts, the program starts, the binary formats) looks at them in turn.
void Detector::feed(std::span<const Frame> frames) {
    TapeEvidence& e = evidence_;
    FrameTally t(frames);
    e.frames += frames.size();
    for (auto& s : surveyors_) s.feed(frames, t);
    binary_.feed(frames);
    e.parity += t.parity;
    std::uint64_t punched = frames.size() - t.count[blank_frame];
    e.punched += punched;
    e.significant += punched - t.count[0xFF] - t.count[0x7F];
    for (int v = 1; v < 0x20; ++v) e.five_track += t.count[v];
    e.iso_lf += t.count[0x0A];
    e.eia_eob += t.count[0x80];
    // ISO readings only: the 7 bits are the character whatever the parity convention.
    for (int v = 1; v < 256; ++v)
        if (t.count[v] && !text_control(static_cast<char>(v & 0x7F)))
            for (std::size_t i = 0; i < readings.size(); ++i)
                if (readings[i].code == Code::iso && surveyors_[i].kind(static_cast<Frame>(v)) == FrameKind::character)
                    controls_[i] += t.count[v];
    note_0x80_runs(frames, t);
    note_koi7(frames, t);
    if (text_ok_ && !frames.empty()) text_ok_ = !text_checker_.check(frames);
}

// Track 8 alone, in a row: found with memchr, the run carried from one piece to the next.
void Detector::note_0x80_runs(std::span<const Frame> frames, const FrameTally& t) {
    if (frames.empty()) return;
    if (t.count[0x80] == 0) {
        run_0x80_ = 0;
        return;
    }
    for (std::size_t i = 0; i < frames.size();) {
        if (frames[i] != 0x80) {
            run_0x80_ = 0;
            const void* next = std::memchr(frames.data() + i, 0x80, frames.size() - i);
            if (!next) return;
            i = static_cast<std::size_t>(static_cast<const Frame*>(next) - frames.data());
        }
        for (; i < frames.size() && frames[i] == 0x80; ++i) ++run_0x80_;
        evidence_.longest_0x80_run = std::max(evidence_.longest_0x80_run, run_0x80_);
    }
}

// КОИ-7 shifts Russian letters with SO ... SI; read as ASCII, the letters between them look Latin. A
// piece with no SO, not begun shifted, holds none.
void Detector::note_koi7(std::span<const Frame> frames, const FrameTally& t) {
    bool any_shift_out = false;
    for (int v = 1; v < 256; ++v)
        any_shift_out |=
            t.count[v] && (v & 0x7F) == 0x0E && surveyors_[0].kind(static_cast<Frame>(v)) == FrameKind::character;
    if (!any_shift_out && !shifted_) return;
    for (Frame f : frames) {
        if (surveyors_[0].kind(f) != FrameKind::character) continue;
        char c = static_cast<char>(f & 0x7F);
        if (c == 0x0E || c == 0x0F || c == '\n') shifted_ = c == 0x0E;
        evidence_.koi7_letters += shifted_ && c >= 0x40 && c <= 0x7E;
    }
}

bool looks_like_koi7(const TapeEvidence& e) { return e.koi7_letters >= 3; }

TapeSurvey Detector::survey(Reading r) const {
    for (std::size_t i = 0; i < readings.size(); ++i)
        if (readings[i] == r) return surveyors_[i].result();
    return {};
}

CodeDetection detect_code(std::span<const Frame> frames, const CodeTable* eia_table) {
    Detector d(eia_table);
    d.feed(frames);
    d.finish();
    return d.result();
}

}  // namespace tape
