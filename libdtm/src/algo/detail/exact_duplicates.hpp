// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact duplicate positions: for every point, the first earlier point at the same x, y.
#pragma once

#include <span>
#include <vector>

#include "algo/detail/big_array.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// first[i]: the index of the first of @p points with the x and y of point i (first[i] == i for
/// a first occurrence); -0.0 equals 0.0. Linear time (hash partitions that fit the caches, see
/// exact_duplicates.cpp), by all threads of the arena, with the same result for every thread
/// count. Every entry is written once, in parallel (the array is not zeroed first).
/// @pre fewer than no_vertex points.
[[nodiscard]] BigArray<VertexIndex> first_occurrences(std::span<const Point3> points);

}  // namespace dtm::detail
