// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: tracing the contour chains of one level through the TIN, before splitting,
/// smoothing and clean-up.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// One raw chain of one level: points[i] lies on TIN edge edges[i] (the edge's two vertices,
/// below first, above second); step i goes from points[i] to points[i + 1] through triangle
/// triangles[i]. A closed chain repeats its first point at the end. skip[i] marks a step that
/// must not be output (the second copy of a piece lying along a TIN edge).
struct RawChain {
    std::vector<Point3> points;
    std::vector<std::array<VertexIndex, 2>> edges;
    std::vector<TriangleIndex> triangles;
    std::vector<std::uint8_t> skip;
    bool closed = false;
};

/// Where a level crosses an edge, when not by linear interpolation of the edge's end heights
/// (the cubic surface's own crossing on a refinement's edge). Must give the same bits from
/// either triangle of the edge, return the above vertex itself when its height is the level,
/// and keep the order of the levels along each edge (a lower level nearer the below end).
class EdgeCrossing {
public:
    virtual ~EdgeCrossing() = default;
    /// The crossing of @p level on edge @p e of triangle @p t, from @p below to @p above.
    [[nodiscard]] virtual Point3 point(
        TriangleIndex t, int e, VertexIndex below, VertexIndex above, double level) const = 0;
};

/// Traces every chain of level @p level through the triangles @p crossing (ascending indices,
/// exactly the triangles with zmin < level <= zmax). @p visited has one byte per triangle, all
/// zero on entry and on return. @p edge_crossing, when given, places the points.
void trace_level(const Tin& tin,
                 double level,
                 std::span<const TriangleIndex> crossing,
                 std::vector<std::uint8_t>& visited,
                 std::vector<RawChain>& chains,
                 const EdgeCrossing* edge_crossing = nullptr);

}  // namespace dtm::detail
