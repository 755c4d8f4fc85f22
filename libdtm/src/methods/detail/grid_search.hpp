// SPDX-License-Identifier: MIT
/// @file
/// @brief The third point of an oriented edge searched in a uniform grid (thesis 000 §3.10.3
/// step 2, §3.10.8.2), shared by uniform-grid and dewall.
///
/// Pass 1 scans the cells of the rectangle spanned by the cells of the edge's endpoints (the
/// thesis' adopted region, Fig. 28); pass 2, while nothing is found, adds rings of cells
/// around it towards the search side (the expansion passes), and stops with "hull edge" when
/// no cell beyond the scanned ones can reach that side; then rings keep growing until they
/// hold the bounding box of the current best circle's part on the search side, which shrinks
/// with every improvement (the dynamic circle box, Figs. 5 and 30). Candidates are judged by exact
/// predicates only (detail/third_point.hpp), which makes the thesis' eight direction cases one
/// half-plane test; the geometry of cells and circle boxes only decides where to look, with a
/// margin of a cell.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "methods/detail/point_grid.hpp"
#include "methods/detail/third_point.hpp"

namespace dtm::methods::detail {

class GridThirdPoint {
public:
    GridThirdPoint(const PointGrid& grid,
                   const std::vector<Point3>& points,
                   CountingPredicates& predicates)
        : grid_(grid), p_(points), third_(points, predicates), stamp_(grid.cells(), 0) {}

    /// The Delaunay third point left of a->b among the grid's points for which keep(v)
    /// holds, or no_vertex (a hull edge of those points).
    template <class Keep>
    VertexIndex find(VertexIndex a, VertexIndex b, Keep&& keep) {
        ++search_;
        if (search_ == 0) {  // the stamps wrapped: start over
            std::fill(stamp_.begin(), stamp_.end(), 0);
            search_ = 1;
        }
        third_.reset(a, b);
        boxed_ = no_vertex;
        a_ = {p_[a].x, p_[a].y};
        d_ = {p_[b].x - p_[a].x, p_[b].y - p_[a].y};
        dlen_ = std::sqrt(d_.x * d_.x + d_.y * d_.y);
        Rect r{std::min(grid_.col(p_[a].x), grid_.col(p_[b].x)),
               std::min(grid_.row(p_[a].y), grid_.row(p_[b].y)),
               std::max(grid_.col(p_[a].x), grid_.col(p_[b].x)),
               std::max(grid_.row(p_[a].y), grid_.row(p_[b].y))};
        scan(r, keep);
        for (;;) {
            Rect g = r;
            if (third_.found()) {
                // Rings outwards until they hold the box of the current circle's part left
                // of the edge (which only shrinks as the best improves).
                if (third_.best() != boxed_) {
                    boxed_ = third_.best();
                    box_ = cap_box(boxed_);
                }
                const Rect& box = box_;
                if (box.c0 >= r.c0 && box.c1 <= r.c1 && box.r0 >= r.r0 && box.r1 <= r.r1) break;
                g = {std::max(std::min(r.c0, box.c0), r.c0 - 1),
                     std::max(std::min(r.r0, box.r0), r.r0 - 1),
                     std::min(std::max(r.c1, box.c1), r.c1 + 1),
                     std::min(std::max(r.r1, box.r1), r.r1 + 1)};
            } else {
                // Towards the blocks beyond that can reach the left side; none: a hull edge.
                g = grow(r);
                if (g.c0 == r.c0 && g.c1 == r.c1 && g.r0 == r.r0 && g.r1 == r.r1) {
                    return no_vertex;
                }
            }
            scan_ring(r, g, keep);
            r = g;
        }
        return third_.choose();
    }

    [[nodiscard]] std::uint64_t cells_scanned() const noexcept { return cells_; }
    [[nodiscard]] std::size_t bytes() const noexcept {
        return stamp_.capacity() * sizeof(std::uint32_t);
    }

private:
    struct Rect {
        int c0, r0, c1, r1;
    };

    /// Some point of the cell rectangle may be strictly left of the edge (a cell's margin).
    [[nodiscard]] bool may_reach(int c0, int r0, int c1, int r1) const noexcept {
        const double s = grid_.cell_size();
        const double xs[2] = {grid_.x0() + c0 * s - s, grid_.x0() + (c1 + 1) * s + s};
        const double ys[2] = {grid_.y0() + r0 * s - s, grid_.y0() + (r1 + 1) * s + s};
        for (const double x : xs) {
            for (const double y : ys) {
                const double ux = x - a_.x, uy = y - a_.y;
                const double left = d_.x * uy - d_.y * ux;
                const double margin = 1e-9 * dlen_ * (std::abs(ux) + std::abs(uy));
                if (left > -margin) return true;
            }
        }
        return false;
    }

    /// r grown by one cell towards each of the four blocks beyond it (left and right: all
    /// rows; below and above: r's columns) that can reach the left side of the edge.
    [[nodiscard]] Rect grow(const Rect& r) const noexcept {
        const int cols = grid_.cols(), rows = grid_.rows();
        Rect g = r;
        if (r.c0 > 0 && may_reach(0, 0, r.c0 - 1, rows - 1)) g.c0 = r.c0 - 1;
        if (r.c1 < cols - 1 && may_reach(r.c1 + 1, 0, cols - 1, rows - 1)) g.c1 = r.c1 + 1;
        if (r.r0 > 0 && may_reach(g.c0, 0, g.c1, r.r0 - 1)) g.r0 = r.r0 - 1;
        if (r.r1 < rows - 1 && may_reach(g.c0, r.r1 + 1, g.c1, rows - 1)) g.r1 = r.r1 + 1;
        return g;
    }

