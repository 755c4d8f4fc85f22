// SPDX-License-Identifier: MIT
/// @file
/// @brief Invariant checkers for a Tin, used by tests and `dtm tin --check`.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "dtm/algo/criteria.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// What a check found. ok() when problems is empty; at most a few problems are listed.
struct CheckReport {
    std::vector<std::string> problems;
    [[nodiscard]] bool ok() const noexcept { return problems.empty(); }
    [[nodiscard]] std::string text() const;
};

/// Manifold, counter-clockwise, non-degenerate triangles, symmetric neighbour links, valid indices,
/// constrained edges are TIN edges.
[[nodiscard]] CheckReport verify_topology(const Tin& tin);

/// Exact constrained Delaunay property: for every edge shared by two triangles that is not
/// constrained, the opposite vertex is not strictly inside the other triangle's circumcircle.
[[nodiscard]] CheckReport verify_constrained_delaunay(const Tin& tin);

/// Every segment of every polyline of @p input (breaklines, soft breaklines, boundaries, holes) is
/// present as a chain of constrained TIN edges along it: through vertices exactly on it (or
/// within rounding of it, 1 um + 1e-9 of its length, where crossings split it) and vertices
/// added at crossings. A segment that leaves the surface (an end beyond the boundary or in a
/// hole, or on its way out through the boundary and back) is required only where it lies on it.
/// Polyline vertices are found by position, or through @p input_to_vertex
/// (TriangulateResult::input_to_vertex) when given, which is needed when points were snapped.
[[nodiscard]] CheckReport verify_constraints(const Tin& tin,
                                             const TerrainInput& input,
                                             std::span<const VertexIndex> input_to_vertex = {});

/// The whole check of a TIN made from @p input (`dtm tin --check`): verify_topology, then the
/// exact constrained Delaunay property, or for a TIN optimised under another @p criterion local
/// optimality of every unconstrained edge (the first five offenders listed), then
/// verify_constraints; the problems of all three in that order.
[[nodiscard]] CheckReport verify_tin(const Tin& tin,
                                     const TerrainInput& input,
                                     std::span<const VertexIndex> input_to_vertex,
                                     Criterion criterion = Criterion::delaunay);

/// Sum of triangle areas in xy (compensated summation).
[[nodiscard]] double tin_area(const Tin& tin);

}  // namespace dtm
