// SPDX-License-Identifier: MIT
/// @file
/// @brief [dewall] DeWall: divide and conquer without a merge, the wall first, the halves in
/// parallel (thesis 000 §3.9; Cignoni, Montani, Perego, Scopigno 1992).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// No params; MethodOptions::threads sets the TBB threads (the result never depends on it).
[[nodiscard]] MethodResult run_dewall(const MethodInput& input,
                                      const MethodOptions& options,
                                      const Progress& progress);

}  // namespace dtm::methods
