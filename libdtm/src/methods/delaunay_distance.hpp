// SPDX-License-Identifier: MIT
/// @file
/// @brief [delaunay-distance] Incremental construction by Delaunay distance with an active
/// edge list (lecture 004; thesis 000 §2.4.3).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// No params: every search scans all points (the lecture's O(n^2) algorithm). The start point
/// is chosen by MethodOptions::seed.
[[nodiscard]] MethodResult run_delaunay_distance(const MethodInput& input,
                                                 const MethodOptions& options,
                                                 const Progress& progress);

}  // namespace dtm::methods
