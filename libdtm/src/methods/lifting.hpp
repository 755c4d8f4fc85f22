// SPDX-License-Identifier: MIT
/// @file
/// @brief [lifting] Delaunay triangulation as the lower convex hull of the points lifted to
/// the paraboloid z = x^2 + y^2 (thesis 000 §2.4.4), with the exact lifted orientation.
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// No params. The hull's insertion order is a random permutation from MethodOptions::seed.
[[nodiscard]] MethodResult run_lifting(const MethodInput& input,
                                       const MethodOptions& options,
                                       const Progress& progress);

}  // namespace dtm::methods
