#include "tape/survey.hpp"

#include <algorithm>
#include <cstring>

namespace tape {

ParityCounts count_parity(std::span<const Frame> frames) { return FrameTally(frames).parity; }

ParityCounts& ParityCounts::operator+=(const ParityCounts& o) {
    frames += o.frames;
    even += o.even;
    odd += o.odd;
    mark += o.mark;
    space += o.space;
    return *this;
}

std::uint64_t ParityCounts::misfits(Parity p) const {
    switch (p) {
        case Parity::even:
            return frames - even;
        case Parity::odd:
            return frames - odd;
        case Parity::mark:
            return frames - mark;
        case Parity::space:
            return frames - space;
        case Parity::none:
            return 0;
    }
    return frames;
}

std::optional<Parity> ParityCounts::dominant() const {
    if (frames == 0) return std::nullopt;
    Parity best = Parity::even;
    for (Parity p : {Parity::odd, Parity::mark, Parity::space})
        if (misfits(p) < misfits(best)) best = p;
    if (misfits(best) * 10 > frames) return std::nullopt;
    return best;
}

FrameTally::FrameTally(std::span<const Frame> frames) : size(frames.size()) {
    // Four tallies in turn, so that a run of equal frames does not wait on one counter; 32 bits each
    // for a piece of at most 2^30 frames at a time.
    constexpr std::size_t piece = std::size_t{1} << 30;
    for (std::size_t from = 0; from < frames.size(); from += piece) {
        std::array<std::array<std::uint32_t, 256>, 4> part{};
        const Frame* f = frames.data() + from;
        std::size_t n = std::min(piece, frames.size() - from), i = 0;
        for (; i + 4 <= n; i += 4) ++part[0][f[i]], ++part[1][f[i + 1]], ++part[2][f[i + 2]], ++part[3][f[i + 3]];
        for (; i < n; ++i) ++part[0][f[i]];
        for (int v = 0; v < 256; ++v) count[v] += part[0][v] + part[1][v] + part[2][v] + part[3][v];
    }
    first_punched = size;
    if (count[blank_frame] == size) return;
    first_punched = 0;
    while (frames[first_punched] == blank_frame) ++first_punched;
    last_punched = size - 1;
    while (frames[last_punched] == blank_frame) --last_punched;
    for (int v = 1; v < 256; ++v) {
        parity.frames += count[v];
        if (hole_count(static_cast<Frame>(v)) % 2 == 0) parity.even += count[v];
        if (v & 0x80) parity.mark += count[v];
    }
    parity.odd = parity.frames - parity.even;
    parity.space = parity.frames - parity.mark;
}

Surveyor::Surveyor(const FrameCode& code) : code_(code) {
    for (int f = 1; f < 256; ++f)
        if (code_.kind(static_cast<Frame>(f)) == FrameKind::character && code_.character(static_cast<Frame>(f)) == '%')
            percent_frame_ = percent_frame_ == -1 ? f : -2;
}

void Surveyor::feed(std::span<const Frame> frames) { feed(frames, FrameTally(frames)); }

void Surveyor::feed(std::span<const Frame> frames, const FrameTally& t) {
    s_.frames += frames.size();
    s_.parity += t.parity;
    count_blank_tape(t);
    for (int v = 1; v < 256; ++v) {
        std::uint64_t n = t.count[v];
        if (n == 0) continue;
        auto f = static_cast<Frame>(v);
        switch (code_.kind(f)) {
            case FrameKind::blank:  // a punched frame the code takes for blank tape
                s_.blank_inside += n;
                break;
            case FrameKind::rubout:
                s_.rubouts += n;
                break;
            case FrameKind::parity_error:
                s_.parity_errors += n;
                break;
            case FrameKind::not_in_code:
                s_.not_in_code += n;
                break;
            case FrameKind::character:
                s_.data += n;
                if (code_.character(f) == '\n') s_.end_of_blocks += n;
                break;
        }
    }
    count_program_starts(frames);
}

// Blank frames before the first punched one are leader; between punched frames, inside; after the
// last, trailer for now (the next piece may go on).
void Surveyor::count_blank_tape(const FrameTally& t) {
    std::uint64_t blank = t.count[blank_frame];
    if (t.first_punched == t.size) {
        blank_run_ += blank;
        return;
    }
    std::uint64_t before = t.first_punched, after = t.size - 1 - t.last_punched;
    (punched_ ? s_.blank_inside : s_.leader) += blank_run_ + before;
    s_.blank_inside += blank - before - after;
    blank_run_ = after;
    punched_ = true;
}

// A '%' starts a program only when one follows it: the '%' that closes the last program (the rewind
// stop) is followed by nothing but line ends and blank tape. A run such as "%%" counts once. Only the
// frames from a '%' to the character after it are looked at.
void Surveyor::count_program_starts(std::span<const Frame> frames) {
    for (std::size_t i = 0; i < frames.size();) {
        if (!percent_) {
            i = next_percent(frames, i);
            if (i == frames.size()) return;
            percent_ = true;
            ++i;
            continue;
        }
        Frame f = frames[i++];
        if (f == blank_frame || code_.kind(f) != FrameKind::character) continue;
        char c = code_.character(f);
        if (c != '%' && c != ' ' && c != '\n' && c != '\r') {
            ++s_.program_starts;
            percent_ = false;
        }
    }
}

std::size_t Surveyor::next_percent(std::span<const Frame> frames, std::size_t from) const {
    if (percent_frame_ == -1) return frames.size();
    if (percent_frame_ >= 0) {
        const void* p = std::memchr(frames.data() + from, percent_frame_, frames.size() - from);
        return p ? static_cast<std::size_t>(static_cast<const Frame*>(p) - frames.data()) : frames.size();
    }
    while (from < frames.size() &&
           !(code_.kind(frames[from]) == FrameKind::character && code_.character(frames[from]) == '%'))
        ++from;
    return from;
}

TapeSurvey Surveyor::result() const {
    TapeSurvey s = s_;
    (punched_ ? s.trailer : s.leader) += blank_run_;
    return s;
}

TapeSurvey survey(std::span<const Frame> frames, const FrameCode& code) {
    Surveyor surveyor(code);
    surveyor.feed(frames);
    return surveyor.result();
}

}  // namespace tape
