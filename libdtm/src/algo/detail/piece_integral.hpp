// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the closed-form integral of a linear function d over a convex polygon, split
/// at d = 0 into its positive and negative parts (volume.cpp, sections.cpp).
///
/// The part where d >= 0 (and the part where d <= 0) of a convex polygon is convex; its corners
/// are the polygon's corners on that side and the zeros of the edges whose ends have strictly
/// opposite signs (t = d_i / (d_i - d_j)). Over a convex polygon a linear function integrates
/// exactly as the sum over the fan triangles (q0, qi, qi+1) of area x mean of the corner values.
#pragma once

#include <array>
#include <cstddef>

namespace dtm::detail {

/// A polygon corner: plan coordinates (relative to a nearby origin) and the value of d.
struct LinearCorner {
    double x;
    double y;
    double d;
};

struct AreaIntegral {
    double area = 0.0;
    double integral = 0.0;
};

/// Area and integral of d over the convex polygon @p p (counter-clockwise, @p n corners).
inline AreaIntegral integrate_polygon(const LinearCorner* p, std::size_t n) {
    AreaIntegral r;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double a = 0.5 * ((p[i].x - p[0].x) * (p[i + 1].y - p[0].y) -
                                (p[i].y - p[0].y) * (p[i + 1].x - p[0].x));
        r.area += a;
        r.integral += a * (p[0].d + p[i].d + p[i + 1].d) / 3.0;
    }
    return r;
}

/// The part of @p p where sign * d >= 0, into @p out (room for n + 2); returns its corner count.
inline std::size_t polygon_half(const LinearCorner* p,
                                std::size_t n,
                                double sign,
                                LinearCorner* out) {
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const LinearCorner& a = p[i];
        const LinearCorner& b = p[i + 1 == n ? 0 : i + 1];
        const double da = sign * a.d;
        const double db = sign * b.d;
        if (da >= 0.0) {
            out[m++] = a;
        }
        if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) {
            const double t = da / (da - db);
            out[m++] = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0.0};
        }
    }
    return m;
}

/// Fill (d > 0), cut (d < 0) and unchanged (d == 0 everywhere) parts of a convex polygon of at
/// most 14 corners: areas and the integrals of d and -d.
struct SignedParts {
    AreaIntegral fill;
    AreaIntegral cut;  ///< integral of -d (positive)
    double unchanged_area = 0.0;
};

inline SignedParts split_polygon(const LinearCorner* p, std::size_t n) {
    SignedParts out;
    bool positive = false;
    bool negative = false;
    for (std::size_t i = 0; i < n; ++i) {
        positive = positive || p[i].d > 0.0;
        negative = negative || p[i].d < 0.0;
    }
    if (!positive && !negative) {
        out.unchanged_area = integrate_polygon(p, n).area;
        return out;
    }
    std::array<LinearCorner, 16> part;  // NOLINT: filled by polygon_half
    if (positive) {
        out.fill = negative ? integrate_polygon(part.data(), polygon_half(p, n, 1.0, part.data()))
                            : integrate_polygon(p, n);
    }
    if (negative) {
        out.cut = positive ? integrate_polygon(part.data(), polygon_half(p, n, -1.0, part.data()))
                           : integrate_polygon(p, n);
        out.cut.integral = -out.cut.integral;
    }
    return out;
}

}  // namespace dtm::detail
