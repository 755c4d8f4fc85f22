// SPDX-License-Identifier: MIT
/// @file
/// @brief Heights of a TIN's surface at any (x, y): point location, linear interpolation, and
/// the nearest vertex for points off the TIN. Build once from a Tin, then query fast; used for
/// the heights of 2-D lines (line_heights.hpp), soft breaklines, and by profiles, check points
/// and volumes.
#pragma once

#include <cstdint>
#include <memory>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// Where a point lies on a TIN.
struct TinLocation {
    enum class Kind : std::uint8_t {
        outside,   ///< on no triangle (beyond the hull or the boundary, in a hole)
        triangle,  ///< strictly inside edge.triangle
        edge,      ///< on the half-edge `edge`, strictly between its two vertices
        vertex,    ///< on the vertex origin(tin, edge)
    };
    Kind kind = Kind::outside;
    HalfEdge edge;
};

/// Point location and heights on one Tin. The surface is linear on each triangle; on an edge the
/// height is interpolated along the edge from its lower-numbered vertex and on a vertex it is the
/// vertex's own z, so the result never depends on which triangle the location reached (or on
/// the thread or the order of the queries).
///
/// Location walks from the last triangle found (a Cursor) or from a coarse grid of start
/// triangles, deciding each step with the exact orient2d; the edge tried first varies
/// pseudo-randomly, which keeps the walk from cycling in constrained (non-Delaunay) TINs
/// (Devillers, Pion and Teillaud, "Walking in a triangulation", 2002). A walk that leaves a
/// non-convex TIN (boundary, holes, trimmed edges) falls back to a grid of the triangles, built
/// on first need. The nearest vertex comes from a k-d tree of the vertices used by triangles,
/// also built on first need. Both lazy indices are built once even under concurrent queries.
///
/// Thread safety: every const member may be called from several threads at once, each thread
/// with its own Cursor.
class SurfaceSampler {
public:
    /// Memory of a walk: keep one per thread for queries near each other (along a line).
    struct Cursor {
        TriangleIndex triangle = no_triangle;
    };

    /// @param tin with its neighbour links (as libdtm returns it, or after link_neighbours());
    /// it must stay alive and unchanged while the sampler is used. O(triangles).
    explicit SurfaceSampler(const Tin& tin);
    SurfaceSampler(SurfaceSampler&&) noexcept;
    SurfaceSampler& operator=(SurfaceSampler&&) noexcept;
    ~SurfaceSampler();

    [[nodiscard]] TinLocation locate(Point2 p, Cursor& cursor) const;
    /// The height of the surface at @p p; NaN off the TIN.
    [[nodiscard]] double height(Point2 p, Cursor& cursor) const;
    /// height(), or off the TIN the z of the nearest vertex (NaN for a TIN without triangles).
    [[nodiscard]] double height_or_nearest(Point2 p, Cursor& cursor) const;
    /// The height at a location found by locate(); NaN for outside.
    [[nodiscard]] double height_at(const TinLocation& where, Point2 p) const;
    /// The vertex of some triangle nearest to @p p in xy (of equally near ones, the lowest
    /// index); no_vertex when the TIN has no triangle.
    [[nodiscard]] VertexIndex nearest_vertex(Point2 p) const;

    [[nodiscard]] const Tin& tin() const noexcept { return *tin_; }

private:
    struct Indices;
    const Tin* tin_;
    std::unique_ptr<Indices> indices_;
};

}  // namespace dtm
