// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact predicates on perpendicular bisectors, for Voronoi diagrams and their clipping:
/// which of two sites a point is nearer to, and on which side of a third bisector the crossing
/// of a segment with a bisector lies.
///
/// Like orient2d and incircle (predicates.hpp) they return the exact sign for every finite
/// double input: a floating-point evaluation with a running error bound decides almost every
/// call, big-integer arithmetic (geom/detail/bigint.hpp) the rest. 2.5-D: only x and y are read.
#pragma once

#include "dtm/core/point.hpp"

namespace dtm::geom {

/// Sign of |p - a|^2 - |p - b|^2: -1 when p is nearer to a, +1 nearer to b, 0 on the bisector.
[[nodiscard]] int distance_order(
    double px, double py, double ax, double ay, double bx, double by) noexcept;

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
/// opposite sides of it, distance_order(a, g, h) == -distance_order(b, g, h) != 0). Returns
/// distance_order(X, g, k): on which side of the bisector of g and k that crossing lies. Degree
/// 4 in the coordinates.
[[nodiscard]] int crossing_order(
    const Point2& a, const Point2& b, const Point2& g, const Point2& h, const Point2& k) noexcept;

template <class P, class A, class B>
[[nodiscard]] inline int distance_order(const P& p, const A& a, const B& b) noexcept {
    return distance_order(p.x, p.y, a.x, a.y, b.x, b.y);
}

template <class A, class B, class C, class D>
[[nodiscard]] inline int dot_sign(const A& a, const B& b, const C& c, const D& d) noexcept {
    return dot_sign(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

}  // namespace dtm::geom
