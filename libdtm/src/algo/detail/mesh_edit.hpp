// SPDX-License-Identifier: MIT
/// @file
/// @brief Editing the kernel's Delaunay triangles (with ghosts) into a constrained Delaunay
/// triangulation: point insertion with Lawson flips, and segment (breakline) insertion by cavity
/// retriangulation.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "algo/detail/ghost_mesh.hpp"
#include "dtm/core/point.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {

/// Two constraints cross; where, and the height of each line there.
struct Crossing {
    Point2 at;
    double z_first;   ///< height of the constraint already in the mesh
    double z_second;  ///< height of the constraint being inserted
    bool conflict;    ///< |z_first - z_second| > tolerance
};

/// Where a point lies relative to the mesh.
struct Location {
    enum class Kind { face, edge, vertex, outside } kind;
    /// face: p in the (real) triangle of e; edge: p on e, whose triangle is real; vertex:
    /// p == org(e); outside: e is a hull edge p is beyond.
    HalfEdge e;
};

class MeshEditor {
public:
    /// Edits @p mesh in place (its constraint bits are created, all zero).
    /// @param z heights per vertex, grown with every vertex added.
    MeshEditor(GhostMesh& mesh, std::vector<double>& z, double z_tolerance);

    /// Locate @p p starting the walk at @p hint (any half-edge of the mesh).
    [[nodiscard]] Location locate(Point2 p, HalfEdge hint);
    /// A half-edge out of @p v.
    [[nodiscard]] HalfEdge edge_of(VertexId v) const { return vertex_edge_[v]; }

    /// Inserts a vertex at @p p with height @p z (returns the existing vertex at p if any).
    /// @pre p is inside the triangulated hull.
    VertexId insert_point(Point2 p, double z, HalfEdge hint);

    /// Makes the segment a-b a chain of constrained edges with the given ConstraintBits,
    /// splitting it at vertices it passes through and at crossings with other constraints.
    /// Not for several threads at once.
    void insert_segment(VertexId a, VertexId b, std::uint8_t bits);
    /// Hints the caches at what insert_segment(a, b) reads first, in two steps a few segments
    /// apart: the vertex's edge and both points, then (@p star) the triangle of that edge.
    void prefetch(VertexId a, VertexId b, bool star) const noexcept;

    [[nodiscard]] const std::vector<Crossing>& crossings() const noexcept { return crossings_; }

    /// One piece of a segment: from a vertex to the next vertex reached along it.
    struct PiecePlan {
        VertexId from = 0;
        VertexId to = 0;                             ///< the segment's end, or a vertex on it
        HalfEdge along = no_half_edge;               ///< an existing edge from -> to
        HalfEdge crossed_constraint = no_half_edge;  ///< the walk met this constrained edge
        std::vector<std::uint32_t> cavity;           ///< the triangles the piece crosses
        std::vector<HalfEdge> right_chain;  ///< cavity boundary right of the piece, from -> to
        std::vector<HalfEdge> left_chain;   ///< cavity boundary left of it, to -> from
    };
    /// The whole insertion of a segment, planned on the current mesh without changing it.
    /// Filled again for every segment: the vectors keep their memory (no allocation per plan in
    /// the parallel rounds once the plans have grown).
    struct SegmentPlan {
        std::vector<PiecePlan> pieces;  ///< the first piece_count are this plan's
        std::size_t piece_count = 0;
        std::vector<VertexId> vertices;   ///< every vertex whose triangles the insertion changes
        bool crosses_constraint = false;  ///< must go through insert_segment instead
    };

