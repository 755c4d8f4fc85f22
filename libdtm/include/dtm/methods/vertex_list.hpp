// SPDX-License-Identifier: MIT
/// @file
/// @brief The "vertex list" (seznam vrcholů) of the thesis' uniform-grid method (000 §3.10.7):
/// for every vertex its neighbours in clockwise order, cyclic for interior vertices and open
/// for hull vertices (first and last are its hull neighbours; the hull's counter-clockwise
/// predecessor first). Triangles around v are (v, L[i], L[i+1]) (clockwise). It answers the
/// thesis' four queries in time proportional to the lists read.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::methods {

struct VertexList {
    std::vector<std::uint32_t> offset;  ///< per vertex, into around; size vertex count + 1
    std::vector<VertexIndex> around;    ///< the lists one after another
    std::vector<std::uint8_t> hull;     ///< 1 for an open (hull) list

    [[nodiscard]] std::size_t vertex_count() const noexcept {
        return offset.empty() ? 0 : offset.size() - 1;
    }
    [[nodiscard]] std::span<const VertexIndex> neighbours(VertexIndex v) const {
        return {around.data() + offset[v], around.data() + offset[v + 1]};
    }
    [[nodiscard]] bool is_hull(VertexIndex v) const { return hull[v] != 0; }
};

/// Receives each vertex's list as soon as it is complete: interior vertices during the sweep,
/// hull vertices at its end (R53).
using VertexListSink =
    std::function<void(VertexIndex v, std::span<const VertexIndex> clockwise, bool hull)>;

/// A vertex list from explicit lists (e.g. the thesis' figures).
[[nodiscard]] VertexList make_vertex_list(const std::vector<std::vector<VertexIndex>>& lists,
                                          const std::vector<bool>& hull);

/// The vertex list of a Tin (counter-clockwise triangles, linked).
[[nodiscard]] VertexList vertex_list_of(const Tin& tin);

using VertexTriangle = std::array<VertexIndex, 3>;

/// Query 1: the triangles at vertex v, (v, L[i], L[i+1]).
[[nodiscard]] std::vector<VertexTriangle> triangles_at_vertex(const VertexList& list,
                                                              VertexIndex v);
/// Query 2: the one or two triangles on edge a-b: (a, b, La[i+1]) where La[i] = b, and
/// (b, a, Lb[j+1]) where Lb[j] = a.
[[nodiscard]] std::vector<VertexTriangle> triangles_on_edge(const VertexList& list,
                                                            VertexIndex a,
                                                            VertexIndex b);
/// Query 3: the edges at vertex v, (v, L[i]).
[[nodiscard]] std::vector<std::pair<VertexIndex, VertexIndex>> edges_at_vertex(
    const VertexList& list, VertexIndex v);
/// Query 4: the triangles sharing an edge with triangle t = (a, b, c) (as listed by query 2).
[[nodiscard]] std::vector<VertexTriangle> neighbours_of_triangle(const VertexList& list,
                                                                 const VertexTriangle& t);
/// The hull vertices in order, starting at @p from (a hull vertex), each followed by the last
/// entry of its list (R50).
[[nodiscard]] std::vector<VertexIndex> hull_cycle(const VertexList& list, VertexIndex from);

/// The vertex list of the uniform-grid method's own sweep over @p points (distinct points,
/// not all collinear), each list streamed to @p sink when complete (if given).
[[nodiscard]] VertexList uniform_grid_vertex_list(std::span<const Point3> points,
                                                  const VertexListSink& sink = {});

}  // namespace dtm::methods
