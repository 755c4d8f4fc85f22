// SPDX-License-Identifier: MIT
/// @file
/// @brief Robust geometric predicates: the only geometric decisions in libdtm go through here.
///
/// Both return the exact sign of their determinant for every finite double input: a
/// floating-point filter decides almost every call; when it cannot, adaptive exact arithmetic
/// (Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust geometric
/// predicates") takes over. 2.5-D: only x and y are read.
///
/// The filter (Shewchuk's stage A) is inline below so that the common case costs a handful of
/// multiplications and one well-predicted branch; the adaptive stages B, C, D and an exact
/// big-integer fallback for extreme magnitudes live out of line in src/geom/predicates.cpp.
/// See docs/algorithms/predicates.md for the error bounds and why they hold.
#pragma once

#include <cmath>

#include "dtm/core/point.hpp"

namespace dtm::geom {

namespace detail {

/// Half an ulp of 1.0: the relative rounding error of one IEEE-754 double operation.
inline constexpr double epsilon = 0x1p-53;
/// Stage A bound of orient2d. Shewchuk's (3 + 16 eps) eps, with the eps^2 term raised to 24 to
/// cover the one extra rounding of the underflow guard below.
inline constexpr double orient_bound_a = (3.0 + 24.0 * epsilon) * epsilon;
/// Stage A bound of incircle. Shewchuk's (10 + 96 eps) eps, eps^2 term raised for the guards.
inline constexpr double incircle_bound_a = (10.0 + 128.0 * epsilon) * epsilon;
/// Absolute terms added to the filter's magnitude sums so that products which underflow
/// (absolute error up to 2^-1075 each, which a relative bound does not cover) can never let a
/// wrong sign through. They only matter for coordinate differences below ~2^-200.
inline constexpr double orient_underflow_guard = 0x1p-1000;
inline constexpr double incircle_underflow_guard = 0x1p-500;

/// Stages B-D of orient2d; `detsum` is |detleft| + |detright| from stage A. Exact.
[[nodiscard]] int orient2d_adaptive(
    double ax, double ay, double bx, double by, double cx, double cy, double detsum) noexcept;
/// Stages B-D of incircle; `permanent` is the stage A magnitude bound. Exact.
[[nodiscard]] int incircle_adaptive(double ax,
                                    double ay,
                                    double bx,
                                    double by,
                                    double cx,
                                    double cy,
                                    double dx,
                                    double dy,
                                    double permanent) noexcept;

}  // namespace detail

/// Sign of the orientation determinant of (a, b, c):
/// +1 counter-clockwise (c left of a->b), -1 clockwise, 0 collinear. Exact.
[[nodiscard]] inline int orient2d(
    double ax, double ay, double bx, double by, double cx, double cy) noexcept {
#if defined(__clang__)
#pragma clang fp contract(off)
#endif
    const double detleft = (ax - cx) * (by - cy);
    const double detright = (ay - cy) * (bx - cx);
    const double det = detleft - detright;
    const double detsum = std::abs(detleft) + std::abs(detright);
    const double bound = detail::orient_bound_a * (detsum + detail::orient_underflow_guard);
    // NaN/inf from overflow fail the test and go to the exact path.
    if (std::abs(det) > bound) [[likely]] {
        return (det > 0.0) - (det < 0.0);
    }
    return detail::orient2d_adaptive(ax, ay, bx, by, cx, cy, detsum);
}

/// +1 if d lies strictly inside the circle through a, b, c (given counter-clockwise),
/// -1 if strictly outside, 0 if on it (sign flips for clockwise a, b, c). Exact.
[[nodiscard]] inline int incircle(double ax,
                                  double ay,
                                  double bx,
                                  double by,
                                  double cx,
                                  double cy,
                                  double dx,
                                  double dy) noexcept {
#if defined(__clang__)
#pragma clang fp contract(off)
#endif
    const double adx = ax - dx;
    const double ady = ay - dy;
    const double bdx = bx - dx;
    const double bdy = by - dy;
    const double cdx = cx - dx;
    const double cdy = cy - dy;

    const double bdxcdy = bdx * cdy;
    const double cdxbdy = cdx * bdy;
    const double alift = adx * adx + ady * ady;
    const double cdxady = cdx * ady;
    const double adxcdy = adx * cdy;
    const double blift = bdx * bdx + bdy * bdy;
    const double adxbdy = adx * bdy;
    const double bdxady = bdx * ady;
    const double clift = cdx * cdx + cdy * cdy;

    const double det =
        alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    constexpr double g = detail::incircle_underflow_guard;
    const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy) + g) * (alift + g) +
                             (std::abs(cdxady) + std::abs(adxcdy) + g) * (blift + g) +
                             (std::abs(adxbdy) + std::abs(bdxady) + g) * (clift + g);
    const double bound = detail::incircle_bound_a * permanent;
    if (std::abs(det) > bound) [[likely]] {
        return (det > 0.0) - (det < 0.0);
    }
    return detail::incircle_adaptive(ax, ay, bx, by, cx, cy, dx, dy, permanent);
}

/// Point overloads: any types with x and y members (Point2, Point3, ...), mixed freely.
template <class A, class B, class C>
[[nodiscard]] inline int orient2d(const A& a, const B& b, const C& c) noexcept {
    return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

template <class A, class B, class C, class D>
[[nodiscard]] inline int incircle(const A& a, const B& b, const C& c, const D& d) noexcept {
    return incircle(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

/// Sign of |ab|^2 - |cd|^2: +1 if a, b are farther apart than c, d, -1 if closer, 0 if equally
/// far. Exact for every finite input (a floating-point filter, then big integers); the greedy
/// triangulation and the shortest-diagonal criterion order edges by it.
[[nodiscard]] int compare_distance(double ax,
                                   double ay,
                                   double bx,
                                   double by,
                                   double cx,
                                   double cy,
                                   double dx,
                                   double dy) noexcept;

template <class A, class B, class C, class D>
[[nodiscard]] inline int compare_distance(const A& a, const B& b, const C& c, const D& d) noexcept {
    return compare_distance(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

}  // namespace dtm::geom
