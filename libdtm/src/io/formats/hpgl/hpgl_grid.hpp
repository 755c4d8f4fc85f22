// SPDX-License-Identifier: MIT
/// @file
/// @brief A static uniform grid (compressed rows: cell offsets + point indices) for "every point
/// within r" queries; built in linear time, about one point per cell, queries touch 1-4 cells.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::io::hpgl {

inline double distance(Point2 a, Point2 b) {
    const double dx = a.x - b.x, dy = a.y - b.y;
    return std::sqrt(dx * dx + dy * dy);
}

class PointGrid {
public:
    /// @p radius is the query radius the grid is tuned for (cells are at least 2 * radius).
    PointGrid(const std::vector<Point2>& points, double radius) : points_(points) {
        Box2 box;
        for (const Point2& p : points) {
            if (std::isfinite(p.x) && std::isfinite(p.y)) box.add(p);
        }
        if (box.empty()) return;
        x0_ = box.xmin;
        y0_ = box.ymin;
        const double w = box.xmax - box.xmin, h = box.ymax - box.ymin;
        const double n = static_cast<double>(points.size());
        cell_ =
            std::max({2.0 * radius, std::sqrt(w * h / n), std::max(w, h) / (4.0 * n + 16.0), 1e-9});
        nx_ = static_cast<std::int64_t>(w / cell_) + 1;
        ny_ = static_cast<std::int64_t>(h / cell_) + 1;
        start_.assign(static_cast<std::size_t>(nx_ * ny_ + 1), 0);
        std::vector<std::uint32_t> cell_of(points.size(), UINT32_MAX);
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) continue;
            cell_of[i] = static_cast<std::uint32_t>(column(points[i].x) + nx_ * row(points[i].y));
            ++start_[cell_of[i] + 1];
        }
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        index_.resize(start_.back());
        std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (cell_of[i] != UINT32_MAX)
                index_[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
        }
    }

    /// Calls @p visit(index, distance) for every point within @p r of @p p (r <= the tuned radius
    /// keeps queries at 1-4 cells), in increasing index order within each cell.
    template <class Visit>
    void near(Point2 p, double r, Visit&& visit) const {
        if (start_.empty() || !(std::isfinite(p.x) && std::isfinite(p.y))) return;
        const double lx = (p.x - r - x0_) / cell_, hx = (p.x + r - x0_) / cell_;
        const double ly = (p.y - r - y0_) / cell_, hy = (p.y + r - y0_) / cell_;
        if (hx < 0.0 || hy < 0.0 || lx >= static_cast<double>(nx_) ||
            ly >= static_cast<double>(ny_))
            return;
        const auto cx0 = static_cast<std::int64_t>(std::max(lx, 0.0));
        const auto cy0 = static_cast<std::int64_t>(std::max(ly, 0.0));
        const auto cx1 = static_cast<std::int64_t>(std::min(hx, static_cast<double>(nx_ - 1)));
        const auto cy1 = static_cast<std::int64_t>(std::min(hy, static_cast<double>(ny_ - 1)));
        for (std::int64_t cy = cy0; cy <= cy1; ++cy) {
            for (std::int64_t cx = cx0; cx <= cx1; ++cx) {
                const auto c = static_cast<std::size_t>(cx + nx_ * cy);
                for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) {
                    const std::uint32_t i = index_[k];
                    const double d = distance(p, points_[i]);
                    if (d <= r) visit(i, d);
                }
            }
        }
    }

private:
    [[nodiscard]] std::int64_t column(double x) const {
        return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - x0_) / cell_), 0, nx_ - 1);
    }
    [[nodiscard]] std::int64_t row(double y) const {
        return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - y0_) / cell_), 0, ny_ - 1);
    }

    const std::vector<Point2>& points_;
    double x0_ = 0.0, y0_ = 0.0, cell_ = 1.0;
    std::int64_t nx_ = 0, ny_ = 0;
    std::vector<std::size_t> start_;
    std::vector<std::uint32_t> index_;
};

}  // namespace dtm::io::hpgl
