// SPDX-License-Identifier: MIT
/// @file
/// @brief A small hand-built TIN shared by the TIN writer tests: an n x n grid of vertices at an
/// S-JTSK offset, two triangles per cell, and the middle row as a breakline.
#pragma once

#include <cstddef>

#include "dtm/core/tin.hpp"

namespace dtm::test {

inline Tin grid_tin(std::size_t n = 5) {
    Tin tin;
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t i = 0; i < n; ++i) {
            const double x = -750000.0 + 2.5 * static_cast<double>(i);
            const double y = -1050000.0 + 2.5 * static_cast<double>(j);
            tin.vertices.push_back({x, y, 300.0 + 0.1 * static_cast<double>(i * i + j)});
        }
    }
    const auto at = [n](std::size_t i, std::size_t j) {
        return static_cast<VertexIndex>(j * n + i);
    };
    for (std::size_t j = 0; j + 1 < n; ++j) {
        for (std::size_t i = 0; i + 1 < n; ++i) {
            Triangle lower;
            lower.v = {at(i, j), at(i + 1, j), at(i + 1, j + 1)};
            Triangle upper;
            upper.v = {at(i, j), at(i + 1, j + 1), at(i, j + 1)};
            tin.triangles.push_back(lower);
            tin.triangles.push_back(upper);
        }
    }
    for (std::size_t i = 0; i + 1 < n; ++i) {
        tin.constraints.push_back({at(i, n / 2), at(i + 1, n / 2), ConstraintKind::breakline});
    }
    return tin;
}

}  // namespace dtm::test
