// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact predicates on perpendicular bisectors, for clipping Voronoi regions: on which
/// side of a bisector the crossing of a segment with another bisector lies, and the sign of a
/// dot product of differences. (Which of two sites a point is nearer to is
/// geom::compare_distances, predicates.hpp.)
///
/// Like orient2d and incircle (predicates.hpp) they return the exact sign for every finite
/// double input: a floating-point evaluation with a running error bound decides almost every
/// call, big-integer arithmetic (geom/detail/bigint.hpp) the rest. 2.5-D: only x and y are read.
#pragma once

#include "dtm/core/point.hpp"

namespace dtm::geom {

/// Sign of (b - a) . (d - c), the dot product of two differences.
[[nodiscard]] int dot_sign(double ax,
                           double ay,
                           double bx,
                           double by,
                           double cx,
                           double cy,
                           double dx,
                           double dy) noexcept;

/// The segment a-b crosses the bisector of g and h at X (precondition: a and b lie strictly on
/// opposite sides of it, compare_distances(a, g, a, h) == -compare_distances(b, g, b, h) != 0).
/// Returns the sign of |X - g|^2 - |X - k|^2: on which side of the bisector of g and k that
/// crossing lies (-1 nearer g). Degree 4 in the coordinates.
[[nodiscard]] int crossing_order(
    const Point2& a, const Point2& b, const Point2& g, const Point2& h, const Point2& k) noexcept;

template <class A, class B, class C, class D>
[[nodiscard]] inline int dot_sign(const A& a, const B& b, const C& c, const D& d) noexcept {
    return dot_sign(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

}  // namespace dtm::geom
