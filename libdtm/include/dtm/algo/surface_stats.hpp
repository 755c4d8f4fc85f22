// SPDX-License-Identifier: MIT
/// @file
/// @brief Summary measures of a TIN surface: planimetric and 3-D area, extent and z range.
#pragma once

#include <cstddef>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct SurfaceStats {
    std::size_t vertex_count = 0;
    std::size_t triangle_count = 0;
    std::size_t constraint_count = 0;
    /// Extent of the vertices that some triangle uses (unused vertices are not part of the
    /// surface).
    Box2 extent;
    double z_min = 0.0;  ///< over the used vertices; 0 when the TIN has no triangle
    double z_max = 0.0;
    double planimetric_area = 0.0;  ///< sum of triangle areas projected on the xy plane
    double surface_area = 0.0;      ///< sum of the true 3-D triangle areas (>= planimetric_area)
};

/// Measures @p tin. Areas are exact sums rounded once (order-free) with coordinates taken
/// relative to the first vertex, so large projected offsets (S-JTSK, UTM) cost no precision.
[[nodiscard]] SurfaceStats surface_stats(const Tin& tin);

/// What became of a group of input points (every one is counted exactly once).
struct PointFate {
    std::size_t total = 0;
    std::size_t used = 0;     ///< became a vertex of some triangle
    std::size_t merged = 0;   ///< merged into another input point (duplicate or snapped)
    std::size_t removed = 0;  ///< its vertex lies outside the boundary, in a hole, or was trimmed
};

/// Where every input point of a triangulation went, split into survey points and line vertices
/// (breakline, soft breakline, boundary and hole vertices), in TriangulateResult's input order.
struct InputAccounting {
    PointFate survey_points;
    PointFate line_vertices;
};

/// Accounts for every entry of result.input_to_vertex. The first @p survey_point_count entries
/// are survey points. A merged point counts as merged even if the point it merged into was
/// later removed; a point that is not merged counts as used when some triangle has its vertex.
[[nodiscard]] InputAccounting account_inputs(const TriangulateResult& result,
                                             std::size_t survey_point_count);

}  // namespace dtm
