// Whether the reads went past the tape's start and end (vote.hpp): a tape is punched with leader and
// trailer, and where no read has any, the tape's start or end may be missing (every read started late,
// or stopped early). A stain at the very end of one read's trailer is not the data going on: frames are
// the data's where another read backs them, or where they follow such frames closely with no other
// read there to say otherwise.
#include "vote.hpp"

namespace tape::detail {
namespace {

// Frames within this many columns of backed data, with no other read covering them, are data too.
constexpr std::size_t close = 8;

bool punched(Frame f) { return hole_count(f) > 1; }

bool backed_by_another(const VoteContext& v, std::size_t c, std::size_t r, Frame f, bool& others_cover) {
    others_cover = false;
    for (std::size_t s = 0; s < v.a.reads(); ++s) {
        if (s == r || !v.a.covers(s, c)) continue;
        others_cover = true;
        auto g = frame_at(v.a, v.reads, c, s);
        if (g && *g == f) return true;
    }
    return false;
}

// The columns read r has, in the direction away from the start (start) or from the end.
bool read_went_past(const VoteContext& v, std::size_t r, bool start) {
    const std::size_t first = v.a.first_column(r), end = v.a.end_column(r);
    if (first >= end) return false;
    bool alone = v.a.reads() == 1;
    // Walk from the tape's middle towards this end: the last backed punched frame met, and whether
    // trailer-like frames follow it.
    std::size_t since_data = close + 1;
    bool past = false;
    auto step = [&](std::size_t c) {
        auto f = frame_at(v.a, v.reads, c, r);
        if (!f) return;
        if (!punched(*f)) {
            past = true;
            ++since_data;
            return;
        }
        bool others_cover = false;
        bool data = alone || backed_by_another(v, c, r, *f, others_cover) || (!others_cover && since_data <= close);
        if (data)
            past = false, since_data = 0;
        else
            ++since_data;
    };
    if (start)
        for (std::size_t c = end; c-- > first;) step(c);
    else
        for (std::size_t c = first; c < end; ++c) step(c);
    return past;
}

}  // namespace

// Leader of a binary tape may be a run of one frame of several holes (all eight tracks).
bool starts_with_a_run(std::span<const Frame> read, bool start) {
    constexpr std::size_t run = 10;
    if (read.size() < run) return false;
    for (std::size_t i = 1; i < run; ++i)
        if ((start ? read[i] : read[read.size() - 1 - i]) != (start ? read[0] : read.back())) return false;
    return true;
}

bool read_past_end(const VoteContext& v, bool start) {
    for (std::size_t r = 0; r < v.a.reads(); ++r)
        if (v.a.related(r) && (read_went_past(v, r, start) || starts_with_a_run(v.reads[r], start))) return true;
    return false;
}

}  // namespace tape::detail
