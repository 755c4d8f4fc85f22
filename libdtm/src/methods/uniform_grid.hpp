// SPDX-License-Identifier: MIT
/// @file
/// @brief [uniform-grid] Delaunay triangulation with a uniform grid after Fang and Piegl 1993,
/// the thesis' own method with its vertex-list output (000 §3.10; dtm/methods/vertex_list.hpp).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// Params: tol=<distance> (0 by default: exact duplicates only; otherwise a point within tol
/// of one already stored in its grid cell is dropped, as §3.10.1 does).
[[nodiscard]] MethodResult run_uniform_grid(const MethodInput& input,
                                            const MethodOptions& options,
                                            const Progress& progress);

}  // namespace dtm::methods
