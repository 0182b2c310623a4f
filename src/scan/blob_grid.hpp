// Blobs in square cells, for finding those near a point (feed_chain.cpp, track_sampling.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "scan/scan_geometry.hpp"

namespace tape::scan {

/// Blobs in square cells of about `cell` pixels (fewer, larger cells for blobs spread very far).
class Grid {
public:
    Grid(std::span<const Blob> blobs, float cell) : blobs_(blobs) {
        float x0 = std::numeric_limits<float>::max(), y0 = x0, x1 = std::numeric_limits<float>::lowest(), y1 = x1;
        for (const auto& b : blobs)
            x0 = std::min(x0, b.x), y0 = std::min(y0, b.y), x1 = std::max(x1, b.x), y1 = std::max(y1, b.y);
        if (blobs.empty()) x0 = y0 = x1 = y1 = 0;
        x0_ = x0, y0_ = y0;
        // At most about 4 million cells, whatever the coordinates.
        double span = std::max<double>(x1 - x0, y1 - y0);
        cell_ = std::max<float>(cell, static_cast<float>(span / 2048.0));
        cols_ = static_cast<int>((x1 - x0) / cell_) + 1;
        rows_ = static_cast<int>((y1 - y0) / cell_) + 1;
        start_.assign(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_) + 1, 0);
        for (const auto& b : blobs) ++start_[index(b.x, b.y) + 1];
        for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
        items_.resize(blobs.size());
        std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
        for (std::uint32_t i = 0; i < blobs.size(); ++i) items_[fill[index(blobs[i].x, blobs[i].y)]++] = i;
    }

    /// Calls f(index) for every blob within r of (x, y) (and a few more).
    template <class F>
    void near(float x, float y, float r, F&& f) const {
        int c0 = column(x - r), c1 = column(x + r), r0 = row(y - r), r1 = row(y + r);
        for (int rr = r0; rr <= r1; ++rr)
            for (int cc = c0; cc <= c1; ++cc) {
                std::size_t k =
                    static_cast<std::size_t>(rr) * static_cast<std::size_t>(cols_) + static_cast<std::size_t>(cc);
                for (std::uint32_t at = start_[k]; at < start_[k + 1]; ++at) f(items_[at]);
            }
    }

private:
    int column(float x) const { return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, cols_ - 1); }
    int row(float y) const { return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, rows_ - 1); }
    std::size_t index(float x, float y) const {
        return static_cast<std::size_t>(row(y)) * static_cast<std::size_t>(cols_) + static_cast<std::size_t>(column(x));
    }

    std::span<const Blob> blobs_;
    float x0_ = 0, y0_ = 0, cell_ = 1;
    int cols_ = 1, rows_ = 1;
    std::vector<std::uint32_t> start_, items_;
};

/// The blob nearest (x, y) within r whose diameter is from lo to hi, or UINT32_MAX.
inline std::uint32_t nearest_blob(const Grid& grid, std::span<const Blob> blobs, float x, float y, float r, float lo,
                                  float hi) {
    std::uint32_t found = UINT32_MAX;
    float best = r;
    grid.near(x, y, r, [&](std::uint32_t i) {
        float d = std::hypot(blobs[i].x - x, blobs[i].y - y);
        if (d < best && blobs[i].diameter >= lo && blobs[i].diameter <= hi) best = d, found = i;
    });
    return found;
}

}  // namespace tape::scan