    /// The cells of the bounding box of the part left of a->b of the circle through a, b and
    /// c, a cell wider: a, b and the circle's axis extremes on that side.
    [[nodiscard]] Rect cap_box(VertexIndex c) const noexcept {
        const double ex = p_[c].x - a_.x, ey = p_[c].y - a_.y;
        const double det = 2.0 * (d_.x * ey - d_.y * ex);
        const double l1 = d_.x * d_.x + d_.y * d_.y;
        const double l2 = ex * ex + ey * ey;
        const double ux = (ey * l1 - d_.y * l2) / det;
        const double uy = (d_.x * l2 - ex * l1) / det;
        const double rad = std::sqrt(ux * ux + uy * uy) * (1.0 + 1e-9);
        if (!std::isfinite(rad)) return {0, 0, grid_.cols() - 1, grid_.rows() - 1};
        Box2 box;
        box.add(0.0, 0.0);
        box.add(d_.x, d_.y);
        const double extremes[4][2] = {
            {ux - rad, uy}, {ux + rad, uy}, {ux, uy - rad}, {ux, uy + rad}};
        for (const auto& q : extremes) {
            const double left = d_.x * q[1] - d_.y * q[0];
            if (left > -1e-9 * dlen_ * (std::abs(q[0]) + std::abs(q[1]) + rad)) box.add(q[0], q[1]);
        }
        const double s = grid_.cell_size();
        return {grid_.col(a_.x + box.xmin - s), grid_.row(a_.y + box.ymin - s),
                grid_.col(a_.x + box.xmax + s), grid_.row(a_.y + box.ymax + s)};
    }

    template <class Keep>
    void scan_cell(int col, int row, Keep& keep) {
        std::uint32_t& s = stamp_[grid_.index(col, row)];
        if (s == search_) return;
        s = search_;
        if (grid_.count(col, row) == 0 || !may_reach(col, row, col, row)) return;
        ++cells_;
        grid_.for_each(col, row, [&](VertexIndex v) {
            if (keep(v)) third_.offer(v);
        });
    }
    template <class Keep>
    void scan(const Rect& r, Keep& keep) {
        for (int row = r.r0; row <= r.r1; ++row) {
            for (int col = r.c0; col <= r.c1; ++col) scan_cell(col, row, keep);
        }
    }
    /// The cells of g outside r (r inside g).
    template <class Keep>
    void scan_ring(const Rect& r, const Rect& g, Keep& keep) {
        for (int row = g.r0; row <= g.r1; ++row) {
            if (row < r.r0 || row > r.r1) {
                for (int col = g.c0; col <= g.c1; ++col) scan_cell(col, row, keep);
            } else {
                for (int col = g.c0; col < r.c0; ++col) scan_cell(col, row, keep);
                for (int col = r.c1 + 1; col <= g.c1; ++col) scan_cell(col, row, keep);
            }
        }
    }

    const PointGrid& grid_;
    const std::vector<Point3>& p_;
    ThirdPoint third_;
    std::vector<std::uint32_t> stamp_;
    std::uint32_t search_ = 0;
    std::uint64_t cells_ = 0;
    VertexIndex boxed_ = no_vertex;  ///< the best whose cap box is box_
    Rect box_{0, 0, 0, 0};
    Point2 a_;
    Point2 d_;
    double dlen_ = 0.0;
};

/// The exact nearest neighbour of point q among the grid's points for which keep(v) holds
/// (q itself excluded), by rings of cells around q's cell; a ring is scanned only while it can
/// hold a point closer than the best so far (the per-direction pruning of 000 §3.10.3), and
/// no farther than @p bound when bound >= 0. no_vertex if there is none.
template <class Keep>
VertexIndex nearest_in_grid(const PointGrid& grid,
                            const std::vector<Point3>& p,
                            CountingPredicates& pred,
                            VertexIndex q,
                            Keep&& keep,
                            double bound = -1.0) {
    const int qc = grid.col(p[q].x), qr = grid.row(p[q].y);
    const double s = grid.cell_size();
    VertexIndex best = no_vertex;
    double best_d = bound;  // an upper estimate of the best distance, for the pruning only
    auto consider = [&](VertexIndex v) {
        if (v == q || !keep(v)) return;
        if (bound >= 0.0) {
            const double dx = p[v].x - p[q].x, dy = p[v].y - p[q].y;
            if (std::sqrt(dx * dx + dy * dy) > bound * (1.0 + 1e-9)) return;
        }
        if (best == no_vertex || pred.compare_distances(p[q], p[v], p[q], p[best]) < 0) {
            const double dx = p[v].x - p[q].x, dy = p[v].y - p[q].y;
            best = v;
            best_d = std::sqrt(dx * dx + dy * dy) * (1.0 + 1e-9);
        }
    };
    grid.for_each(qc, qr, consider);
    const int rings = std::max(grid.cols(), grid.rows());
    for (int k = 1; k <= rings; ++k) {
        // Ring k lies at least (k - 1) cells beyond q's cell.
        if (best_d >= 0.0 && (k - 1) * s > best_d) break;
        const int r0 = qr - k, r1 = qr + k, c0 = qc - k, c1 = qc + k;
        for (int r = std::max(r0, 0); r <= std::min(r1, grid.rows() - 1); ++r) {
            if (r == r0 || r == r1) {
                for (int c = std::max(c0, 0); c <= std::min(c1, grid.cols() - 1); ++c) {
                    grid.for_each(c, r, consider);
                }
            } else {
                if (c0 >= 0) grid.for_each(c0, r, consider);
                if (c1 < grid.cols()) grid.for_each(c1, r, consider);
            }
        }
    }
    return best;
}

}  // namespace dtm::methods::detail
