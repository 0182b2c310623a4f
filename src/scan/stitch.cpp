// Pieces of one tape read from several pictures, joined into one read (scan_geometry.hpp). Their order
// and overlap are found by aligning their frames (tape/align.hpp), each also turned end for end, since a
// picture does not show which way its strip runs. The pair that overlaps best is joined first, again
// until no two overlap; what is left stands in the order given, with a gap between pieces.
#include <algorithm>
#include <optional>

#include "scan/scan_geometry.hpp"
#include "tape/align.hpp"
#include "tape/error.hpp"

namespace tape::scan {
namespace {

// Two pieces overlap when their shared columns hold at least this many punched frames alike, and
// the frames they both have agree at least this often.
constexpr std::size_t min_shared_punched = 6;
constexpr double min_agreement = 0.9;

struct Overlap {
    bool flip = false;      // the second piece turned end for end
    std::size_t score = 0;  // punched frames alike in the overlap
};

ReadAlignment align_two(const Piece& a, const Piece& b) {
    std::span<const Frame> reads[] = {a.frames, b.frames};
    AlignOptions o;
    o.anchor_length = 8;
    o.min_shared = 0;
    return align_reads(reads, o);
}

std::optional<std::size_t> overlap_score(const Piece& a, const Piece& b) {
    if (a.frames.empty() || b.frames.empty()) return std::nullopt;
    ReadAlignment al = align_two(a, b);
    std::size_t alike = 0, both = 0, punched = 0;
    for (std::size_t c = 0; c < al.columns(); ++c) {
        auto i = al.frame(c, 0), j = al.frame(c, 1);
        if (!al.covers(0, c) || !al.covers(1, c)) continue;
        if (i == ReadAlignment::none || j == ReadAlignment::none) {
            ++both;  // one has a frame the other, covering it, has not
            continue;
        }
        ++both;
        Frame fa = a.frames[static_cast<std::size_t>(i)], fb = b.frames[static_cast<std::size_t>(j)];
        alike += fa == fb;
        punched += fa == fb && fa != blank_frame;
    }
    if (punched < min_shared_punched || static_cast<double>(alike) < min_agreement * static_cast<double>(both))
        return std::nullopt;
    return punched;
}

std::optional<Overlap> best_overlap(const Piece& a, const Piece& b) {
    std::optional<Overlap> best;
    for (bool flip : {false, true}) {
        auto s = overlap_score(a, flip ? reversed(b) : b);
        if (s && (!best || *s > best->score)) best = Overlap{flip, *s};
    }
    return best;
}

void take(Piece& out, const Piece& p, std::size_t k) {
    out.frames.push_back(p.frames[k]);
    out.confidence.push_back(p.confidence[k]);
    out.doubt.push_back(p.doubt[k]);
    out.image.push_back(p.image[k]);
    out.index.push_back(p.index[k]);
}

// One column where both pieces have a frame: the surer reading, or a doubt when two sure ones differ.
void take_either(Piece& out, const Piece& a, std::size_t i, const Piece& b, std::size_t j) {
    bool a_sure = a.doubt[i].empty(), b_sure = b.doubt[j].empty();
    bool first = a_sure != b_sure ? a_sure : a.confidence[i] >= b.confidence[j];
    take(out, first ? a : b, first ? i : j);
    if (a.frames[i] != b.frames[j] && a_sure && b_sure) {
        out.confidence.back() = 0;
        out.doubt.back() =
            "the pictures disagree here (" + frame_hex(a.frames[i]) + " and " + frame_hex(b.frames[j]) + ")";
    }
}

Piece join(const Piece& a, const Piece& b) {
    ReadAlignment al = align_two(a, b);
    Piece out;
    for (std::size_t c = 0; c < al.columns(); ++c) {
        auto i = al.frame(c, 0), j = al.frame(c, 1);
        if (i != ReadAlignment::none && j != ReadAlignment::none) {
            take_either(out, a, static_cast<std::size_t>(i), b, static_cast<std::size_t>(j));
            continue;
        }
        bool from_a = i != ReadAlignment::none;
        take(out, from_a ? a : b, static_cast<std::size_t>(from_a ? i : j));
        if (al.covers(from_a ? 1 : 0, c)) {
            out.confidence.back() = 0;
            out.doubt.back() = "only one of the pictures that show this place has this frame";
        }
    }
    bool a_first = al.first_column(0) <= al.first_column(1), a_last = al.end_column(0) >= al.end_column(1);
    out.start_cut = a_first ? a.start_cut : b.start_cut;
    out.end_cut = a_last ? a.end_cut : b.end_cut;
    return out;
}

std::uint32_t first_image(const Piece& p) {
    return p.image.empty() ? UINT32_MAX : *std::min_element(p.image.begin(), p.image.end());
}

}  // namespace

Piece reversed(Piece p) {
    std::reverse(p.frames.begin(), p.frames.end());
    std::reverse(p.confidence.begin(), p.confidence.end());
    std::reverse(p.doubt.begin(), p.doubt.end());
    std::reverse(p.image.begin(), p.image.end());
    std::reverse(p.index.begin(), p.index.end());
    std::swap(p.start_cut, p.end_cut);
    return p;
}

Piece stitch(std::vector<Piece> pieces, std::vector<std::uint64_t>& gaps) {
    gaps.clear();
    std::erase_if(pieces, [](const Piece& p) { return p.frames.empty(); });
    // overlaps[i][j] (i < j): how piece j lies against piece i; recomputed for a joined piece only.
    const std::size_t n = pieces.size();
    std::vector<std::vector<std::optional<Overlap>>> overlaps(n, std::vector<std::optional<Overlap>>(n));
    std::vector<bool> alive(n, true);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) overlaps[i][j] = best_overlap(pieces[i], pieces[j]);
    for (;;) {
        std::size_t bi = n, bj = n;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (alive[i] && alive[j] && overlaps[i][j] &&
                    (bi == n || overlaps[i][j]->score > overlaps[bi][bj]->score))
                    bi = i, bj = j;
        if (bi == n) break;
        pieces[bi] = join(pieces[bi], overlaps[bi][bj]->flip ? reversed(pieces[bj]) : pieces[bj]);
        alive[bj] = false;
        pieces[bj] = Piece{};
        for (std::size_t k = 0; k < n; ++k) {
            if (k == bi || !alive[k]) continue;
            auto o = best_overlap(pieces[std::min(bi, k)], pieces[std::max(bi, k)]);
            overlaps[std::min(bi, k)][std::max(bi, k)] = o;
        }
    }
    std::vector<Piece> left;
    for (std::size_t i = 0; i < n; ++i)
        if (alive[i]) left.push_back(std::move(pieces[i]));
    std::sort(left.begin(), left.end(), [](const Piece& a, const Piece& b) { return first_image(a) < first_image(b); });
    Piece out;
    for (std::size_t i = 0; i < left.size(); ++i) {
        if (i > 0)
            gaps.push_back(out.frames.size());
        else
            out.start_cut = left[i].start_cut;
        for (std::size_t k = 0; k < left[i].frames.size(); ++k) take(out, left[i], k);
        out.end_cut = left[i].end_cut;
    }
    return out;
}

}  // namespace tape::scan
