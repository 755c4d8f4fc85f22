// SPDX-License-Identifier: MIT
/// @file
/// @brief [monotone] Constrained triangulation by regularisation and y-monotone polygons
/// (Preparata and Shamos; thesis 000 §3.2), O(n log n).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_monotone(const MethodInput& input,
                                        const MethodOptions& options,
                                        const Progress& progress);

}  // namespace dtm::methods
