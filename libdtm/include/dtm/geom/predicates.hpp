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

/// Stage A bound of orient3d: Shewchuk's (7 + 56 eps) eps, eps^2 term raised for the guard.
inline constexpr double orient3d_bound_a = (7.0 + 64.0 * epsilon) * epsilon;
/// Stage A bound of the squared-distance comparison: 2 + 2 roundings per square sum, one
/// subtraction; (4 + 32 eps) eps covers them with room.
inline constexpr double distance_bound_a = (4.0 + 32.0 * epsilon) * epsilon;
inline constexpr double orient3d_underflow_guard = 0x1p-500;
inline constexpr double distance_underflow_guard = 0x1p-1000;

/// The exact paths of orient3d and compare_distances (predicates_space.cpp).
[[nodiscard]] int orient3d_exact(const double* a,
                                 const double* b,
                                 const double* c,
                                 const double* d) noexcept;
[[nodiscard]] int compare_distances_exact(double ax,
                                          double ay,
                                          double bx,
                                          double by,
                                          double cx,
                                          double cy,
                                          double dx,
                                          double dy) noexcept;

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
    // NaN/inf from overflow fail the test and go to the exact path. A det that passes is not 0
    // (bound >= 0), so its sign is +1 or -1, which lets `orient2d(...) > 0` compile to det > 0.
    if (std::abs(det) > bound) [[likely]] {
        return det > 0.0 ? 1 : -1;
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
        return det > 0.0 ? 1 : -1;  // not 0: see orient2d
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

/// Orientation of four points in space: +1 if d lies below the plane through a, b, c, "below"
/// meaning the side from which a, b, c do not appear counter-clockwise (a, b, c counter-
/// clockwise seen from above, d under them), -1 above, 0 coplanar: the sign of
/// det[a - d; b - d; c - d] (Shewchuk's convention). Exact for every finite double input.
[[nodiscard]] inline int orient3d(const Point3& a,
                                  const Point3& b,
                                  const Point3& c,
                                  const Point3& d) noexcept {
#if defined(__clang__)
#pragma clang fp contract(off)
#endif
    const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
    const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
    const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    constexpr double g = detail::orient3d_underflow_guard;
    const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy) + g) * (std::abs(adz) + g) +
                             (std::abs(cdxady) + std::abs(adxcdy) + g) * (std::abs(bdz) + g) +
                             (std::abs(adxbdy) + std::abs(bdxady) + g) * (std::abs(cdz) + g);
    const double bound = detail::orient3d_bound_a * permanent;
    if (std::abs(det) > bound) [[likely]] {
        return (det > 0.0) - (det < 0.0);
    }
    const double pa[3] = {a.x, a.y, a.z};
    const double pb[3] = {b.x, b.y, b.z};
    const double pc[3] = {c.x, c.y, c.z};
    const double pd[3] = {d.x, d.y, d.z};
    return detail::orient3d_exact(pa, pb, pc, pd);
}

/// orient3d of a, b, c, d lifted to the paraboloid z = x^2 + y^2, with the lifts taken exactly
/// (they are not doubles): +1 if the lift of d lies below the plane through the lifts of
/// a, b, c (seen with a, b, c counter-clockwise from above), -1 above, 0 coplanar. The lower
/// convex hull of the lifted points projects to the Delaunay triangulation (thesis 000
/// §2.4.4).
///
/// Exactly the in-circle sign: adding an affine function of (x, y) to z is a shear of
/// determinant 1, which changes no orientation, and lift(p) - lift(d) = lift(p - d) +
/// 2 d.(p - d) is such a function of p; so the lifted determinant equals
/// det[(a - d, |a - d|^2); (b - d, |b - d|^2); (c - d, |c - d|^2)], which is incircle's. Its
/// independent evaluation (big integers on the untranslated lifts) and CGAL agree in the tests.
template <class A, class B, class C, class D>
[[nodiscard]] inline int orient3d_lifted(const A& a, const B& b, const C& c, const D& d) noexcept {
    return incircle(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

/// Sign of |a - b|^2 - |c - d|^2 (distances in xy): -1 if a-b is the shorter, 0 equal, +1
/// longer. Exact for every finite double input.
[[nodiscard]] inline int compare_distances(double ax,
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
    const double abx = ax - bx, aby = ay - by, cdx = cx - dx, cdy = cy - dy;
    const double l1 = abx * abx + aby * aby;
    const double l2 = cdx * cdx + cdy * cdy;
    const double det = l1 - l2;
    const double bound = detail::distance_bound_a * (l1 + l2 + detail::distance_underflow_guard);
    if (std::abs(det) > bound) [[likely]] {
        return (det > 0.0) - (det < 0.0);
    }
    return detail::compare_distances_exact(ax, ay, bx, by, cx, cy, dx, dy);
}

template <class A, class B, class C, class D>
[[nodiscard]] inline int compare_distances(const A& a,
                                           const B& b,
                                           const C& c,
                                           const D& d) noexcept {
    return compare_distances(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

}  // namespace dtm::geom
