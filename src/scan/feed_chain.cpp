// Chains of feed holes among the round blobs of a picture (scan_geometry.hpp). A chain is grown from a
// pair of neighbouring blobs of one size: the next blob is looked for one step further on, the step
// following the line slowly (a bowed strip), a few holes may be missing (dust, a tear). Rows of code
// holes make chains too; feed holes are told from them by their size against their spacing.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "scan/blob_grid.hpp"
#include "scan/scan_geometry.hpp"

namespace tape::scan {
namespace {

constexpr int max_missing = 3;           // feed holes not seen in a row before a chain ends
constexpr float near_size = 1.5F;        // blobs of one chain differ in diameter by at most this factor
constexpr float step_tolerance = 0.25F;  // the next blob within this part of a step of where it should be

struct Vec {
    float x, y;
};
float length(Vec v) { return std::hypot(v.x, v.y); }

bool alike(float a, float b) { return a <= b * near_size && b <= a * near_size; }

// The direction of v as one of 8 bins over half a turn: a blob is the start of at most one chain a bin.
int direction_bin(Vec v) {
    double a = std::atan2(v.y, v.x);
    if (a < 0) a += std::numbers::pi;
    return std::min(7, static_cast<int>(a / (std::numbers::pi / 8)));
}

class ChainFinder {
public:
    ChainFinder(std::span<const Blob> blobs, const Grid& grid) : blobs_(blobs), grid_(grid), used_(blobs.size(), 0) {}

    // The chain through the seed pair (a, b), grown both ways.
    FeedChain grow_from(std::uint32_t a, std::uint32_t b) {
        Vec step{blobs_[b].x - blobs_[a].x, blobs_[b].y - blobs_[a].y};
        size_ = (blobs_[a].diameter + blobs_[b].diameter) / 2;
        std::vector<std::uint32_t> ahead{b}, behind;
        std::vector<std::uint8_t> ahead_missing{0}, behind_missing;
        extend(b, step, ahead, ahead_missing);
        extend(a, Vec{-step.x, -step.y}, behind, behind_missing);
        FeedChain c;
        // behind holds blobs going backwards, each with the holes missing between it and the one before
        // it on the way out: in the chain's order that count belongs to the blob after it.
        for (std::size_t i = behind.size(); i-- > 0;) {
            c.blobs.push_back(behind[i]);
            c.missing_before.push_back(i + 1 < behind.size() ? behind_missing[i + 1] : 0);
        }
        c.blobs.push_back(a);
        c.missing_before.push_back(behind.empty() ? 0 : behind_missing[0]);
        for (std::size_t i = 0; i < ahead.size(); ++i) {
            c.blobs.push_back(ahead[i]);
            c.missing_before.push_back(ahead_missing[i]);
        }
        return c;
    }

    bool used(std::uint32_t blob, Vec step) const { return used_[blob] >> direction_bin(step) & 1U; }
    void mark(const FeedChain& c) {
        for (std::size_t i = 0; i + 1 < c.blobs.size(); ++i) {
            const Blob &p = blobs_[c.blobs[i]], &q = blobs_[c.blobs[i + 1]];
            int bin = direction_bin(Vec{q.x - p.x, q.y - p.y});
            used_[c.blobs[i]] |= static_cast<std::uint8_t>(1U << bin);
            used_[c.blobs[i + 1]] |= static_cast<std::uint8_t>(1U << bin);
        }
    }

private:
    // Follows the line from blob `from` in the direction of step, appending what it finds.
    void extend(std::uint32_t from, Vec step, std::vector<std::uint32_t>& out, std::vector<std::uint8_t>& missing) {
        int misses = 0;
        std::uint32_t last = from;
        while (misses <= max_missing && out.size() < blobs_.size()) {
            float k = static_cast<float>(misses + 1);
            float qx = blobs_[last].x + step.x * k, qy = blobs_[last].y + step.y * k;
            float tolerance = step_tolerance * length(step), best = tolerance;
            std::uint32_t found = UINT32_MAX;
            grid_.near(qx, qy, tolerance, [&](std::uint32_t i) {
                float d = std::hypot(blobs_[i].x - qx, blobs_[i].y - qy);
                if (d < best && i != last && alike(blobs_[i].diameter, size_)) best = d, found = i;
            });
            if (found == UINT32_MAX) {
                ++misses;
                continue;
            }
            Vec seen{(blobs_[found].x - blobs_[last].x) / k, (blobs_[found].y - blobs_[last].y) / k};
            step = Vec{0.75F * step.x + 0.25F * seen.x, 0.75F * step.y + 0.25F * seen.y};
            out.push_back(found);
            missing.push_back(static_cast<std::uint8_t>(misses));
            last = found, misses = 0;
        }
    }

