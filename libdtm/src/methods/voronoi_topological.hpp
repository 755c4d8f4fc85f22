// SPDX-License-Identifier: MIT
/// @file
/// @brief [voronoi-topological] The topology-oriented incremental Voronoi diagram of Sugihara
/// and Iri (000 §3.6).
#pragma once

#include <vector>

#include "dtm/methods/method.hpp"
#include "methods/detail/voronoi_incremental_graph.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_voronoi_topological(const MethodInput& input,
                                                   const MethodOptions& options,
                                                   const Progress& progress);

namespace detail {
/// Procedure B: T grown from the nearest region's vertex of smallest H by the vertices with
/// H < 0 that keep it a tree (C4) meeting every incident region in one piece (C5).
void choose_tree_topological(IncrementalVoronoi& graph,
                             std::uint32_t g,
                             const Point2& p,
                             std::vector<std::uint32_t>& tree);
}  // namespace detail

}  // namespace dtm::methods
