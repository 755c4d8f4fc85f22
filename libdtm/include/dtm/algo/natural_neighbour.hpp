// SPDX-License-Identifier: MIT
/// @file
/// @brief Sibson's natural-neighbour interpolation on a (constrained) Delaunay TIN.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm {

/// Natural-neighbour (Sibson) interpolation: the height at p is the average of the heights of
/// p's natural neighbours weighted by the areas their Voronoi cells would lose to p if p were
/// inserted. Continuous everywhere, C1 except at the data points (C0 there), every vertex height
/// interpolated exactly. The insertion cavity (the triangles whose circumcircle contains p,
/// reached from p's triangle without crossing a barrier) is decided by the exact incircle
/// predicate; the areas are computed in floating point from circumcentres relative to p.
/// Barriers are the constrained edges (breaklines, boundaries, holes) and the border of the
/// TIN: a constrained Delaunay TIN is Delaunay in each region they bound, and on a barrier edge
/// the interpolation becomes the linear one along the edge, from both sides, so the surface
/// stays continuous across it (without being smooth there).
/// A cheap view: @p tin and @p barriers must outlive it. Not thread-safe with one Workspace.
class NaturalNeighbourSurface {
public:
    /// Scratch space of one thread.
    struct Workspace {
        std::vector<std::uint32_t> stamp;  ///< per triangle: epoch of the last cavity holding it
        std::uint32_t epoch = 0;
        std::vector<TriangleIndex> cavity;
        struct BorderEdge {
            TriangleIndex t;
            int corner;  ///< corner of t at the edge's first vertex (counter-clockwise)
        };
        std::vector<BorderEdge> border;
    };

    /// @p barriers: per triangle, bit e set when edge e (opposite v[e]) is a barrier (see
    /// natural_neighbour_barriers).
    NaturalNeighbourSurface(const Tin& tin, std::span<const std::uint8_t> barriers)
        : tin_(tin), barriers_(barriers) {}

    /// The height at (x, y), which lies in triangle @p t (inside or on its border).
    [[nodiscard]] double value(TriangleIndex t, double x, double y, Workspace& ws) const;

private:
    [[nodiscard]] bool barrier(TriangleIndex t, std::size_t e) const {
        return ((barriers_[t] >> e) & 1U) != 0 || tin_.triangles[t].n[e] == no_triangle;
    }
    [[nodiscard]] double linear(TriangleIndex t, double x, double y) const;

    const Tin& tin_;
    std::span<const std::uint8_t> barriers_;
};

/// Per triangle, bit e set when edge e is constrained (any ConstraintKind).
[[nodiscard]] std::vector<std::uint8_t> natural_neighbour_barriers(const Tin& tin);

}  // namespace dtm
