// SPDX-License-Identifier: MIT
/// @file
/// @brief The benchmarks' TIN: a jittered n x n grid over 2000 m at S-JTSK offsets with a smooth
/// terrain, triangles and neighbour links built directly (no triangulator needed).
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "dtm/core/tin.hpp"

namespace dtm::bench {

/// n x n jittered grid over 2000 m with a smooth terrain; triangles and neighbour links built
/// directly (no triangulator needed).
inline dtm::Tin jittered_grid_tin(int n, unsigned seed) {
    std::mt19937 rng(seed);
    const double h = 2000.0 / (n - 1);
    std::uniform_real_distribution<double> jitter(-0.2 * h, 0.2 * h);
    dtm::Tin tin;
    tin.vertices.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double x = i * h + (i > 0 && i < n - 1 ? jitter(rng) : 0.0);
            const double y = j * h + (j > 0 && j < n - 1 ? jitter(rng) : 0.0);
            tin.vertices.push_back(
                {-750'000.0 + x, -1'050'000.0 + y,
                 300.0 + 40.0 * std::sin(x / 300.0) * std::cos(y / 250.0) + 0.02 * x});
        }
    }
    const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * n + i); };
    const auto tri = [n](int i, int j, int k) {
        return static_cast<std::uint32_t>(2 * (j * (n - 1) + i) + k);
    };
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            // lower-right triangle (k = 0) and upper-left (k = 1), diagonal (i,j)-(i+1,j+1)
            dtm::Triangle a{{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, {}};
            dtm::Triangle b{{id(i, j), id(i + 1, j + 1), id(i, j + 1)}, {}};
            a.n = {i + 2 < n ? tri(i + 1, j, 1) : dtm::no_triangle, tri(i, j, 1),
                   j > 0 ? tri(i, j - 1, 1) : dtm::no_triangle};
            b.n = {j + 2 < n ? tri(i, j + 1, 0) : dtm::no_triangle,
                   i > 0 ? tri(i - 1, j, 0) : dtm::no_triangle, tri(i, j, 0)};
            tin.triangles.push_back(a);
            tin.triangles.push_back(b);
        }
    }
    return tin;
}

}  // namespace dtm::bench
