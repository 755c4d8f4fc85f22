// SPDX-License-Identifier: MIT
/// @file
/// @brief Inserting many constraint segments: in parallel where they cannot interfere, with a
/// result that never depends on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "algo/detail/input_merge.hpp"
#include "algo/detail/mesh_edit.hpp"
#include "dtm/core/progress.hpp"

namespace dtm::detail {

/// The order insert_segments gives the free segments (the result equals inserting them one by
/// one in ascending order): blocks of nearby segments (the kernel number of the smaller endpoint
/// divided by 2^16), and within a block a fixed hash of the segment's index @p index.
[[nodiscard]] inline std::uint64_t segment_priority(std::uint64_t index,
                                                    std::uint64_t smaller_endpoint) noexcept {
    std::uint64_t h = index + 0x9e3779b97f4a7c15ull;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    h ^= h >> 31;
    return ((smaller_endpoint >> 16) << 32) | (h & 0xffffffffull);
}

/// For each segment (kernel vertex ids): true when it touches no other segment except at a
/// shared endpoint (no crossing, no overlap, no T-junction). Exact predicates only.
[[nodiscard]] std::vector<bool> find_free_segments(const GhostMesh& mesh,
                                                   const std::vector<InputSegment>& segments);

/// Inserts @p segments (kernel vertex ids). Free segments go first, by deterministic
/// reservations (rounds of plan -> reserve vertices by priority -> apply the winners in
/// parallel), which gives exactly the result of inserting them one by one in priority order; the
/// others (crossings, overlaps: none after split_segments) follow one by one in input order.
/// @p all_free: the caller knows every segment is free (split_segments found none touching).
void insert_segments(MeshEditor& editor,
                     const GhostMesh& mesh,
                     const std::vector<InputSegment>& segments,
                     bool all_free,
                     const Progress& progress);

}  // namespace dtm::detail
