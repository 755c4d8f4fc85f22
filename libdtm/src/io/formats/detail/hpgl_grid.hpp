// SPDX-License-Identifier: MIT
/// @file
/// @brief A hashed uniform grid of point indices for "everything within r" queries in linear time.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::io::hpgl {

class PointGrid {
public:
    explicit PointGrid(double cell) : cell_(cell > 0.0 ? cell : 1.0) {}

    void insert(Point2 p, std::uint32_t index) { cells_[key(cell_of(p.x), cell_of(p.y))].push_back(index); }

    /// Calls @p visit(index) for every point in the 3 x 3 cells around @p p (a superset of the
    /// points within one cell size of @p p).
    template <class Visit>
    void near(Point2 p, Visit&& visit) const
    {
        const std::int64_t cx = cell_of(p.x), cy = cell_of(p.y);
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                const auto it = cells_.find(key(cx + dx, cy + dy));
                if (it == cells_.end()) continue;
                for (const std::uint32_t index : it->second) visit(index);
            }
        }
    }

    [[nodiscard]] bool empty() const noexcept { return cells_.empty(); }

private:
    [[nodiscard]] std::int64_t cell_of(double v) const
    {
        const double c = std::floor(v / cell_);
        if (std::isnan(c)) return 0;
        return c > 1e15 ? std::int64_t{1'000'000'000'000'000} : c < -1e15 ? -std::int64_t{1'000'000'000'000'000}
                                                                           : static_cast<std::int64_t>(c);
    }
    static std::uint64_t key(std::int64_t x, std::int64_t y)
    {
        return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y);
    }

    double cell_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

inline double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace dtm::io::hpgl
