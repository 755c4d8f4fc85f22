// SPDX-License-Identifier: MIT
/// @file
/// @brief Triangulated irregular network: a plain value type with index-based topology.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm {

/// Index of a vertex in Tin::vertices.
using VertexIndex = std::uint32_t;
/// Index of a triangle in Tin::triangles.
using TriangleIndex = std::uint32_t;
inline constexpr TriangleIndex no_triangle = std::numeric_limits<TriangleIndex>::max();
inline constexpr VertexIndex no_vertex = std::numeric_limits<VertexIndex>::max();

/// One TIN face. Vertices are counter-clockwise in the xy plane.
///
///            v[2]
///            /  \   (ccw)
///     n[1]  /    \  n[0]        n[i] is the neighbour across the edge
///          /      \             opposite v[i]; no_triangle on the border
///       v[0] ----- v[1]         of the TIN (hull, outer boundary, hole).
///             n[2]
struct Triangle {
    std::array<VertexIndex, 3> v{no_vertex, no_vertex, no_vertex};
    std::array<TriangleIndex, 3> n{no_triangle, no_triangle, no_triangle};
};

/// What a constrained edge came from. The values are those of the PLY `kind` byte and the VTK
/// `constraint_kind` array (docs/formats.md).
enum class ConstraintKind : std::uint8_t {
    breakline = 0,
    soft_breakline = 1,
    boundary = 2,
    hole = 3
};
inline constexpr unsigned constraint_kind_count = 4;

/// The kind's bit in a set of kinds (1 << kind): the triangulator marks each edge with the set of
/// every kind that runs along it.
[[nodiscard]] constexpr std::uint8_t constraint_bit(ConstraintKind kind) noexcept {
    return static_cast<std::uint8_t>(1U << static_cast<unsigned>(kind));
}

/// "breakline", "soft breakline", "boundary", "hole".
[[nodiscard]] const char* constraint_kind_name(ConstraintKind kind) noexcept;

/// An edge of the TIN that must stay an edge (a piece of a breakline, boundary or hole).
/// Stored with a < b.
struct ConstrainedEdge {
    VertexIndex a = no_vertex;
    VertexIndex b = no_vertex;
    ConstraintKind kind = ConstraintKind::breakline;
    friend bool operator==(const ConstrainedEdge&, const ConstrainedEdge&) = default;
};

/// A triangulated irregular network.
/// Invariants (checked by verify_topology): every triangle is counter-clockwise with three distinct
/// vertices; neighbour links are symmetric; every constrained edge is an edge of some triangle.
/// Canonical order (what libdtm returns): the order of vertices is the input order (first
/// occurrence; vertices added where breaklines cross come last); the order of triangles is
/// deterministic, a function of the input only (never of thread or tile counts), and spatially
/// coherent; constraints are sorted by (a, b).
struct Tin {
    std::vector<Point3> vertices;  ///< x, y in CRS units; z = elevation
    std::vector<Triangle> triangles;
    std::vector<ConstrainedEdge> constraints;

    [[nodiscard]] const Point3& vertex(VertexIndex i) const { return vertices[i]; }
};

/// One side of a triangle as a directed edge: side s of triangle t is the edge opposite v[s],
/// running from v[s + 1] to v[s + 2] (indices mod 3, counter-clockwise around t); n[s] is the
/// triangle on its other side.
struct HalfEdge {
    TriangleIndex triangle = no_triangle;
    std::uint8_t side = 0;
    friend bool operator==(const HalfEdge&, const HalfEdge&) = default;
};

[[nodiscard]] inline VertexIndex origin(const Tin& tin, HalfEdge e) {
    return tin.triangles[e.triangle].v[(e.side + 1U) % 3U];
}
[[nodiscard]] inline VertexIndex destination(const Tin& tin, HalfEdge e) {
    return tin.triangles[e.triangle].v[(e.side + 2U) % 3U];
}
/// The same edge seen from the triangle across it; triangle == no_triangle on the border.
[[nodiscard]] HalfEdge twin(const Tin& tin, HalfEdge e);

/// Sets every Triangle::n from the triangles' vertices: two triangles are neighbours when they
/// share an edge in opposite directions; edges of one triangle only get no_triangle. O(n).
/// @throws InputError (without a file) if an edge is used twice in the same direction (the
/// triangles overlap or are not consistently oriented), or there are too many triangles.
void link_neighbours(Tin& tin);

}  // namespace dtm
