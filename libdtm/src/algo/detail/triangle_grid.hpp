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
#include <utility>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// The corners of one triangle, counter-clockwise as in the TIN.
struct PackedTriangle {
    std::array<double, 3> x;
    std::array<double, 3> y;
    std::array<double, 3> z;
    std::array<VertexIndex, 3> v;
    [[nodiscard]] Box2 box() const noexcept {
        Box2 b;
        b.xmin = std::min({x[0], x[1], x[2]});
        b.xmax = std::max({x[0], x[1], x[2]});
        b.ymin = std::min({y[0], y[1], y[2]});
        b.ymax = std::max({y[0], y[1], y[2]});
        return b;
    }
};

/// Height of @p t's plane at (px, py) (barycentric, relative to its first corner).
inline double plane_height(const PackedTriangle& t, double px, double py) {
    const double ux = t.x[1] - t.x[0];
    const double uy = t.y[1] - t.y[0];
    const double vx = t.x[2] - t.x[0];
    const double vy = t.y[2] - t.y[0];
    const double qx = px - t.x[0];
    const double qy = py - t.y[0];
    const double d = ux * vy - uy * vx;
    if (d == 0.0) {
        return t.z[0];
    }
    const double l1 = (qx * vy - qy * vx) / d;
    const double l2 = (ux * qy - uy * qx) / d;
    return t.z[0] + l1 * (t.z[1] - t.z[0]) + l2 * (t.z[2] - t.z[0]);
}

/// Height along the edge between corners @p a and @p b of @p t at (px, py), interpolated from
/// the end with the smaller vertex index, so both triangles of the edge give the same bits.
inline double edge_height(
    const PackedTriangle& t, std::size_t a, std::size_t b, double px, double py) {
    if (t.v[b] < t.v[a]) {
        std::swap(a, b);
    }
    const double ex = t.x[b] - t.x[a];
    const double ey = t.y[b] - t.y[a];
    const double len2 = ex * ex + ey * ey;
    const double s = len2 > 0.0 ? ((px - t.x[a]) * ex + (py - t.y[a]) * ey) / len2 : 0.0;
    return t.z[a] + std::clamp(s, 0.0, 1.0) * (t.z[b] - t.z[a]);
}

/// Height of @p t at a point of the closed triangle whose orientations against t's edges (edge
/// k: corner k to corner k + 1) are @p signs: a corner's own height, interpolation along an edge
/// the point lies on, or the plane inside. The same bits from every triangle sharing the place.
inline double height_at(const PackedTriangle& t,
                        const std::array<int, 3>& signs,
                        double px,
                        double py) {
    for (std::size_t k = 0; k < 3; ++k) {
        if (t.x[k] == px && t.y[k] == py) {
            return t.z[k];
        }
    }
    for (std::size_t k = 0; k < 3; ++k) {
        if (signs[k] == 0) {
            return edge_height(t, k, (k + 1) % 3, px, py);
        }
    }
    return plane_height(t, px, py);
}

/// The triangles of @p tin with their corners copied in (parallel).
[[nodiscard]] std::vector<PackedTriangle> pack_triangles(const Tin& tin);

class TriangleGrid {
public:
    TriangleGrid() = default;
    /// Indexes every triangle of @p tin (which must outlive the grid only for tin());
    /// @p cells_per_triangle tunes the cell size (cells ~ triangles x this).
    explicit TriangleGrid(const Tin& tin, double cells_per_triangle = 0.5);

    [[nodiscard]] bool empty() const noexcept { return triangles_.empty(); }
    [[nodiscard]] const PackedTriangle& triangle(TriangleIndex t) const { return triangles_[t]; }
    [[nodiscard]] std::size_t triangle_count() const noexcept { return triangles_.size(); }
    /// Bounding box of triangle @p t.
    [[nodiscard]] const Box2& box(TriangleIndex t) const { return boxes_[t]; }
    /// Bounding box of every triangle.
    [[nodiscard]] const Box2& bounds() const noexcept { return bounds_; }

    [[nodiscard]] std::size_t cols() const noexcept { return cols_; }
    [[nodiscard]] std::size_t rows() const noexcept { return rows_; }
    /// Column of @p x, clamped to the grid (monotone in x).
    [[nodiscard]] std::size_t col(double x) const noexcept {
        return clamp_cell((x - x0_) * inv_, cols_);
    }
    [[nodiscard]] std::size_t row(double y) const noexcept {
        return clamp_cell((y - y0_) * inv_, rows_);
    }
    /// Calls fn(t) once for every triangle whose cell range overlaps the cell range of @p box
    /// (a superset of the triangles whose boxes overlap it). Each cell keeps its triangles in four
    /// groups by whether the cell is the first column and/or the first row of the triangle's
    /// range; a pair of ranges overlaps in exactly one cell that is the first column of one of
    /// them and the first row of one of them, so scanning the right groups visits each
    /// triangle once, with no duplicate test.
    template <class Fn>
    void for_each_candidate(const Box2& box, Fn&& fn) const {
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
                const std::uint32_t* off = offsets_.data() + 4 * (r * cols_ + c);
                // Groups: 0 first column only, 1 first column and first row, 2 first row only,
                // 3 neither. Beyond the box's first column the triangle must start in this
                // column (groups 0, 1); beyond its first row, in this row (groups 1, 2).
                const std::size_t first = r == r0 ? 0 : 1;
                const std::size_t last = c == c0 ? (r == r0 ? 4 : 3) : 2;
                const std::uint32_t* begin = items_.data() + off[first];
                const std::uint32_t* end = items_.data() + off[last];
                for (const std::uint32_t* it = begin; it < end; ++it) {
                    fn(*it);
                }
            }
        }
    }
    /// Approximate heap bytes held.
    [[nodiscard]] std::size_t memory_bytes() const noexcept {
        return triangles_.capacity() * sizeof(PackedTriangle) + boxes_.capacity() * sizeof(Box2) +
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
    std::vector<Box2> boxes_;
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
