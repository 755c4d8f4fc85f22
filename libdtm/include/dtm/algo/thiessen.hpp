// SPDX-License-Identifier: MIT
/// @file
/// @brief Thiessen polygons: the Voronoi regions of survey points clipped to a region (a
/// boundary with holes, or the points' convex hull). Exact in its decisions: which part of the
/// region belongs to which point is decided by exact predicates on the input coordinates; only
/// the output coordinates of crossings and Voronoi vertices are computed.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// One polygon: rings[0] the outer ring counter-clockwise, then the holes clockwise; rings are
/// not closed (the first point is not repeated).
struct ThiessenPolygon {
    std::vector<std::vector<Point2>> rings;
};

struct ThiessenCell {
    std::vector<ThiessenPolygon> polygons;  ///< empty: the point's region misses the clip region
    double area = 0.0;
    /// The points whose cells share an edge of positive length with this one (sorted).
    std::vector<VertexIndex> neighbours;
};

struct ThiessenResult {
    std::vector<ThiessenCell> cells;  ///< one per site, in site order
    double region_area = 0.0;         ///< area of the clip region
    std::size_t empty_cells = 0;      ///< sites whose region misses the clip region
};

/// A triangulation of the clip region: the constrained triangulation of @p boundaries (closed
/// rings) minus @p holes, exactly as dtm's TIN domain treats them.
/// @throws InputError (from triangulate) for rings it cannot use.
[[nodiscard]] Tin clip_region_of_rings(std::span<const Polyline> boundaries,
                                       std::span<const Polyline> holes);

/// A triangulation of the convex hull of @p delaunay's vertices (its boundary, collinear
/// boundary vertices dropped). @throws InputError when the TIN has no triangle.
[[nodiscard]] Tin clip_region_of_hull(const Tin& delaunay);

/// The Thiessen polygons of @p sites (distinct points) clipped to @p region.
/// @param delaunay a Delaunay triangulation of the sites (vertex i is site i, neighbour links
///   set), or a Tin without triangles when the sites are collinear (or fewer than three).
/// @param region any triangulation of the clip region (counter-clockwise, neighbour links set).
/// @throws Cancelled.
[[nodiscard]] ThiessenResult thiessen_cells(std::span<const Point3> sites,
                                            const Tin& delaunay,
                                            const Tin& region,
                                            const Progress& progress = {});

}  // namespace dtm
