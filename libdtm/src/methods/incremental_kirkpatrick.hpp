// SPDX-License-Identifier: MIT
/// @file
/// @brief [incremental-kirkpatrick] Incremental Delaunay insertion on the winged-edge
/// structure with Kirkpatrick's hierarchy for point location (thesis 000 §3.8, §3.8.2).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// No params. Random insertion order from MethodOptions::seed.
[[nodiscard]] MethodResult run_incremental_kirkpatrick(const MethodInput& input,
                                                       const MethodOptions& options,
                                                       const Progress& progress);

}  // namespace dtm::methods
