// SPDX-License-Identifier: MIT
/// @file
/// @brief Editing a Delaunay edge mesh into a constrained Delaunay one: point insertion with
/// Lawson flips, and segment (breakline) insertion by cavity retriangulation.
#pragma once

#include <cstdint>
#include <vector>

#include "algo/detail/edge_mesh.hpp"
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
    EdgeId e;  ///< face: p in the left face of e; edge: p on e; vertex: p == org(e)
};

class MeshEditor {
public:
    /// @param z heights per vertex, grown with every vertex added.
    MeshEditor(EdgeMesh& mesh, EdgeSlots& slots, std::vector<double>& z, double z_tolerance);

    /// Locate @p p starting the walk at @p hint (any live edge).
    [[nodiscard]] Location locate(Point2 p, EdgeId hint);
    /// Any live edge out of @p v (no_edge for an isolated vertex).
    [[nodiscard]] EdgeId edge_of(VertexId v) const { return vertex_edge_[v]; }

    /// Inserts a vertex at @p p with height @p z (returns the existing vertex at p if any).
    /// @pre p is inside the triangulated hull.
    VertexId insert_point(Point2 p, double z, EdgeId hint);

    /// Makes the segment a-b a chain of constrained edges with the given ConstraintBits,
    /// splitting it at vertices it passes through and at crossings with other constraints.
    void insert_segment(VertexId a, VertexId b, std::uint8_t bits);

    [[nodiscard]] const std::vector<Crossing>& crossings() const noexcept { return crossings_; }

    /// One piece of a segment: from a vertex to the next vertex reached along it.
    struct PiecePlan {
        VertexId from = 0;
        VertexId to = 0;                      ///< the segment's end, or a vertex exactly on it
        EdgeId along = no_edge;               ///< an existing edge from -> to
        EdgeId crossed_constraint = no_edge;  ///< the walk met this constrained edge
        std::vector<EdgeId> crossed;          ///< edges the piece crosses (the cavity)
        std::vector<EdgeId> right_chain;      ///< cavity boundary right of the piece, from -> to
        std::vector<EdgeId> left_chain;       ///< cavity boundary left of it, to -> from
    };
    /// The whole insertion of a segment, planned on the current mesh without changing it.
    /// Filled again for every segment: the vectors keep their memory (no allocation per plan in
    /// the parallel rounds once the plans have grown).
    struct SegmentPlan {
        std::vector<PiecePlan> pieces;   ///< the first piece_count are this plan's
        std::size_t piece_count = 0;
        std::vector<VertexId> vertices;  ///< every vertex whose edges the insertion changes
        bool crosses_constraint = false; ///< must go through insert_segment instead
    };

    /// Read-only: plans the insertion of a-b into @p plan. Safe to call from several threads at
    /// once (with different plans).
    void plan_segment(VertexId a, VertexId b, SegmentPlan& plan) const;
    /// Applies a plan made on the current mesh, allocating edges from @p slots (the plan's own
    /// deleted edges suffice). Plans whose vertex sets are disjoint may be applied concurrently.
    void apply_segment(const SegmentPlan& plan, std::uint8_t bits, EdgeSlots& slots);

private:
    struct Work {
        VertexId a;
        VertexId b;
        std::uint8_t bits;
    };

    [[nodiscard]] int orient(VertexId a, VertexId b, VertexId c) const
    {
        return geom::orient2d(mesh_.p(a), mesh_.p(b), mesh_.p(c));
    }
    [[nodiscard]] int orient_p(VertexId a, VertexId b, Point2 c) const
    {
        return geom::orient2d(mesh_.p(a), mesh_.p(b), c);
    }
    /// The left face of e is a counter-clockwise triangle (not the outer face).
    [[nodiscard]] bool is_triangle(EdgeId e) const
    {
        const EdgeId e1 = mesh_.lnext(e);
        const EdgeId e2 = mesh_.lnext(e1);
        return mesh_.lnext(e2) == e && orient(mesh_.org[e], mesh_.dest(e), mesh_.dest(e1)) > 0;
    }
    [[nodiscard]] EdgeId find_edge(VertexId a, VertexId b) const;
    void ensure_slots(std::size_t count);
    VertexId add_vertex(Point2 p, double z);
    void delete_edge(EdgeId e, EdgeSlots& slots);
    void flip(EdgeId e);
    void legalize(EdgeId e);
    void plan_piece(VertexId u, VertexId w, PiecePlan& plan) const;
    void apply_piece(const PiecePlan& plan, std::uint8_t bits, EdgeSlots& slots);
    void insert_piece(const Work& work, std::vector<Work>& stack);
    void cross_constraint(VertexId u, VertexId w, std::uint8_t bits, EdgeId f,
                          std::vector<Work>& stack);
    void fill_cavity(EdgeId base, const std::vector<EdgeId>& edges, EdgeSlots& slots);

    EdgeMesh& mesh_;
    EdgeSlots& slots_;
    std::vector<double>& z_;
    double z_tolerance_;
    std::vector<EdgeId> vertex_edge_;
    std::vector<Crossing> crossings_;
    PiecePlan piece_scratch_;  ///< insert_piece's plan, its memory kept from piece to piece
    std::uint64_t rng_ = 0x9e3779b97f4a7c15ull;
};

}  // namespace dtm::detail
