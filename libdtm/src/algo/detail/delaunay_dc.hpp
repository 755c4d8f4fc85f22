// SPDX-License-Identifier: MIT
/// @file
/// @brief Delaunay triangulation by divide and conquer with alternating cuts (kernel of dtm).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "algo/detail/ghost_merge.hpp"
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

/// A subtree built by build_kernel_subtree: its hull handles and the two slots it left unused
/// (the last two of its range).
struct KernelSubtree {
    GhostHull<HalfEdge> hull;
    std::array<std::size_t, 2> spare;
};

/// The kernel's steps one subtree at a time, for the distributed run (each rank builds the
/// subtrees it holds whole; dist/) and its tests. order_kernel_subtree puts points [lo, hi) of a
/// subtree whose first cut is by @p cut (0 x, 1 y) in the kernel order; build_kernel_subtree
/// triangulates them (already in that order, at least two) into the slots [2 lo, 2 hi) of
/// mesh.tris (sized by the caller, the slots unused), with hull handles in the order of
/// @p frame (the parent's cut). Both give exactly what delaunay_divide_and_conquer gives for
/// that subtree.
void order_kernel_subtree(BigArray<KernelPoint>& points, std::size_t lo, std::size_t hi, int cut);
KernelSubtree build_kernel_subtree(BigArray<KernelPoint>& points,
                                   GhostMesh& mesh,
                                   std::size_t lo,
                                   std::size_t hi,
                                   int cut,
                                   int frame);

}  // namespace dtm::detail
