// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: a uniform bucket grid over the triangles of a TIN, for the analyses that ask
/// "which triangles may touch this box" many times (overlay, profiles, point location).
///
/// Every triangle is listed in each cell its bounding box overlaps (a CSR array). The cell size
/// gives about two triangles per cell. The triangles' corners are copied next to each other in
/// the TIN's triangle order (spatially coherent), so a query reads them without the random
/// accesses into the vertex array that input-ordered vertices would cost. Cell lookup is a
/// monotone function of the coordinate, so a box that lies in two triangles' boxes lies in
/// cells that both are listed in (the overlay uses this to visit each candidate pair once).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// The corners of one triangle, counter-clockwise as in the TIN.
struct PackedTriangle {
    std::array<double, 3> x;
    std::array<double, 3> y;
    std::array<double, 3> z;
    [[nodiscard]] Box2 box() const noexcept {
        Box2 b;
        b.xmin = std::min({x[0], x[1], x[2]});
        b.xmax = std::max({x[0], x[1], x[2]});
        b.ymin = std::min({y[0], y[1], y[2]});
        b.ymax = std::max({y[0], y[1], y[2]});
        return b;
    }
};

class TriangleGrid {
public:
    TriangleGrid() = default;
    /// Indexes every triangle of @p tin (which must outlive the grid only for tin());
    /// @p cells_per_triangle tunes the cell size (cells ~ triangles x this).
    explicit TriangleGrid(const Tin& tin, double cells_per_triangle = 0.5);

    [[nodiscard]] bool empty() const noexcept { return triangles_.empty(); }
    [[nodiscard]] const PackedTriangle& triangle(TriangleIndex t) const { return triangles_[t]; }
    [[nodiscard]] std::size_t triangle_count() const noexcept { return triangles_.size(); }
    /// Bounding box of every triangle.
    [[nodiscard]] const Box2& bounds() const noexcept { return bounds_; }

    [[nodiscard]] std::size_t cols() const noexcept { return cols_; }
    [[nodiscard]] std::size_t rows() const noexcept { return rows_; }
    /// Column of @p x, clamped to the grid (monotone in x).
    [[nodiscard]] std::size_t col(double x) const noexcept { return clamp_cell((x - x0_) * inv_, cols_); }
    [[nodiscard]] std::size_t row(double y) const noexcept { return clamp_cell((y - y0_) * inv_, rows_); }
    /// The triangles listed in cell (col, row).
    [[nodiscard]] const TriangleIndex* cell_begin(std::size_t c, std::size_t r) const noexcept {
        return items_.data() + offsets_[r * cols_ + c];
    }
    [[nodiscard]] const TriangleIndex* cell_end(std::size_t c, std::size_t r) const noexcept {
        return items_.data() + offsets_[r * cols_ + c + 1];
    }
    /// Calls fn(t) for every triangle listed in a cell that @p box touches (a triangle listed in
    /// several such cells is passed several times).
    template <class Fn>
    void for_each_in_box(const Box2& box, Fn&& fn) const {
        if (empty() || box.xmax < bounds_.xmin || box.xmin > bounds_.xmax ||
            box.ymax < bounds_.ymin || box.ymin > bounds_.ymax) {
            return;
        }
        const std::size_t c0 = col(box.xmin);
        const std::size_t c1 = col(box.xmax);
        const std::size_t r0 = row(box.ymin);
        const std::size_t r1 = row(box.ymax);
        for (std::size_t r = r0; r <= r1; ++r) {
            for (std::size_t c = c0; c <= c1; ++c) {
                for (const TriangleIndex* it = cell_begin(c, r); it != cell_end(c, r); ++it) {
                    fn(*it);
                }
            }
        }
    }
    /// Approximate heap bytes held.
    [[nodiscard]] std::size_t memory_bytes() const noexcept {
        return triangles_.capacity() * sizeof(PackedTriangle) +
               (offsets_.capacity() + items_.capacity()) * sizeof(std::uint32_t);
    }

private:
    static std::size_t clamp_cell(double v, std::size_t n) noexcept {
        if (!(v > 0.0)) {
            return 0;
        }
        const double f = std::floor(v);
        return f >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(f);
    }

    std::vector<PackedTriangle> triangles_;
    Box2 bounds_;
    double x0_ = 0.0;
    double y0_ = 0.0;
    double inv_ = 1.0;
    std::size_t cols_ = 1;
    std::size_t rows_ = 1;
    std::vector<std::uint32_t> offsets_;
    std::vector<TriangleIndex> items_;
};

}  // namespace dtm::detail
