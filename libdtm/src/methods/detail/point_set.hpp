// SPDX-License-Identifier: MIT
/// @file
/// @brief The input of a method made ready: distinct points (first of exact xy duplicates kept,
/// input order), segments mapped onto them, split where a point lies inside them, checked for
/// crossings. And a planar edge set made into a Tin.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "dtm/core/tin.hpp"
#include "dtm/methods/method.hpp"
#include "methods/detail/counting_predicates.hpp"

namespace dtm::methods::detail {

struct PreparedInput {
    std::vector<Point3> points;                ///< distinct, in input order
    std::vector<VertexIndex> input_to_vertex;  ///< per input point
    std::uint64_t duplicates = 0;
    /// Constraint segments between distinct points (a < b), sorted, split at points on them.
    std::vector<std::pair<VertexIndex, VertexIndex>> segments;
};

/// Merges exact duplicates and prepares the segments. @throws InputError naming @p method if a
/// segment names a missing point or two segments cross (or overlap).
[[nodiscard]] PreparedInput prepare_input(const MethodInput& input,
                                          std::string_view method,
                                          CountingPredicates& pred);

/// True when every point lies on one line (or there are fewer than 3).
[[nodiscard]] bool all_collinear(std::span<const Point3> points, CountingPredicates& pred);

/// Indices of the points on the convex hull boundary (collinear boundary points included),
/// counter-clockwise, starting at the lowest-leftmost point. @pre not all_collinear.
[[nodiscard]] std::vector<VertexIndex> hull_boundary(std::span<const Point3> points,
                                                     CountingPredicates& pred);

/// The Tin of a planar triangulation given by its undirected edges (any order): triangles are
/// the bounded faces, counter-clockwise, in order of their smallest directed edge; @p segments
/// become constraints. @throws std::logic_error if a bounded face is not a triangle.
[[nodiscard]] Tin tin_from_edges(std::span<const Point3> points,
                                 std::span<const std::pair<VertexIndex, VertexIndex>> edges,
                                 std::span<const std::pair<VertexIndex, VertexIndex>> segments,
                                 CountingPredicates& pred);

}  // namespace dtm::methods::detail
