// SPDX-License-Identifier: MIT
/// @file
/// @brief [greedy-naive] The basic greedy triangulation, O(n^3) (thesis 000 §3.1a).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_greedy_naive(const MethodInput& input,
                                            const MethodOptions& options,
                                            const Progress& progress);

}  // namespace dtm::methods
