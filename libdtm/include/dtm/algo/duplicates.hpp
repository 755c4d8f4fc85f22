// SPDX-License-Identifier: MIT
/// @file
/// @brief Counting points that repeat the xy position of an earlier point.
#pragma once

#include <cstddef>
#include <span>

#include "dtm/core/point.hpp"

namespace dtm {

/// How many of @p points have the same x and y (exactly; -0.0 equals 0.0) as an earlier one:
/// the number triangulate() merges without a snap distance. Linear time (a hash table).
[[nodiscard]] std::size_t count_repeated_positions(std::span<const Point3> points);

}  // namespace dtm
