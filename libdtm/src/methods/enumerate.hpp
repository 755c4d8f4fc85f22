// SPDX-License-Identifier: MIT
/// @file
/// @brief [enumerate] Every triangulation of a small point set (n <= 12) and the optimum of each
/// against every criterion (thesis 000 §2.3).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_enumerate(const MethodInput& input,
                                         const MethodOptions& options,
                                         const Progress& progress);

}  // namespace dtm::methods
