// SPDX-License-Identifier: MIT
/// @file
/// @brief Working with the Voronoi diagrams of the Voronoi methods (MethodResult::voronoi):
/// the exact validator, edge directions, and the thesis' own DCEL form (Preparata-Shamos edge
/// nodes V1 V2 F1 F2 P1 P2 with the VRCHOL and OBLAST traversals, thesis 000 §3.3.2).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "dtm/algo/validate.hpp"
#include "dtm/core/point.hpp"
#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// Direction of half-edge @p h: rot90ccw(q - p), p the generator of its face, q of its twin's.
[[nodiscard]] Point2 voronoi_direction(const VoronoiDiagram& diagram,
                                       std::span<const Point3> generators,
                                       std::uint32_t h);

/// Destination of half-edge @p h (the origin of its twin; none = at infinity).
[[nodiscard]] inline std::uint32_t voronoi_destination(const VoronoiDiagram& d, std::uint32_t h) {
    return d.half_edges[h ^ 1u].origin;
}

/// Everything a Voronoi diagram of @p generators must satisfy, decided exactly:
/// - DCEL: twins pair up, next stays in the face and starts where the half-edge ends (at
///   infinity too), every face cycle closes, one cycle per distinct generator, face_edge names a
///   half-edge of the face (none exactly for the duplicates of an earlier point);
/// - topology: vertices of degree >= 3 whose faces are distinct, no two regions share two edges,
///   V - E + F = 1 (the plane with one point at infinity);
/// - geometry, exactly: the generators around each vertex are cocircular, counter-clockwise on
///   their circle, and every edge is locally Delaunay (the generator beyond an edge's end is not
///   inside the circle of the other end); unbounded edges separate hull neighbours; every vertex
///   position lies within 1e-6 relative of its generators' circumcentre.
/// @param exact_geometry false skips the geometric checks (topology only: for diagrams built
///   from deliberately corrupted predicates).
[[nodiscard]] CheckReport verify_voronoi(const VoronoiDiagram& diagram,
                                         std::span<const Point3> generators,
                                         bool exact_geometry = true);

/// The Preparata-Shamos DCEL of 000 §3.3.2: one node per edge with V1, V2 (start, end vertex;
/// none at infinity), F1, F2 (face on the left, on the right), P1, P2 (the edge that follows it
/// counter-clockwise around V1, around V2), and HV (one edge per vertex), HF (one edge per face).
struct EdgeNodeDcel {
    static constexpr std::uint32_t none = VoronoiDiagram::none;
    std::vector<std::uint32_t> v1, v2, f1, f2, p1, p2;
    std::vector<std::uint32_t> hv;  ///< per vertex
    std::vector<std::uint32_t> hf;  ///< per generator (none for duplicates)
};

/// Edge node e is the half-edge pair 2e, 2e + 1 (V1 = origin of 2e, F1 = face of 2e).
[[nodiscard]] EdgeNodeDcel edge_node_dcel(const VoronoiDiagram& diagram);

/// VRCHOL(j): the edges around vertex @p j counter-clockwise, in time proportional to its degree.
[[nodiscard]] std::vector<std::uint32_t> vrchol(const EdgeNodeDcel& dcel, std::uint32_t j);

/// OBLAST(j): the edges around the region of generator @p j clockwise (unbounded regions: from
/// one infinite edge to the other).
[[nodiscard]] std::vector<std::uint32_t> oblast(const EdgeNodeDcel& dcel, std::uint32_t j);

}  // namespace dtm::methods
