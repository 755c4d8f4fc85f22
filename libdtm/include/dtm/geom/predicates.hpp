// SPDX-License-Identifier: MIT
/// @file
/// @brief Robust geometric predicates: the only geometric decisions in libdtm go through here.
///
/// Both return the exact sign of their determinant for every finite double input: a
/// floating-point filter decides almost every call; when it cannot, adaptive exact arithmetic
/// (Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust geometric
/// predicates") takes over. 2.5-D: only x and y are read.
#pragma once

#include "dtm/core/point.hpp"

namespace dtm::geom {

/// Sign of the orientation determinant of (a, b, c):
/// +1 counter-clockwise (c left of a->b), -1 clockwise, 0 collinear. Exact.
[[nodiscard]] int orient2d(double ax, double ay, double bx, double by, double cx,
                           double cy) noexcept;

/// +1 if d lies strictly inside the circle through a, b, c (given counter-clockwise),
/// -1 if strictly outside, 0 if on it (sign flips for clockwise a, b, c). Exact.
[[nodiscard]] int incircle(double ax, double ay, double bx, double by, double cx, double cy,
                           double dx, double dy) noexcept;

template <class P>
[[nodiscard]] inline int orient2d(const P& a, const P& b, const P& c) noexcept
{
    return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

template <class P>
[[nodiscard]] inline int incircle(const P& a, const P& b, const P& c, const P& d) noexcept
{
    return incircle(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

}  // namespace dtm::geom
