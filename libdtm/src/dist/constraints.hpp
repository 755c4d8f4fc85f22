// SPDX-License-Identifier: MIT
/// @file
/// @brief Breaklines inserted into the distributed Delaunay mesh (R-B2 of docs/distributed.md):
/// the serial insertion's slots and constraint bits exactly, for segments that touch only at
/// shared endpoints (split_segments' output).
#pragma once

#include <cstdint>
#include <vector>

#include "dist/kernel.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/dist/comm.hpp"

namespace dtm::dist {

/// One segment by the input ids of its endpoints (DistributedMesh::input_ids); its index in the
/// list is its index in the serial insert_segments call (it decides the priority).
struct GlobalSegment {
    std::uint64_t a = 0;
    std::uint64_t b = 0;
    std::uint8_t bits = 0;  ///< ConstraintBits
};

struct ConstraintStats {
    std::uint64_t marked = 0;      ///< segments that were edges already (all ranks)
    std::uint64_t components = 0;  ///< groups of the other segments inserted together
    std::uint64_t gathered = 0;    ///< triangles this rank received to insert into (with frames)
    std::uint64_t changed = 0;     ///< slots of this rank the insertion changed
};

/// Collective: every rank passes the same @p segments (replicated: the breaklines of a survey
/// are few against its points). Inserts them as the serial insert_segments does and sets
/// mesh.mesh.bits for every own slot.
///
/// A segment changes only triangles it meets (Anglada's cavities stay inside the triangles the
/// segment crosses, and those of earlier segments), so segments whose triangles are neither
/// shared nor edge-adjacent never interact. Every rank tests its triangles against the
/// segments (exact predicates), groups the segments by shared or adjacent triangles (a
/// union-find replayed identically on every rank), and sends each group's triangles, with one
/// ring of neighbours, to one rank; there the serial editor inserts the group's segments in the
/// serial priority order into a copy with slots and vertices renumbered monotonically, and the
/// changed slots and neighbour links go back to their owners.
/// @throws Error when a segment crosses another (split_segments was not run or ran out of rounds)
ConstraintStats insert_constraints(Comm& comm,
                                   DistributedMesh& mesh,
                                   const std::vector<GlobalSegment>& segments,
                                   const Progress& progress);

}  // namespace dtm::dist
