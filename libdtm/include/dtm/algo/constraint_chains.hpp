// SPDX-License-Identifier: MIT
/// @file
/// @brief The constrained edges of a TIN joined into polylines, one kind at a time: what the
/// exchange writers (LandXML SourceData, DXF polylines) store as breaklines and boundaries.
#pragma once

#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm {

/// A chain of constrained edges: vertex indices in order; closed chains do not repeat the first.
struct ConstraintChain {
    std::vector<VertexIndex> vertices;
    bool closed = false;
};

/// Every constrained edge of @p kind exactly once, in maximal chains: open chains run between
/// vertices where the kind's edges do not meet in twos (ends, junctions), from the lowest such
/// vertex first; the remaining edges form closed rings, each started at its lowest edge. A
/// function of the constraint list only (deterministic). O(edges).
[[nodiscard]] std::vector<ConstraintChain> constraint_chains(const Tin& tin, ConstraintKind kind);

/// The edges of chains as constrained edges (a < b) of @p kind, appended to @p out.
void chain_edges(const std::vector<VertexIndex>& vertices,
                 bool closed,
                 ConstraintKind kind,
                 std::vector<ConstrainedEdge>& out);

}  // namespace dtm
