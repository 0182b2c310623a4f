// Gathering the evidence for a verdict on a tape: every reading tried at once over the same frames.
#include "tape/detect.hpp"

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

void Detector::feed(std::span<const Frame> frames) {
    TapeEvidence& e = evidence_;
    e.frames += frames.size();
    for (auto& s : surveyors_) s.feed(frames);
    binary_.feed(frames);
    ParityCounts p = count_parity(frames);
    e.parity.frames += p.frames;
    e.parity.even += p.even;
    e.parity.odd += p.odd;
    e.parity.mark += p.mark;
    e.parity.space += p.space;
    for (Frame f : frames) {
        run_0x80_ = f == 0x80 ? run_0x80_ + 1 : 0;
        e.longest_0x80_run = std::max(e.longest_0x80_run, run_0x80_);
        if (f == blank_frame) continue;
        ++e.punched;
        e.significant += f != 0xFF && f != 0x7F;
        e.five_track += f < 0x20;
        e.iso_lf += f == 0x0A;
        e.eia_eob += f == 0x80;
        // ISO readings only: the 7 bits are the character whatever the parity convention.
        if (!text_control(static_cast<char>(f & 0x7F)))
            for (std::size_t i = 0; i < readings.size(); ++i)
                if (readings[i].code == Code::iso && surveyors_[i].kind(f) == FrameKind::character) ++controls_[i];
        note_koi7(f);
    }
    if (text_ok_ && !frames.empty()) text_ok_ = !text_checker_.check(frames);
}

// КОИ-7 shifts Russian letters with SO ... SI; read as ASCII, the letters between them look Latin.
void Detector::note_koi7(Frame f) {
    if (surveyors_[0].kind(f) != FrameKind::character) return;
    char c = static_cast<char>(f & 0x7F);
    if (c == 0x0E || c == 0x0F || c == '\n') shifted_ = c == 0x0E;
    evidence_.koi7_letters += shifted_ && c >= 0x40 && c <= 0x7E;
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
