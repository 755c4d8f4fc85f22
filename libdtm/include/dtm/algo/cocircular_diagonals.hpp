// SPDX-License-Identifier: MIT
/// @file
/// @brief The data-dependent choice among the Delaunay TINs of a point set with cocircular
/// points: the TIN the smooth (cubic) interpolation is built on.
#pragma once

#include <cstddef>

#include "dtm/algo/criteria.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// Where four or more vertices lie exactly on one empty circle (lattice data: DEM cell centres,
/// grid surveys), every triangulation of their polygon is (constrained) Delaunay, and the
/// triangulator's pick is a symbolic tie-break that knows nothing of the heights. This flips the
/// unconstrained interior edges whose quadrilateral is cocircular (exact incircle == 0) while a
/// flip strictly lowers the exact sum of the data-dependent @p criterion cost (normal_jump or
/// normals_angle, criteria.hpp) over the quadrilateral's five edges: Dyn, Levin and Rippa's
/// local optimisation, restricted to the ties. The result is a (constrained) Delaunay TIN of the
/// same vertices and constraints (each flip keeps the common circumcircle of the triangles);
/// triangle indices are kept, only the triangles of flipped quadrilaterals change. Serial and
/// deterministic. Returns the number of flips (0 for a criterion that does not read z).
std::size_t choose_cocircular_diagonals(Tin& tin, Criterion criterion = Criterion::normal_jump);

/// True when choose_cocircular_diagonals would flip at least one edge of @p tin (no copy; on
/// points in general position, where no quadrilateral is cocircular, one pass of incircle tests).
[[nodiscard]] bool has_improvable_cocircular_edge(const Tin& tin,
                                                  Criterion criterion = Criterion::normal_jump);

}  // namespace dtm
