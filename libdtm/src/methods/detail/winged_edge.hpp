// SPDX-License-Identifier: MIT
/// @file
/// @brief The winged-edge structure of the thesis (000 §3.8.1, after [SKA92]) and incremental
/// Delaunay insertion on it (§3.8: the containing triangle split at the new point, the edges
/// opposite it tested against the empty-circle criterion and swapped, recursively), with the
/// point location by "walking on the wings".
///
/// Three lists, as in Fig. 4: the vertices (coordinates: the input points plus the three
/// corners of the auxiliary triangle T_pom, here symbolic, detail/super_triangle.hpp), the
/// edges [v1 v2 | e11 e21 | e12 e22 | T1 T2] and the triangles {3 edges}. Edge e runs v1->v2;
/// T1 is the triangle on its left, T2 on its right; e12 and e22 are the left triangle's other
/// edges at v1 and at v2 (first counter-clockwise at v1, first clockwise at v2), e11 and e21
/// the right triangle's (first clockwise at v1, first counter-clockwise at v2). A triangle
/// lists its edges counter-clockwise. After every change the wings of the sides of every
/// triangle rewritten are set from its edge list (the walk and the legalization read the
/// quadrilateral around an edge from its wings), and check() verifies the whole structure.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dtm/core/tin.hpp"
#include "methods/detail/super_triangle.hpp"

namespace dtm::methods::detail {

using EdgeIndex = std::uint32_t;
inline constexpr EdgeIndex no_edge = 0xffffffffu;

struct WingedEdgeRecord {
    VertexIndex v1 = no_vertex;
    VertexIndex v2 = no_vertex;
    EdgeIndex e11 = no_edge;         ///< at v1, first clockwise (right triangle)
    EdgeIndex e21 = no_edge;         ///< at v2, first counter-clockwise (right triangle)
    EdgeIndex e12 = no_edge;         ///< at v1, first counter-clockwise (left triangle)
    EdgeIndex e22 = no_edge;         ///< at v2, first clockwise (left triangle)
    TriangleIndex t1 = no_triangle;  ///< left
    TriangleIndex t2 = no_triangle;  ///< right
};

struct WingedTriangle {
    std::array<EdgeIndex, 3> e{};  ///< counter-clockwise
};

class WingedEdgeDelaunay {
public:
    /// Room for @p points plus the three corners; the triangulation starts as T_pom.
    WingedEdgeDelaunay(const std::vector<Point3>& points, CountingPredicates& predicates);

    /// Inserts point @p p, locating it by a walk from the triangle of @p start (no_edge: the
    /// last edge the previous walk crossed). Returns the walk's steps.
    std::uint64_t insert(VertexIndex p, EdgeIndex start = no_edge);

    /// The triangle containing @p p (closed), by the walk from @p start's left (or right)
    /// triangle; @p steps counts the triangles visited. Every side of the triangle found is
    /// tested on the way; the one with p on its line (if any) is kept for insert().
    [[nodiscard]] TriangleIndex locate(VertexIndex p, EdgeIndex start, std::uint64_t& steps);

    /// An edge out of vertex @p v (no_edge before v is inserted).
    [[nodiscard]] EdgeIndex edge_of(VertexIndex v) const noexcept { return vertex_edge_[v]; }
    [[nodiscard]] EdgeIndex last_edge() const noexcept { return last_; }
    [[nodiscard]] std::uint64_t flips() const noexcept { return flips_; }
    [[nodiscard]] const std::vector<WingedEdgeRecord>& edges() const noexcept { return edges_; }
    [[nodiscard]] const std::vector<WingedTriangle>& triangles() const noexcept { return tris_; }
    [[nodiscard]] SuperTriangle& super() noexcept { return st_; }
    /// The corners of triangle @p t, counter-clockwise, starting at the origin of its edge 0.
    [[nodiscard]] std::array<VertexIndex, 3> corners(TriangleIndex t) const noexcept;
    [[nodiscard]] std::size_t bytes() const noexcept;

    /// Every invariant: edges' triangles list them, triangles' edges chain head to tail
    /// counter-clockwise, wings equal the recomputed ones. Empty when consistent.
    [[nodiscard]] std::string check() const;

    /// The Delaunay triangulation without the corners' triangles, as Tin triangles (linked).
    [[nodiscard]] std::vector<Triangle> real_triangles() const;

    /// real_triangles(), in the same order with the same links, built with little memory
    /// beyond the result: the links (12 bytes per triangle) read from the edges, the corners
    /// written over the triangle list, the edges freed, then the result assembled. The
    /// structure is empty afterwards. Its peak: bytes() + release_extra_bytes().
    [[nodiscard]] std::vector<Triangle> release_triangles();
    [[nodiscard]] std::size_t release_extra_bytes() const noexcept {
        return tris_.size() * sizeof(std::array<TriangleIndex, 3>);
    }

private:
    /// The triangles touching a corner of T_pom, ascending (O(hull) many).
    [[nodiscard]] std::vector<TriangleIndex> corner_triangles() const;
    /// A kept triangle's number once the @p dropped ones are gone; no_triangle for a dropped one.
    [[nodiscard]] static TriangleIndex kept_number(const std::vector<TriangleIndex>& dropped,
                                                   TriangleIndex t);
    [[nodiscard]] VertexIndex origin_in(EdgeIndex e, TriangleIndex t) const noexcept {
        return edges_[e].t1 == t ? edges_[e].v1 : edges_[e].v2;
    }
    [[nodiscard]] TriangleIndex other_side(EdgeIndex e, TriangleIndex t) const noexcept {
        return edges_[e].t1 == t ? edges_[e].t2 : edges_[e].t1;
    }
    [[nodiscard]] int position(TriangleIndex t, EdgeIndex e) const noexcept {
        const auto& x = tris_[t].e;
        return x[0] == e ? 0 : (x[1] == e ? 1 : 2);
    }
    /// The end of edge @p e that is not @p v.
    [[nodiscard]] VertexIndex far_end(EdgeIndex e, VertexIndex v) const noexcept {
        return edges_[e].v1 == v ? edges_[e].v2 : edges_[e].v1;
    }
    EdgeIndex new_edge(VertexIndex a, VertexIndex b);
    /// The wings of side @p w on the side of triangle @p t, where it is followed by @p next
    /// and preceded by @p prev (counter-clockwise).
    void set_wing(EdgeIndex w, TriangleIndex t, EdgeIndex next, EdgeIndex prev) noexcept;
    /// The wings of all three sides of @p t on its side.
    void wing_triangle(TriangleIndex t) noexcept;
    TriangleIndex new_triangle();
    void replace_side(EdgeIndex e, TriangleIndex from, TriangleIndex to) noexcept;
    void split_triangle(TriangleIndex t, VertexIndex p);
    void split_edge(TriangleIndex t, int k, VertexIndex p);
    void legalize(VertexIndex p);
    void flip(EdgeIndex e);

    const std::vector<Point3>& pts_;
    SuperTriangle st_;
    std::vector<WingedEdgeRecord> edges_;
    std::vector<WingedTriangle> tris_;
    std::vector<EdgeIndex> vertex_edge_;
    std::vector<EdgeIndex> pending_;  ///< edges opposite the new point, to test
    EdgeIndex last_ = 0;
    int on_side_ = -1;  ///< after locate(): the side of the triangle found with p on its line
    std::uint64_t flips_ = 0;
};

}  // namespace dtm::methods::detail
