// SPDX-License-Identifier: MIT
/// @file
/// @brief Test helpers for map labelling: a hilly TIN from an analytic surface, height lookup on
/// a TIN by brute force, and an overlap test for convex quadrilaterals written independently of
/// dtm's separating-axis code (edge crossings and containment with exact orientation signs).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::test {

/// Two hills, a hollow and a saddle between the hills on [0, 200] x [0, 150] (metres).
inline double hills_z(double x, double y) {
    const auto bump = [](double x0, double y0, double r, double h, double x1, double y1) {
        const double d2 = ((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0)) / (r * r);
        return h * std::exp(-d2);
    };
    return 250.0 + 0.05 * x + bump(60, 75, 30, 25, x, y) + bump(140, 75, 30, 20, x, y) -
           bump(100, 20, 15, 8, x, y);
}

/// A TIN of @p count random points on hills_z, shifted by (x0, y0).
inline Tin hills_tin(std::size_t count, std::uint32_t seed, double x0 = 0.0, double y0 = 0.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(0.0, 200.0);
    std::uniform_real_distribution<double> uy(0.0, 150.0);
    TerrainInput input;
    for (const auto& c :
         std::array<std::array<double, 2>, 4>{{{0, 0}, {200, 0}, {200, 150}, {0, 150}}}) {
        input.points.push_back({x0 + c[0], y0 + c[1], hills_z(c[0], c[1])});
    }
    for (std::size_t i = 0; i < count; ++i) {
        const double x = ux(rng);
        const double y = uy(rng);
        input.points.push_back({x0 + x, y0 + y, hills_z(x, y)});
    }
    return triangulate(input).tin;
}

/// Height of the TIN surface at (x, y), or nothing outside every triangle (brute force).
inline std::optional<double> tin_height(const Tin& tin, double x, double y) {
    for (const Triangle& t : tin.triangles) {
        const Point3& a = tin.vertices[t.v[0]];
        const Point3& b = tin.vertices[t.v[1]];
        const Point3& c = tin.vertices[t.v[2]];
        const double d = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const double l1 = ((b.x - x) * (c.y - y) - (c.x - x) * (b.y - y)) / d;
        const double l2 = ((c.x - x) * (a.y - y) - (a.x - x) * (c.y - y)) / d;
        const double l3 = 1.0 - l1 - l2;
        if (l1 >= -1e-12 && l2 >= -1e-12 && l3 >= -1e-12) return l1 * a.z + l2 * b.z + l3 * c.z;
    }
    return std::nullopt;
}

using Quad = std::array<Point2, 4>;

inline double cross(Point2 o, Point2 a, Point2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// Strict interior of a counter-clockwise convex quadrilateral.
inline bool strictly_inside(const Quad& q, Point2 p) {
    for (int i = 0; i < 4; ++i) {
        if (cross(q[static_cast<std::size_t>(i)], q[static_cast<std::size_t>((i + 1) % 4)], p) <=
            0.0) {
            return false;
        }
    }
    return true;
}

/// Proper crossing of two segments (interiors cross at one point).
inline bool segments_cross(Point2 a, Point2 b, Point2 c, Point2 d) {
    const double d1 = cross(a, b, c);
    const double d2 = cross(a, b, d);
    const double d3 = cross(c, d, a);
    const double d4 = cross(c, d, b);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/// True when two counter-clockwise convex quadrilaterals have intersecting interiors.
inline bool quads_overlap(const Quad& p, const Quad& q) {
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            if (segments_cross(
                    p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>((i + 1) % 4)],
                    q[static_cast<std::size_t>(j)], q[static_cast<std::size_t>((j + 1) % 4)])) {
                return true;
            }
        }
    }
    const auto centroid = [](const Quad& r) {
        return Point2{(r[0].x + r[1].x + r[2].x + r[3].x) / 4,
                      (r[0].y + r[1].y + r[2].y + r[3].y) / 4};
    };
    return strictly_inside(p, centroid(q)) || strictly_inside(q, centroid(p));
}

}  // namespace dtm::test
