// SPDX-License-Identifier: MIT
/// @file
/// @brief [voronoi-dc] The Voronoi diagram by divide and conquer on a DCEL (Shamos and Hoey).
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_voronoi_dc(const MethodInput& input,
                                          const MethodOptions& options,
                                          const Progress& progress);

}  // namespace dtm::methods
