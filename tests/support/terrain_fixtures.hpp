// SPDX-License-Identifier: MIT
/// @file
/// @brief Generated terrain inputs for tests (deterministic seeds) and geometric triangle sets for
/// comparing triangulations independently of vertex and triangle numbering.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::test {

/// S-JTSK-like origin: Krovak East-North coordinates of a site in Bohemia.
inline constexpr double sjtsk_e = -750'000.0;
inline constexpr double sjtsk_n = -1'050'000.0;

inline double terrain_z(double x, double y) { return 300.0 + 0.01 * x - 0.02 * y; }

/// @p count uniform random points in [x0, x0 + size) x [y0, y0 + size).
inline std::vector<Point3> random_points(
    std::size_t count, std::uint32_t seed, double x0 = 0.0, double y0 = 0.0, double size = 1000.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, size);
    std::vector<Point3> pts(count);
    for (Point3& p : pts) {
        const double x = u(rng);
        const double y = u(rng);
        p = {x0 + x, y0 + y, terrain_z(x, y)};
    }
    return pts;
}

/// A regular grid of cols x rows points with spacing @p step, rotated by @p angle radians about
/// its first point and shifted to (x0, y0): heavily cocircular input.
inline std::vector<Point3> tilted_grid(
    int cols, int rows, double step, double angle, double x0, double y0) {
    std::vector<Point3> pts;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < cols; ++i) {
            const double x = i * step;
            const double y = j * step;
            pts.push_back({x0 + c * x - s * y, y0 + s * x + c * y, terrain_z(x, y)});
        }
    }
    return pts;
}

using XyTriangle = std::array<std::pair<double, double>, 3>;

/// The triangles of @p tin as sets of xy positions, rotated to start at the smallest position.
inline std::set<XyTriangle> triangle_set(const Tin& tin) {
    std::set<XyTriangle> out;
    for (const Triangle& t : tin.triangles) {
        XyTriangle tri;
        for (int i = 0; i < 3; ++i) tri[i] = {tin.vertices[t.v[i]].x, tin.vertices[t.v[i]].y};
        int k = 0;
        for (int i = 1; i < 3; ++i)
            if (tri[i] < tri[k]) k = i;
        out.insert({tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]});
    }
    return out;
}

}  // namespace dtm::test
