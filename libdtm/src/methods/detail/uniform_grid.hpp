// SPDX-License-Identifier: MIT
/// @file
/// @brief A uniform bucket grid over a box: cell of a point, cells a segment or a box may touch
/// (conservatively, one cell of margin for rounding), items per cell. Only a filter: every
/// decision is then taken by the exact predicates.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::methods::detail {

class UniformGrid {
public:
    UniformGrid() = default;
    /// A grid over @p box with about @p target_cells cells (at least 1).
    UniformGrid(const Box2& box, std::size_t target_cells) { reset(box, target_cells); }

    void reset(const Box2& box, std::size_t target_cells) {
        x0_ = box.xmin;
        y0_ = box.ymin;
        const double w = std::max(box.xmax - box.xmin, 0.0);
        const double h = std::max(box.ymax - box.ymin, 0.0);
        const double area = std::max(w * h, 1e-300);
        cell_ = std::sqrt(area / static_cast<double>(std::max<std::size_t>(target_cells, 1)));
        if (!(cell_ > 0.0) || !std::isfinite(cell_)) cell_ = std::max({w, h, 1.0});
        cell_ = std::max({cell_, w / 4096.0, h / 4096.0, 1e-300});
        cols_ = static_cast<int>(std::min(4096.0, std::floor(w / cell_) + 1));
        rows_ = static_cast<int>(std::min(4096.0, std::floor(h / cell_) + 1));
        cells_.assign(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_), {});
        row_bottom_.resize(static_cast<std::size_t>(rows_) + 1);
        for (int r = 0; r <= rows_; ++r) row_bottom_[static_cast<std::size_t>(r)] = y0_ + r * cell_;
    }

    [[nodiscard]] int cols() const noexcept { return cols_; }
    [[nodiscard]] int rows() const noexcept { return rows_; }
    [[nodiscard]] double cell_size() const noexcept { return cell_; }
    [[nodiscard]] int col(double x) const noexcept { return clamp((x - x0_) / cell_, cols_); }
    /// The row whose slab [bottom(r), bottom(r + 1)) holds y: consistent with the slab bounds the
    /// segment walks use, so a point's row is never off by one against them.
    [[nodiscard]] int row(double y) const noexcept {
        int r = clamp((y - y0_) / cell_, rows_);
        while (r > 0 && y < bottom(r)) --r;
        while (r + 1 < rows_ && y >= bottom(r + 1)) ++r;
        return r;
    }
    [[nodiscard]] double bottom(int r) const noexcept {
        return row_bottom_[static_cast<std::size_t>(r)];
    }
    [[nodiscard]] std::size_t index(int c, int r) const noexcept {
        return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) +
               static_cast<std::size_t>(c);
    }
    template <class P>
    [[nodiscard]] std::size_t cell_of(const P& p) const noexcept {
        return index(col(p.x), row(p.y));
    }

    void insert(std::size_t cell, std::uint32_t item) { cells_[cell].push_back(item); }
    template <class P>
    void insert_point(const P& p, std::uint32_t item) {
        insert(cell_of(p), item);
    }
    [[nodiscard]] const std::vector<std::uint32_t>& items(std::size_t cell) const noexcept {
        return cells_[cell];
    }
    [[nodiscard]] std::vector<std::uint32_t>& items(std::size_t cell) noexcept {
        return cells_[cell];
    }

    /// Calls f(cell) for every cell the segment pq may touch: the rows of its y range (exact:
    /// row() agrees with the slab bounds), in each the x range of the segment within the row's
    /// slab, widened by @p margin columns. Two segments that meet share a cell when one of them is
    /// walked with margin 1 (the rounding of the interpolated x is far below a cell); so does a
    /// point on a segment walked with margin 1.
    template <class P, class F>
    void for_segment_cells(const P& p, const P& q, F&& f, int margin = 1) const {
        const int r0 = row(std::min(p.y, q.y));
        const int r1 = row(std::max(p.y, q.y));
        const double dy = q.y - p.y;
        const double ylo = std::min(p.y, q.y);
        const double yhi = std::max(p.y, q.y);
        for (int r = r0; r <= r1; ++r) {
            double xa = std::min(p.x, q.x);
            double xb = std::max(p.x, q.x);
            if (dy != 0.0) {
                // The part of the segment in this row's slab (clamped to the segment's y range).
                const double ya = std::clamp(bottom(r), ylo, yhi);
                const double yb = std::clamp(bottom(r + 1), ylo, yhi);
                const double xa1 = p.x + (q.x - p.x) * ((ya - p.y) / dy);
                const double xb1 = p.x + (q.x - p.x) * ((yb - p.y) / dy);
                xa = std::max(xa, std::min(xa1, xb1));
                xb = std::min(xb, std::max(xa1, xb1));
            }
            const int c0 = std::max(0, col(xa) - margin);
            const int c1 = std::min(cols_ - 1, col(xb) + margin);
            for (int c = c0; c <= c1; ++c) f(index(c, r));
        }
    }

    /// Calls f(cell) for every cell of the box [xmin, xmax] x [ymin, ymax] (one cell of margin).
    template <class F>
    void for_box_cells(double xmin, double ymin, double xmax, double ymax, F&& f) const {
        const int c0 = std::max(0, col(xmin) - 1);
        const int c1 = std::min(cols_ - 1, col(xmax) + 1);
        const int r0 = std::max(0, row(ymin) - 1);
        const int r1 = std::min(rows_ - 1, row(ymax) + 1);
        for (int r = r0; r <= r1; ++r) {
            for (int c = c0; c <= c1; ++c) f(index(c, r));
        }
    }

private:
    static int clamp(double v, int n) noexcept {
        if (!(v > 0.0)) return 0;
        if (v >= n - 1) return n - 1;
        return static_cast<int>(v);
    }

    double x0_ = 0.0;
    double y0_ = 0.0;
    double cell_ = 1.0;
    int cols_ = 1;
    int rows_ = 1;
    std::vector<std::vector<std::uint32_t>> cells_{1};
    std::vector<double> row_bottom_{0.0, 1.0};
};

}  // namespace dtm::methods::detail
