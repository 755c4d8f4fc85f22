// SPDX-License-Identifier: MIT
/// @file
/// @brief The TIN's domain on the distributed mesh (R-B3 of docs/distributed.md): the serial
/// apply_domain's boundary and hole nesting depths as a fixpoint reached by exchanging labels.
#pragma once

#include <cstdint>
#include <unordered_set>
#include <vector>

#include "dist/kernel.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/dist/comm.hpp"

namespace dtm::dist {

struct DomainStats {
    std::uint64_t removed = 0;  ///< triangles removed on all ranks
    std::uint32_t rounds = 0;   ///< label exchanges until nothing changed
};

/// Collective, after insert_constraints: sets mesh.removed as the serial apply_domain removes
/// triangles for boundary and hole rings (without hole seeds and `max_edge`): the nesting depth
/// of every triangle (how many boundary or hole edges separate it from the outside, a shortest
/// path with 0-1 weights from the hull) is odd for the kept ones; without a boundary the hull
/// counts as one. Shortest paths are the unique fixpoint of relaxation, so each rank relaxes
/// its own triangles (buckets by depth) and sends the labels crossing to other ranks until an
/// integer allreduce says no label changed. Nothing is removed when there is no ring.
DomainStats apply_distributed_domain(Comm& comm,
                                     DistributedMesh& mesh,
                                     bool has_boundary,
                                     const Progress& progress);

/// Collective, after apply_distributed_domain: the hole seeds as the serial apply_domain takes
/// them (Shewchuk's Triangle): the first triangle of the serial TIN order that holds the seed
/// (exact orient2d; an integer min over the ranks), if still kept, and everything reachable
/// from it without crossing a constrained edge is removed; the flood crosses ranks by notices.
/// Returns the triangles it removed on all ranks.
std::uint64_t remove_hole_seeds(Comm& comm,
                                DistributedMesh& mesh,
                                const std::vector<Point2>& seeds,
                                const Progress& progress);

/// Collective, after apply_distributed_domain: peels border triangles whose border edge is longer
/// than @p max_edge and not constrained, as the serial trim_long_edges does, from the outside
/// inwards: the result is the least fixpoint of that rule (removing a triangle only makes
/// more edges border), reached by local peeling and notices to the ranks across. Returns the
/// triangles it removed on all ranks.
std::uint64_t trim_distributed_long_edges(Comm& comm,
                                          DistributedMesh& mesh,
                                          double max_edge,
                                          const Progress& progress);

/// The TIN's face numbers of a rank's slots: the serial TIN's order (dist::serial_face) with the
/// removed triangles left out, as apply_domain's compaction leaves them out.
struct FaceNumbers {
    static constexpr std::uint64_t none = ~std::uint64_t{0};
    std::vector<std::uint64_t> face;  ///< per own slot; none for ghosts and removed triangles
    std::uint64_t count = 0;          ///< faces of the TIN over all ranks
};

/// Collective: a removed triangle's serial index is reported to the rank holding that slot
/// number, which counts the removed ones before each of its indices (plus an exclusive scan
/// over the ranks); the few triangles moved into hull-ghost holes learn theirs from there.
[[nodiscard]] FaceNumbers kept_face_numbers(Comm& comm,
                                            const LocalMesh& mesh,
                                            const std::vector<std::uint64_t>& ghosts);

/// Collective: the removed slots of other ranks that neighbour this rank's slots.
[[nodiscard]] std::unordered_set<std::uint64_t> foreign_removed(Comm& comm, const LocalMesh& mesh);

}  // namespace dtm::dist
