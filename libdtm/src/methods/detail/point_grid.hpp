// SPDX-License-Identifier: MIT
/// @file
/// @brief A uniform grid of point indices (thesis 000 §3.10.1-3.10.2): about one point per
/// cell, cells in compressed rows, points removable (the grid method drops interior
/// vertices). Cells only narrow where to look; every decision is a predicate on the points.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::methods::detail {

class PointGrid {
public:
    /// Cell size sqrt(area / n) over the box enlarged by @p tol on every side, x_res =
    /// int(dx / size) + 1, y_res = int(dy / size) + 1 (R44); at most about 4n cells for very
    /// flat boxes. Points on the top or right border go to the cell below or left.
    PointGrid(const std::vector<Point3>& points, double tol) {
        Box2 box;
        for (const Point3& p : points) box.add(p);
        x0_ = box.xmin - tol;
        y0_ = box.ymin - tol;
        const double dx = box.xmax + tol - x0_;
        const double dy = box.ymax + tol - y0_;
        const double n = static_cast<double>(std::max<std::size_t>(points.size(), 1));
        size_ = std::sqrt(dx * dy / n);
        if (!(size_ > 0.0)) size_ = std::max(dx, dy) / n;
        size_ = std::max(size_, std::max(dx, dy) / (4.0 * n));  // at most ~4n cells
        if (!(size_ > 0.0)) size_ = 1.0;
        cols_ = static_cast<int>(dx / size_) + 1;
        rows_ = static_cast<int>(dy / size_) + 1;
        const auto cells = static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_);
        start_.assign(cells + 1, 0);
        std::vector<std::uint32_t> cell_of(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            cell_of[i] = static_cast<std::uint32_t>(index(col(points[i].x), row(points[i].y)));
            ++start_[cell_of[i] + 1];
        }
        for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
        live_.assign(cells, 0);
        items_.resize(points.size());
        pos_.resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::uint32_t c = cell_of[i];
            pos_[i] = start_[c] + live_[c]++;
            items_[pos_[i]] = static_cast<VertexIndex>(i);
        }
    }

    [[nodiscard]] int cols() const noexcept { return cols_; }
    [[nodiscard]] int rows() const noexcept { return rows_; }
    [[nodiscard]] double cell_size() const noexcept { return size_; }
    [[nodiscard]] double x0() const noexcept { return x0_; }
    [[nodiscard]] double y0() const noexcept { return y0_; }
    [[nodiscard]] int col(double x) const noexcept {
        const double c = std::floor((x - x0_) / size_);
        return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(cols_ - 1)));
    }
    [[nodiscard]] int row(double y) const noexcept {
        const double r = std::floor((y - y0_) / size_);
        return static_cast<int>(std::clamp(r, 0.0, static_cast<double>(rows_ - 1)));
    }
    [[nodiscard]] std::size_t index(int c, int r) const noexcept {
        return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) +
               static_cast<std::size_t>(c);
    }
    [[nodiscard]] std::size_t cells() const noexcept { return live_.size(); }

    /// Calls f(v) for every point still in cell (c, r).
    template <class F>
    void for_each(int c, int r, F&& f) const {
        const std::size_t k = index(c, r);
        const std::uint32_t b = start_[k];
        for (std::uint32_t i = 0; i < live_[k]; ++i) f(items_[b + i]);
    }
    [[nodiscard]] std::uint32_t count(int c, int r) const noexcept { return live_[index(c, r)]; }

    /// Removes point v (it is in the cell of its coordinates @p p).
    void remove(VertexIndex v, const Point3& p) noexcept {
        const std::size_t k = index(col(p.x), row(p.y));
        const std::uint32_t last = start_[k] + live_[k] - 1;
        const VertexIndex moved = items_[last];
        items_[pos_[v]] = moved;
        pos_[moved] = pos_[v];
        items_[last] = v;
        pos_[v] = last;
        --live_[k];
    }

    /// The points in cell order (row by row) before any removal: an order that keeps points of
    /// one cell, and of neighbouring cells in a row, together in memory.
    [[nodiscard]] const std::vector<VertexIndex>& cell_order() const noexcept { return items_; }

    [[nodiscard]] std::size_t bytes() const noexcept {
        return (start_.capacity() + live_.capacity() + pos_.capacity()) * sizeof(std::uint32_t) +
               items_.capacity() * sizeof(VertexIndex);
    }

private:
    double x0_ = 0.0;
    double y0_ = 0.0;
    double size_ = 1.0;
    int cols_ = 1;
    int rows_ = 1;
    std::vector<std::uint32_t> start_;
    std::vector<std::uint32_t> live_;
    std::vector<VertexIndex> items_;
    std::vector<std::uint32_t> pos_;
};

}  // namespace dtm::methods::detail
