// SPDX-License-Identifier: MIT
/// @file
/// @brief The Delaunay kernel over ranks (R-S1 to R-S3 of docs/distributed.md): the serial
/// kernel's triangles, slot for slot, from a partition_points share.
#pragma once

#include <cstdint>
#include <vector>

#include "dist/global_mesh.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/dist/partition.hpp"

namespace dtm::dist {

struct KernelOptions {
    /// Rings of neighbours around the band's seeds sent before the first attempt; a merge that
    /// needs more asks for the slot it lacked and runs again (0 forces that path: tests).
    unsigned rings = 1;
};

struct KernelStats {
    std::uint32_t levels = 0;             ///< tree levels with merges across ranks
    std::uint32_t merges = 0;             ///< merges across ranks this rank ran
    std::uint32_t widenings = 0;          ///< rounds in which some merge asked for more
    std::uint64_t band_triangles = 0;     ///< band triangles this rank received to merge
    std::uint64_t changed_triangles = 0;  ///< slots this rank's merges changed
};

struct DistributedMesh {
    /// The slots [2 lo, 2 hi) of this rank's positions [lo, hi) (its leaves), global numbers:
    /// vertex = position in the serial kernel order, half-edge = slot << 2 | i.
    LocalMesh mesh;
    std::vector<std::uint64_t> input_ids;  ///< per own position, the point's global id
    KernelStats stats;
};

/// Collective: a stop request on any rank stops every rank (no rank may leave the collectives).
/// @throws Cancelled on every rank when some rank's @p progress asks to stop.
void check_stop_everywhere(Comm& comm, const Progress& progress);

/// Collective: each rank triangulates the subtrees it holds whole with the serial kernel, then
/// the merges across ranks run level by level, deepest first, each on the rank that holds its
/// left half's last leaf, on a band of triangles the ranks of both halves send (the seeds of
/// band_mesh.hpp, A's spare slots, KernelOptions::rings rings), the changed slots going back to
/// their owners. The result equals delaunay_divide_and_conquer on all the points, slot for slot.
/// @p share is consumed: its points are freed as soon as the kernel's arrays hold them (pass it
/// with std::move where it is not needed afterwards; a rank's peak is then 24 bytes per point
/// lower).
DistributedMesh triangulate_share(Comm& comm,
                                  Share share,
                                  const KernelOptions& options,
                                  const Progress& progress);

}  // namespace dtm::dist
