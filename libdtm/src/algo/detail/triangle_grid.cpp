// SPDX-License-Identifier: MIT
// The bucket grid of triangle_grid.hpp: two passes over the triangles (count per cell, prefix
// sums, fill), each triangle in the cells of its bounding box.
#include "algo/detail/triangle_grid.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <limits>
#include <stdexcept>

namespace dtm::detail {

std::vector<PackedTriangle> pack_triangles(const Tin& tin) {
    std::vector<PackedTriangle> out(tin.triangles.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), 4096),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t t = range.begin(); t != range.end(); ++t) {
                              PackedTriangle& p = out[t];
                              for (std::size_t k = 0; k < 3; ++k) {
                                  const VertexIndex i = tin.triangles[t].v[k];
                                  const Point3& v = tin.vertices[i];
                                  p.x[k] = v.x;
                                  p.y[k] = v.y;
                                  p.z[k] = v.z;
                                  p.v[k] = i;
                              }
                          }
                      });
    return out;
}

TriangleGrid::TriangleGrid(const Tin& tin, double cells_per_triangle)
    : triangles_(pack_triangles(tin)) {
    boxes_.resize(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
        boxes_[t] = triangles_[t].box();
        bounds_.add(boxes_[t].xmin, boxes_[t].ymin);
        bounds_.add(boxes_[t].xmax, boxes_[t].ymax);
    }
    if (triangles_.empty()) {
        offsets_.assign(5, 0);
        return;
    }
    const double width = std::max(bounds_.xmax - bounds_.xmin, 0.0);
    const double height = std::max(bounds_.ymax - bounds_.ymin, 0.0);
    const double cells = std::max(1.0, static_cast<double>(triangles_.size()) * cells_per_triangle);
    double cell = std::sqrt(width * height / cells);
    if (!(cell > 0.0)) {
        cell = std::max(width, height) / cells;
    }
    if (!(cell > 0.0) || !std::isfinite(cell)) {
        cell = 1.0;
    }
    // At most about 4 cells per triangle and 2^31 cells in all, whatever the shape.
    const double limit = std::min(4.0 * cells + 16.0, 2147483647.0);
    while ((std::floor(width / cell) + 1.0) * (std::floor(height / cell) + 1.0) > limit) {
        cell *= 1.25;
    }
    x0_ = bounds_.xmin;
    y0_ = bounds_.ymin;
    inv_ = 1.0 / cell;
    cols_ = static_cast<std::size_t>(std::floor(width * inv_)) + 1;
    rows_ = static_cast<std::size_t>(std::floor(height * inv_)) + 1;

    // Entries of cell k, group g go to [offsets_[4k + g], offsets_[4k + g + 1]).
    const auto group = [](std::size_t c, std::size_t r, std::size_t c0, std::size_t r0) {
        return c == c0 ? (r == r0 ? 1U : 0U) : (r == r0 ? 2U : 3U);
    };
    std::vector<std::uint32_t> counts(4 * cols_ * rows_ + 1, 0);
    std::size_t total = 0;
    for (const Box2& b : boxes_) {
        const std::size_t c0 = col(b.xmin);
        const std::size_t c1 = col(b.xmax);
        const std::size_t r0 = row(b.ymin);
        const std::size_t r1 = row(b.ymax);
        for (std::size_t r = r0; r <= r1; ++r) {
            for (std::size_t c = c0; c <= c1; ++c) {
                ++counts[4 * (r * cols_ + c) + group(c, r, c0, r0) + 1];
            }
        }
        total += (c1 - c0 + 1) * (r1 - r0 + 1);
    }
    if (total > std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("triangle grid: too many cell entries");
    }
    for (std::size_t i = 1; i < counts.size(); ++i) {
        counts[i] += counts[i - 1];
    }
    offsets_ = counts;
    items_.resize(total);
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
        const Box2& b = boxes_[t];
        const std::size_t c0 = col(b.xmin);
        const std::size_t c1 = col(b.xmax);
        const std::size_t r0 = row(b.ymin);
        const std::size_t r1 = row(b.ymax);
        for (std::size_t r = r0; r <= r1; ++r) {
            for (std::size_t c = c0; c <= c1; ++c) {
                items_[counts[4 * (r * cols_ + c) + group(c, r, c0, r0)]++] =
                    static_cast<TriangleIndex>(t);
            }
        }
    }
}

}  // namespace dtm::detail
