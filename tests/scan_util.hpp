// Pictures of tapes for the scan tests and benchmarks: drawn by tape render, written to files, read back
// by tape scan, and the read scored against the tape it was drawn from.
#pragma once

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "tape/align.hpp"
#include "tape/picture.hpp"
#include "tape/render.hpp"
#include "tape/scan.hpp"

/// How a read did against its tape: frames right, wrong but doubtful, wrong and not doubtful.
struct ReadScore {
    std::uint64_t frames = 0, right = 0, flagged_wrong = 0, silently_wrong = 0, doubtful = 0;
    void tally(bool right_frame, bool doubt) {
        if (right_frame)
            ++right;
        else if (doubt)
            ++flagged_wrong;
        else
            ++silently_wrong;
    }
    double right_share() const { return frames ? static_cast<double>(right) / static_cast<double>(frames) : 0; }
};

inline bool doubtful_at(const tape::ScanResult& r, std::uint64_t frame) {
    for (const auto& d : r.doubts.runs)
        if (frame >= d.first && frame <= d.last) return true;
    return false;
}

/// The read against the tape, frame by frame where they have one length, else through the aligner
/// (a frame lost or added is wrong; silently so where no doubt names it).
inline ReadScore score_read(const std::vector<tape::Frame>& tape_frames, const tape::ScanResult& r) {
    ReadScore s;
    s.frames = tape_frames.size();
    for (const auto& d : r.doubts.runs) s.doubtful += d.last - d.first + 1;
    if (r.frames.size() == tape_frames.size()) {
        for (std::size_t i = 0; i < tape_frames.size(); ++i) {
            s.tally(r.frames[i] == tape_frames[i], doubtful_at(r, i + 1));
        }
        return s;
    }
    std::span<const tape::Frame> reads[] = {tape_frames, r.frames};
    tape::AlignOptions o;
    o.min_shared = 0;
    auto a = tape::align_reads(reads, o);
    // A frame the read lacks counts as said when a frame next to the place is doubtful (a lost end, a gap).
    std::vector<std::int32_t> next(a.columns() + 1, tape::ReadAlignment::none);
    for (std::size_t c = a.columns(); c-- > 0;)
        next[c] = a.frame(c, 1) != tape::ReadAlignment::none ? a.frame(c, 1) : next[c + 1];
    std::int32_t before = tape::ReadAlignment::none;
    // A run of equal frames (a leader) is said short when any frame of it is doubtful: where in the run
    // the aligner puts the missing frame is its choice.
    auto doubt_at = [&](std::int32_t g) {
        if (g == tape::ReadAlignment::none) return false;
        auto i = static_cast<std::size_t>(g), j = i;
        while (i > 0 && r.frames[i - 1] == r.frames[j]) --i;
        while (j + 1 < r.frames.size() && r.frames[j + 1] == r.frames[i]) ++j;
        for (std::size_t k = i; k <= j; ++k)
            if (doubtful_at(r, k + 1)) return true;
        return false;
    };
    for (std::size_t c = 0; c < a.columns(); ++c) {
        auto t = a.frame(c, 0), g = a.frame(c, 1);
        bool doubt = g != tape::ReadAlignment::none ? doubtful_at(r, static_cast<std::uint64_t>(g) + 1)
                                                    : doubt_at(before) || doubt_at(next[c]);
        s.tally(t != tape::ReadAlignment::none && g != tape::ReadAlignment::none &&
                    tape_frames[static_cast<std::size_t>(t)] == r.frames[static_cast<std::size_t>(g)],
                doubt);
        if (g != tape::ReadAlignment::none) before = g;
    }
    return s;
}

inline void write_picture(const tape::Picture& p, const std::string& path) {
    auto bytes = tape::encode_picture(p, tape::picture_format_for_path(path), 90);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

/// The picture turned half a turn (the tape seen from the same face, its start at the other end).
inline tape::Picture half_turn(const tape::Picture& p) {
    tape::Picture out = p;
    const std::size_t n = static_cast<std::size_t>(p.width) * p.height;
    for (std::size_t i = 0; i < n; ++i)
        std::copy_n(&p.pixels[(n - 1 - i) * p.channels], p.channels, &out.pixels[i * p.channels]);
    return out;
}

/// Columns [x0, x1) of the picture: one overlapping segment of a long tape.
inline tape::Picture columns(const tape::Picture& p, int x0, int x1) {
    tape::Picture out{x1 - x0, p.height, p.channels, {}};
    out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * p.channels);
    for (int y = 0; y < p.height; ++y) std::copy_n(p.at(x0, y), out.width * p.channels, out.at(0, y));
    return out;
}
