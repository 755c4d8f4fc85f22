// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact duplicate positions: for every point, the first earlier point at the same x, y.
#pragma once

#include <span>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// first[i]: the index of the first of @p points with the x and y of point i (first[i] == i for
/// a first occurrence); -0.0 equals 0.0. Linear time (an open-addressing hash table), filled by
/// all threads of the arena for large inputs, with the same result as one thread.
/// @pre fewer than no_vertex points.
[[nodiscard]] std::vector<VertexIndex> first_occurrences(std::span<const Point3> points);

}  // namespace dtm::detail
