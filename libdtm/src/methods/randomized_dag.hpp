// SPDX-License-Identifier: MIT
/// @file
/// @brief [randomized-dag] Randomized incremental Delaunay triangulation with the history DAG
/// (lecture 003, Alg. 1-4), the super-triangle symbolic or the lecture's finite one.
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// Params: super-triangle=symbolic|finite (finite: d = 100 x extent, can lose hull edges).
/// The insertion order is a random permutation from MethodOptions::seed.
[[nodiscard]] MethodResult run_randomized_dag(const MethodInput& input,
                                              const MethodOptions& options,
                                              const Progress& progress);

}  // namespace dtm::methods
