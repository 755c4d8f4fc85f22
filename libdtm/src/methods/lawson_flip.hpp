// SPDX-License-Identifier: MIT
/// @file
/// @brief [lawson-flip] Lawson's local improvement: any triangulation, then flips of illegal
/// edges until none is left (thesis 000 §2.4.1, §2.3; lectures 004 Alg. 2, 003).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// Params: initial=sweep (the only initial triangulation: a left-to-right sweep),
/// order=stack|pass (stack: every flip queues the four edges around it; pass: the lecture's
/// repeated passes over all edges until one makes no flip).
[[nodiscard]] MethodResult run_lawson_flip(const MethodInput& input,
                                           const MethodOptions& options,
                                           const Progress& progress);

}  // namespace dtm::methods
