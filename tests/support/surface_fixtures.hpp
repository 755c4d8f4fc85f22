// SPDX-License-Identifier: MIT
/// @file
/// @brief Test helpers for the interpolated surfaces: TINs of analytic terrains (with known
/// truth) triangulated by dtm, and finite-difference gradients.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "dtm/algo/interpolation.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/terrain.hpp"

namespace dtm::test {

using Terrain = std::function<double(double, double)>;

/// @p count random points in [x0, x0 + size)^2 with heights from @p f, plus the four corners.
inline TerrainInput sampled_terrain(const Terrain& f,
                                    std::size_t count,
                                    std::uint32_t seed,
                                    double x0 = 0.0,
                                    double y0 = 0.0,
                                    double size = 100.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, size);
    TerrainInput input;
    for (const auto& [cx, cy] : {std::pair{0.0, 0.0}, {size, 0.0}, {0.0, size}, {size, size}}) {
        input.points.push_back({x0 + cx, y0 + cy, f(cx, cy)});
    }
    for (std::size_t i = 0; i < count; ++i) {
        const double x = u(rng), y = u(rng);
        input.points.push_back({x0 + x, y0 + y, f(x, y)});
    }
    return input;
}

/// Central-difference gradient of the evaluator at (x, y) with step @p h (each sample located).
inline std::array<double, 2> fd_gradient(TinEvaluator& eval, double x, double y, double h) {
    TriangleIndex hint = 0;
    const double fx1 = eval.value_at(x + h, y, hint), fx0 = eval.value_at(x - h, y, hint);
    const double fy1 = eval.value_at(x, y + h, hint), fy0 = eval.value_at(x, y - h, hint);
    return {(fx1 - fx0) / (2 * h), (fy1 - fy0) / (2 * h)};
}

}  // namespace dtm::test
