// SPDX-License-Identifier: MIT
/// @file
/// @brief [incremental-walk] Incremental Delaunay insertion on the winged-edge structure with
/// walking point location (thesis 000 §3.8, §3.8.1).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// Params: order=hilbert|random|input (insertion order; the walk starts at the last edge of
/// the previous walk, so a spatially coherent order keeps it short).
[[nodiscard]] MethodResult run_incremental_walk(const MethodInput& input,
                                                const MethodOptions& options,
                                                const Progress& progress);

}  // namespace dtm::methods
