// SPDX-License-Identifier: MIT
/// @file
/// @brief Delaunay triangulation by divide and conquer with alternating cuts (kernel of dtm).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "algo/detail/edge_mesh.hpp"
#include "dtm/core/progress.hpp"

namespace dtm::detail {

struct DelaunayDcOptions {
    /// Subtrees larger than this are built as parallel tasks (tiles); 0 = everything sequential.
    /// The triangulation never depends on it: only where the work runs does.
    std::size_t parallel_cutoff = 0;
};

/// Delaunay triangulation of @p points (pairwise distinct in xy, at least 2) into @p mesh.
/// Takes over @p points (left empty): reordered, they become mesh.points, and their order is the
/// kernel vertex numbering. On return @p slots describes the free edge slots.
/// Collinear input gives a chain of edges and no triangle.
/// @throws Cancelled when @p progress asks to stop.
void delaunay_divide_and_conquer(BigArray<KernelPoint>& points, EdgeMesh& mesh, EdgeSlots& slots,
                                 const DelaunayDcOptions& options, const Progress& progress);

}  // namespace dtm::detail
