// SPDX-License-Identifier: MIT
/// @file
/// @brief Splitting polygons into pseudo-triangles (thesis 001 §2.3, §3): the geodesic tangent
/// (findGeodesic), the splits of a face at a new point, the generalized flip's candidate borders
/// by brute force (getDiagonals, O(k^3)) and by the fast findDiagonal, and the nine criteria
/// that choose among them.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <string_view>
#include <vector>

#include "methods/detail/pseudo_mesh.hpp"

namespace dtm::methods::detail {

enum class PseudoCriterion : std::uint8_t {
    random,
    min_length,
    max_length,
    maxmin_angle,
    minmax_angle,
    maxmin_sum_angle,
    minmax_sum_angle,
    maxmin_angle_hull,
    minmax_angle_hull,
};
[[nodiscard]] std::optional<PseudoCriterion> parse_pseudo_criterion(std::string_view name);

/// One way to split a region: the faces it gives and the edges it adds (the border).
struct Split {
    std::vector<Cycle> faces;
    std::vector<std::pair<VertexIndex, VertexIndex>> border;
};

/// Corner angles of a face in radians: min, max and sum over its convex corners, and the min and
/// max angle of its virtual triangle (the triangle of its corners).
struct FaceAngles {
    double min = 0, max = 0, sum = 0, hull_min = 0, hull_max = 0;
};
[[nodiscard]] FaceAngles face_angles(std::span<const Point3> p,
                                     const Cycle& c,
                                     CountingPredicates& pred);

/// Compares two splits of the same region under @p criterion: +1 if @p a is strictly better.
/// Random is never better (0).
[[nodiscard]] int compare_splits(std::span<const Point3> p,
                                 const Split& a,
                                 const Split& b,
                                 PseudoCriterion criterion,
                                 CountingPredicates& pred);

/// The first vertex (position in @p c) of the geodesic from point @p x to the corner at position
/// @p corner: walk the side that hides x from the corner until an edge has x strictly on its
/// inner side (thesis 001 §2.1, findGeodesic; collinear counts as hidden).
[[nodiscard]] std::size_t geodesic_tangent(std::span<const Point3> p,
                                           const Cycle& c,
                                           std::size_t corner,
                                           const Point3& x,
                                           CountingPredicates& pred);

/// The splits of face @p c by two geodesics from the interior point @p q to two of its corners
/// (one per pair of corners; invalid pairs left out).
[[nodiscard]] std::vector<Split> point_splits(std::span<const Point3> p,
                                              const Cycle& c,
                                              VertexIndex q,
                                              CountingPredicates& pred);

/// Is @p c a pseudo-triangle: exactly three convex corners.
[[nodiscard]] bool is_pseudo_triangle(std::span<const Point3> p,
                                      const Cycle& c,
                                      CountingPredicates& pred);

/// Brute force (getDiagonals, Algorithm 3.2): every inner diagonal of the polygon @p q that
/// splits it into two pseudo-triangles, O(k^3); with an interior point @p in (two common edges),
/// every pair of segments from it that does, O(k^3).
[[nodiscard]] std::vector<Split> brute_splits(std::span<const Point3> p,
                                              const Cycle& q,
                                              VertexIndex in,
                                              CountingPredicates& pred);

/// The split of polygon @p q by the diagonal between positions @p i < @p j, if the diagonal is
/// inside (Table 3.2 at i, no crossing or touching of the boundary: Table 3.1) and both parts
/// are pseudo-triangles without a straight angle at its ends. O(k).
/// @p allow_straight accepts a straight angle at the ends (collinear input, where no other
/// split may exist: the vertex is then no corner, the part still has three).
[[nodiscard]] std::optional<Split> try_diagonal(std::span<const Point3> p,
                                                const Cycle& q,
                                                std::size_t i,
                                                std::size_t j,
                                                CountingPredicates& pred,
                                                bool allow_straight = false);

}  // namespace dtm::methods::detail
