// SPDX-License-Identifier: MIT
/// @file
/// @brief [voronoi-incremental] The classic incremental Voronoi diagram with three auxiliary
/// generators (000 §3.5).
#pragma once

#include <vector>

#include "dtm/methods/method.hpp"
#include "methods/detail/voronoi_incremental_graph.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_voronoi_incremental(const MethodInput& input,
                                                   const MethodOptions& options,
                                                   const Progress& progress);

namespace detail {
/// The classic choice of T: trace the new region's boundary from the nearest generator's
/// region, deciding every vertex by its in-circle sign alone.
void choose_tree_classic(IncrementalVoronoi& graph,
                         std::uint32_t g,
                         const Point2& p,
                         std::vector<std::uint32_t>& tree);
}  // namespace detail

}  // namespace dtm::methods