    /// Read-only: the half-edge a -> b when a-b is an edge of the mesh, else no_half_edge (a
    /// turn around @p a comparing vertex ids: no predicate). Safe from several threads at once.
    [[nodiscard]] HalfEdge edge_between(VertexId a, VertexId b) const noexcept {
        const HalfEdge start = vertex_edge_[a];
        HalfEdge e = start;
        do {
            if (mesh_.dest(e) == b) return e;
            e = mesh_.twin(prev(e));  // the next edge counter-clockwise around a
        } while (e != start);
        return no_half_edge;
    }
    /// Read-only: plans the insertion of a-b into @p plan. Safe to call from several threads at
    /// once (with different plans).
    void plan_segment(VertexId a, VertexId b, SegmentPlan& plan) const;
    /// Adds @p bits to the edge of @p h (both half-edges), a segment planned as that one edge.
    /// Calls on different edges may run concurrently (each half-edge's bits are a byte of its own).
    void mark_edge(HalfEdge h, std::uint8_t bits) noexcept {
        mesh_.set_edge_bits(h, mesh_.edge_bits(h) | bits);
    }
    /// Applies a plan made on the current mesh; the new triangles take the slots of the cavity's.
    /// Plans whose vertex sets are disjoint may be applied concurrently.
    void apply_segment(const SegmentPlan& plan, std::uint8_t bits);

private:
    struct Work {
        VertexId a;
        VertexId b;
        std::uint8_t bits;
    };

    [[nodiscard]] int orient(VertexId a, VertexId b, VertexId c) const {
        return geom::orient2d(mesh_.p(a), mesh_.p(b), mesh_.p(c));
    }
    [[nodiscard]] int orient_p(VertexId a, VertexId b, Point2 c) const {
        return geom::orient2d(mesh_.p(a), mesh_.p(b), c);
    }
    /// Writes triangle @p t = (a, b, c) and makes it the known edge out of its corners.
    void set_triangle(std::size_t t, VertexId a, VertexId b, VertexId c);
    /// Links @p x and @p y as twins; @p x takes the constraint bits @p bits, and so does @p y.
    void bond(HalfEdge x, HalfEdge y, std::uint8_t bits);
    /// A new, unlinked triangle slot.
    std::size_t new_triangle();
    VertexId add_vertex(Point2 p, double z);
    /// The two triangles (a, b, c) and (b, a, d) around the edge of half-edge x = a -> b, and the
    /// twins and constraint bits of their outer sides b-c, c-a, a-d, d-b.
    struct Quad {
        std::size_t t1 = 0;
        std::size_t t2 = 0;
        VertexId a = 0, b = 0, c = 0, d = 0;
        std::array<HalfEdge, 4> outside{};
        std::array<std::uint8_t, 4> bits{};
    };
    [[nodiscard]] Quad quad(HalfEdge x) const;
    /// Flips the edge of @p x (both of its triangles real): (a, b, c) and (b, a, d) become
    /// (c, a, d) and (d, b, c) in the same slots. Returns the half-edge d -> c of the first.
    HalfEdge flip(HalfEdge x);
    /// Lawson flips from the edge of @p x outwards until every unconstrained edge is Delaunay.
    void legalize(HalfEdge x);
    void plan_piece(VertexId u, VertexId w, PiecePlan& plan) const;
    void apply_piece(const PiecePlan& plan, std::uint8_t bits);
    struct Polygon;
    /// Triangulates one side of a cavity by the constrained Delaunay rule into the triangle
    /// slots slots[next_slot...]; its base is bonded to @p base_twin (when known) with
    /// @p base_bits; the new half-edges of doubled boundary edges go to @p made. Returns the
    /// base half-edge.
    HalfEdge fill_polygon(const Polygon& polygon,
                          const std::vector<std::uint32_t>& slots,
                          std::size_t& next_slot,
                          HalfEdge base_twin,
                          std::uint8_t base_bits,
                          std::vector<HalfEdge>& made);
    void insert_piece(const Work& work, std::vector<Work>& stack);
    void cross_constraint(
        VertexId u, VertexId w, std::uint8_t bits, HalfEdge f, std::vector<Work>& stack);

    GhostMesh& mesh_;
    std::vector<double>& z_;
    double z_tolerance_;
    std::vector<HalfEdge> vertex_edge_;
    std::vector<Crossing> crossings_;
    PiecePlan piece_scratch_;         ///< insert_piece's plan, its memory kept from piece to piece
    std::vector<Work> work_scratch_;  ///< insert_segment's stack, kept likewise
    std::uint64_t rng_ = 0x9e3779b97f4a7c15ull;
};

}  // namespace dtm::detail
