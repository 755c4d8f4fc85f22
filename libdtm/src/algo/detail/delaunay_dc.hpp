// SPDX-License-Identifier: MIT
/// @file
/// @brief Delaunay triangulation by divide and conquer with alternating cuts (kernel of dtm).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "algo/detail/ghost_mesh.hpp"
#include "dtm/core/progress.hpp"

namespace dtm::detail {

struct DelaunayDcOptions {
    /// Subtrees larger than this are built as parallel tasks (tiles); 0 = everything sequential.
    /// The triangulation never depends on it: only where the work runs does.
    std::size_t parallel_cutoff = 0;
};

/// Delaunay triangulation of @p points (pairwise distinct in xy) into @p mesh: 2 n triangle
/// slots, real triangles, ghosts on the hull and two unused slots (all corners ghost); no slot
/// for fewer than two points. Takes over @p points (left empty): reordered, they become
/// mesh.points, and their order is the kernel vertex numbering. Collinear input gives ghosts
/// only (a chain of edges and no triangle).
/// @throws Cancelled when @p progress asks to stop; InputError beyond max_kernel_points.
void delaunay_divide_and_conquer(BigArray<KernelPoint>& points,
                                 GhostMesh& mesh,
                                 const DelaunayDcOptions& options,
                                 const Progress& progress);

}  // namespace dtm::detail
