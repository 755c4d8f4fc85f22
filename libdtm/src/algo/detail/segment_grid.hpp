// SPDX-License-Identifier: MIT
/// @file
/// @brief Which constraint segments touch others: a uniform grid over the segments' boxes and an
/// exact touch test, shared by the crossing pre-pass (segment_split) and the insertion
/// (constraint_batch). Templates over `point(v)`, which gives vertex v's position (x, y).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <vector>

#include "algo/detail/input_merge.hpp"
#include "dtm/core/point.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {

/// q is in the closed box of a and b.
template <class P, class Q>
bool in_box(const P& a, const P& b, const Q& q) {
    return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
           q.y <= std::max(a.y, b.y);
}

/// s and t join the same two vertices (in either direction).
inline bool same_segment(const InputSegment& s, const InputSegment& t) {
    return (s.a == t.a && s.b == t.b) || (s.a == t.b && s.b == t.a);
}

/// Segments s and t meet anywhere but at one shared endpoint: they cross, overlap, are equal, or
/// an endpoint of one lies inside the other (a T-junction). Exact predicates only.
template <class PointOf>
bool segments_touch(const PointOf& point, const InputSegment& s, const InputSegment& t) {
    const VertexIndex shared =
        s.a == t.a || s.a == t.b ? s.a : (s.b == t.a || s.b == t.b ? s.b : ~VertexIndex{0});
    if (shared != ~VertexIndex{0}) {
        if (same_segment(s, t)) return true;
        const VertexIndex x = s.a == shared ? s.b : s.a;
        const VertexIndex y = t.a == shared ? t.b : t.a;
        const auto &c = point(shared), &px = point(x), &py = point(y);
        if (geom::orient2d(c, px, py) != 0) return false;
        // Collinear: they overlap unless they leave the shared endpoint in opposite directions.
        return ((px.x > c.x) == (py.x > c.x)) && ((px.x < c.x) == (py.x < c.x)) &&
               ((px.y > c.y) == (py.y > c.y)) && ((px.y < c.y) == (py.y < c.y));
    }
    const auto &a = point(s.a), &b = point(s.b), &c = point(t.a), &d = point(t.b);
    const int o1 = geom::orient2d(a, b, c);
    const int o2 = geom::orient2d(a, b, d);
    const int o3 = geom::orient2d(c, d, a);
    const int o4 = geom::orient2d(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && in_box(a, b, c)) || (o2 == 0 && in_box(a, b, d)) ||
           (o3 == 0 && in_box(c, d, a)) || (o4 == 0 && in_box(c, d, b));
}

/// The segments listed by grid cell: cell c lists listed[start[c] .. start[c + 1]).
struct SegmentGrid {
    std::vector<std::uint32_t> start;
    std::vector<std::uint32_t> listed;
    [[nodiscard]] std::size_t cells() const noexcept {
        return start.empty() ? 0 : start.size() - 1;
    }
};

/// A uniform grid over the segments' extent, about one cell per segment; each segment is listed in
/// every cell its bounding box covers (counting sort, cell-major), so two segments that touch
/// share a cell.
template <class PointOf>
SegmentGrid segment_grid(const std::vector<InputSegment>& segments, const PointOf& point) {
    const std::size_t count = segments.size();
    // The boxes first, in parallel (the endpoints are scattered over the points); everything
    // after reads them in order.
    std::vector<std::array<double, 4>> boxes(count);  // x min, x max, y min, y max
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
        const auto &a = point(segments[i].a), &b = point(segments[i].b);
        boxes[i] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
    });
    Box2 box;
    double total_length = 0.0;
    for (const auto& [x0, x1, y0, y1] : boxes) {
        box.add(x0, y0);
        box.add(x1, y1);
        total_length += (x1 - x0) + (y1 - y0);
    }
    const double extent = std::max(box.xmax - box.xmin, box.ymax - box.ymin);
    // At most about one cell per segment (a segment's box meets few cells, and the counting sort
    // is not swamped by empty cells on large inputs).
    const double per_segment = std::sqrt((box.xmax - box.xmin) * (box.ymax - box.ymin) /
                                         static_cast<double>(std::max<std::size_t>(count, 1)));
    const double cell =
        std::max({total_length / static_cast<double>(std::max<std::size_t>(count, 1)), per_segment,
                  extent / 4096.0, extent * 1e-12, 1e-300});
    const auto cols = static_cast<std::size_t>((box.xmax - box.xmin) / cell) + 1;
    const auto rows = static_cast<std::size_t>((box.ymax - box.ymin) / cell) + 1;
    const auto cell_of = [&](double v, double lo, std::size_t n) {
        return std::min(static_cast<std::size_t>((v - lo) / cell), n - 1);
    };
    const auto cell_range = [&](std::size_t i) {
        const auto& [x0, x1, y0, y1] = boxes[i];
        return std::array<std::size_t, 4>{cell_of(x0, box.xmin, cols), cell_of(x1, box.xmin, cols),
                                          cell_of(y0, box.ymin, rows), cell_of(y1, box.ymin, rows)};
    };
    const std::size_t cells = count == 0 ? 0 : cols * rows;
    SegmentGrid grid;
    grid.start.assign(cells + 1, 0);
    // Counted and scattered by all threads (atomic increments): the order of the segments within
    // a cell then varies from run to run, which changes nothing for the callers (the touching
    // pairs are sorted, the free flags only ever go from free to not free).
    const auto each_cell = [&](std::size_t i, const auto& body) {
        const auto [c0, c1, r0, r1] = cell_range(i);
        for (std::size_t r = r0; r <= r1; ++r) {
            for (std::size_t c = c0; c <= c1; ++c) body(r * cols + c);
        }
    };
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1 << 12), [&](const auto& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            each_cell(i, [&](std::size_t c) {
                std::atomic_ref<std::uint32_t>(grid.start[c + 1])
                    .fetch_add(1, std::memory_order_relaxed);
            });
        }
    });
    for (std::size_t c = 0; c < cells; ++c) grid.start[c + 1] += grid.start[c];
    grid.listed.resize(grid.start[cells]);
    std::vector<std::uint32_t> at(grid.start.begin(), grid.start.end() - 1);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1 << 12), [&](const auto& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            each_cell(i, [&](std::size_t c) {
                const std::uint32_t k =
                    std::atomic_ref<std::uint32_t>(at[c]).fetch_add(1, std::memory_order_relaxed);
                grid.listed[k] = static_cast<std::uint32_t>(i);
            });
        }
    });
    return grid;
}

}  // namespace dtm::detail
