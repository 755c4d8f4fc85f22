// SPDX-License-Identifier: MIT
/// @file
/// @brief Test surfaces a TIN represents exactly (pyramid, frustum, planes), triangulated by dtm
/// from random points plus the ridge lines as breaklines, so that volumes between them have
/// closed forms (pyramid V = A h / 3, frustum V = h / 3 (A1 + A2 + sqrt(A1 A2))).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::test {

/// A square [x0, x0 + side] x [y0, y0 + side] on which a surface is sampled.
struct Square {
    double x0 = 0.0;
    double y0 = 0.0;
    double side = 100.0;
};

/// Height function of a square pyramid / frustum over @p sq: height @p h at the top plateau of
/// half-width @p top_half (0: a pointed pyramid), 0 on the square's edges. Piecewise linear with
/// ridges along the diagonals and the plateau's edges.
inline double frustum_z(const Square& sq, double h, double top_half, double x, double y) {
    const double half = sq.side / 2.0;
    const double cx = sq.x0 + half;
    const double cy = sq.y0 + half;
    const double r = std::max(std::fabs(x - cx), std::fabs(y - cy));  // Chebyshev radius
    if (r <= top_half) {
        return h;
    }
    return h * (half - r) / (half - top_half);
}

/// A TIN of @p z over @p sq from the square's corners, @p count random inner points and the
/// given breaklines (x, y pairs; z taken from @p z).
inline Tin sampled_tin(const Square& sq,
                       std::size_t count,
                       std::uint32_t seed,
                       const std::function<double(double, double)>& z,
                       const std::vector<std::vector<std::pair<double, double>>>& lines = {}) {
    TerrainInput input;
    for (const auto& [u, v] :
         std::vector<std::pair<double, double>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        const double x = sq.x0 + u * sq.side;
        const double y = sq.y0 + v * sq.side;
        input.points.push_back({x, y, z(x, y)});
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t i = 0; i < count; ++i) {
        const double x = sq.x0 + unit(rng) * sq.side;
        const double y = sq.y0 + unit(rng) * sq.side;
        input.points.push_back({x, y, z(x, y)});
    }
    for (const auto& line : lines) {
        Polyline p;
        for (const auto& [x, y] : line) {
            p.points.push_back({x, y, z(x, y)});
        }
        input.breaklines.push_back(p);
    }
    return triangulate(input).tin;
}

/// The pyramid (top_half = 0) or frustum over @p sq as an exact TIN.
inline Tin frustum_tin(
    const Square& sq, double h, double top_half, std::size_t count, std::uint32_t seed) {
    const double half = sq.side / 2.0;
    const double cx = sq.x0 + half;
    const double cy = sq.y0 + half;
    std::vector<std::vector<std::pair<double, double>>> lines;
    const double c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& k : c) {
        lines.push_back(
            {{cx + k[0] * half, cy + k[1] * half}, {cx + k[0] * top_half, cy + k[1] * top_half}});
    }
    if (top_half > 0.0) {
        std::vector<std::pair<double, double>> ring;
        for (const auto& k : c) {
            ring.emplace_back(cx + k[0] * top_half, cy + k[1] * top_half);
        }
        ring.push_back(ring.front());
        lines.push_back(ring);
    }
    return sampled_tin(
        sq, count, seed, [&](double x, double y) { return frustum_z(sq, h, top_half, x, y); },
        lines);
}

/// A plane z = z0 + gx (x - sq.x0) + gy (y - sq.y0) over @p sq as a TIN of random points.
inline Tin plane_tin(
    const Square& sq, double z0, double gx, double gy, std::size_t count, std::uint32_t seed) {
    return sampled_tin(sq, count, seed, [&](double x, double y) {
        return z0 + gx * (x - sq.x0) + gy * (y - sq.y0);
    });
}

}  // namespace dtm::test
