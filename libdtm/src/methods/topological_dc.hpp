// SPDX-License-Identifier: MIT
/// @file
/// @brief [topological-dc] Topology-oriented divide and conquer after Oishi and Sugihara
/// (thesis 000 §3.7; detail/topological_merge.hpp).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// No params.
[[nodiscard]] MethodResult run_topological_dc(const MethodInput& input,
                                              const MethodOptions& options,
                                              const Progress& progress);

}  // namespace dtm::methods