    std::span<const Blob> blobs_;
    const Grid& grid_;
    std::vector<std::uint8_t> used_;  // per blob: the direction bins of the chains it is in
    float size_ = 0;
};

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

void measure(std::span<const Blob> blobs, const Grid& grid, FeedChain& c) {
    std::vector<double> steps;
    double size = 0;
    std::size_t halfway = 0, beside = 0;
    for (std::size_t i = 0; i < c.blobs.size(); ++i) {
        const Blob& q = blobs[c.blobs[i]];
        size += q.diameter;
        if (i == 0) continue;
        const Blob& p = blobs[c.blobs[i - 1]];
        float d = std::hypot(q.x - p.x, q.y - p.y);
        steps.push_back(d / (c.missing_before[i] + 1.0));
        if (c.missing_before[i] == 0 && nearest_blob(grid, blobs, (p.x + q.x) / 2, (p.y + q.y) / 2, 0.15F * d,
                                                     q.diameter / near_size, q.diameter * near_size) != UINT32_MAX)
            ++halfway;
        // Across the row, a step away: the code holes beside a feed hole are half as wide again.
        float ux = (q.x - p.x) / d, uy = (q.y - p.y) / d, step = d / static_cast<float>(c.missing_before[i] + 1);
        for (float side : {-1.0F, 1.0F})
            if (nearest_blob(grid, blobs, q.x - uy * step * side, q.y + ux * step * side, 0.25F * step,
                             q.diameter / 1.25F, q.diameter * 1.25F) != UINT32_MAX) {
                ++beside;
                break;
            }
    }
    c.beside = c.blobs.size() > 1 ? static_cast<double>(beside) / static_cast<double>(c.blobs.size() - 1) : 0;
    c.between = steps.empty() ? 0 : static_cast<double>(halfway) / static_cast<double>(steps.size());
    c.pitch = median(steps);
    c.hole_ratio = c.pitch > 0 ? size / static_cast<double>(c.blobs.size()) / c.pitch : 0;
}

// Chains that are mostly part of a longer one are the same row found twice.
std::vector<FeedChain> distinct(std::vector<FeedChain> chains, std::size_t blob_count) {
    std::sort(chains.begin(), chains.end(),
              [](const FeedChain& a, const FeedChain& b) { return a.frames() > b.frames(); });
    std::vector<std::int32_t> owner(blob_count, -1);
    std::vector<FeedChain> out;
    for (auto& c : chains) {
        std::size_t taken = 0;
        for (auto b : c.blobs) taken += owner[b] >= 0;
        if (taken * 2 > c.blobs.size()) continue;
        for (auto b : c.blobs)
            if (owner[b] < 0) owner[b] = static_cast<std::int32_t>(out.size());
        out.push_back(std::move(c));
    }
    return out;
}

}  // namespace

std::size_t FeedChain::frames() const {
    std::size_t n = blobs.size();
    for (auto m : missing_before) n += m;
    return n;
}

bool feed_like(const FeedChain& chain) {
    return chain.hole_ratio > 0.2 && chain.hole_ratio < 0.6 && chain.between < 0.1 && chain.beside < 0.1;
}

std::vector<FeedChain> follow_chains(std::span<const Blob> blobs, std::size_t min_frames) {
    if (blobs.size() < 2 || blobs.size() > max_blobs) return {};
    std::vector<float> sizes;
    for (const auto& b : blobs) sizes.push_back(b.diameter);
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() * 3 / 4), sizes.end());
    Grid grid(blobs, std::max(2.0F, sizes[sizes.size() * 3 / 4] * 3));
    ChainFinder finder(blobs, grid);
    std::vector<FeedChain> found;
    for (std::uint32_t a = 0; a < blobs.size(); ++a) {
        const Blob& p = blobs[a];
        if (!(p.diameter > 0) || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        float reach = 3.6F * p.diameter * near_size;
        std::vector<std::uint32_t> partners;
        grid.near(p.x, p.y, reach, [&](std::uint32_t b) {
            const Blob& q = blobs[b];
            Vec v{q.x - p.x, q.y - p.y};
            float d = length(v), mean = (p.diameter + q.diameter) / 2;
            if (b != a && (v.x > 0 || (v.x == 0 && v.y > 0)) && alike(p.diameter, q.diameter) && d >= 1.5F * mean &&
                d <= 3.6F * mean)
                partners.push_back(b);
        });
        for (auto b : partners) {
            Vec v{blobs[b].x - p.x, blobs[b].y - p.y};
            if (finder.used(a, v)) continue;
            FeedChain c = finder.grow_from(a, b);
            if (c.blobs.size() < 3) continue;
            finder.mark(c);
            measure(blobs, grid, c);
            if (c.frames() >= min_frames) found.push_back(std::move(c));
        }
    }
    return distinct(std::move(found), blobs.size());
}

}  // namespace tape::scan
