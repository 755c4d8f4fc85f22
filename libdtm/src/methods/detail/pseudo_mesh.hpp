// SPDX-License-Identifier: MIT
/// @file
/// @brief The pseudo-triangulation under construction (thesis 001 §2-3): faces as
/// counter-clockwise vertex cycles, each directed edge mapped to the face on its left, the convex
/// hull as a linked cycle; point location by a straight walk; the three insertion cases.
///
/// Stands in for the winged-edge structure of [Trcka07] (thesis 001 §3): the same O(1)
/// questions (the two faces of an edge, the next edge along a face, the corner opposite a side)
/// are answered from the edge map and the face cycles; corners are not stored but read off the
/// geometry (a vertex is a corner of a face when its angle there is convex).
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "dtm/core/tin.hpp"
#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/uniform_grid.hpp"

namespace dtm::methods::detail {

using FaceId = std::uint32_t;
inline constexpr FaceId kOuterFace = 0xffffffffu;
using Cycle = std::vector<VertexIndex>;

/// Where a point lies in the current structure.
struct Location {
    enum Kind : std::uint8_t { inside, on_edge, on_vertex, outside } kind = inside;
    FaceId face = kOuterFace;   ///< inside: the face
    VertexIndex a = no_vertex;  ///< on_edge: the edge (a, b); on_vertex: a; outside: a visible
    VertexIndex b = no_vertex;  ///< hull edge a -> b (counter-clockwise along the hull)
};

class PseudoMesh {
public:
    PseudoMesh(std::span<const Point3> points, CountingPredicates& pred);

    [[nodiscard]] const Point3& point(VertexIndex v) const { return p_[v]; }
    [[nodiscard]] CountingPredicates& pred() { return pred_; }

    /// Starts the structure with the triangle (a, b, c), counter-clockwise.
    void start(VertexIndex a, VertexIndex b, VertexIndex c);

    /// Locates @p q from the inserted vertex nearest to it in the bucket grid.
    [[nodiscard]] Location locate(VertexIndex q);

    // ----- faces and edges ---------------------------------------------------------------------
    [[nodiscard]] const Cycle& cycle(FaceId f) const { return faces_[f]; }
    [[nodiscard]] bool alive(FaceId f) const { return alive_[f]; }
    [[nodiscard]] std::size_t face_slots() const { return faces_.size(); }
    [[nodiscard]] std::size_t face_count() const { return face_count_; }
    [[nodiscard]] std::size_t edge_count() const { return edge_count_; }
    /// The face left of the directed edge a -> b, kOuterFace outside the hull, or none (no edge).
    [[nodiscard]] FaceId left_face(VertexIndex a, VertexIndex b) const;
    [[nodiscard]] bool has_edge(VertexIndex a, VertexIndex b) const;
    /// Removes faces @p old and adds @p cycles in their place (the union must be the same
    /// region); updates the edge map. Returns the ids of the new faces.
    std::vector<FaceId> replace(std::span<const FaceId> old, std::span<const Cycle> cycles);
    /// Adds a face (for the hull growth), with its edges.
    FaceId add_face(Cycle cycle);

    // ----- the hull -----------------------------------------------------------------------------
    [[nodiscard]] VertexIndex hull_next(VertexIndex v) const { return hull_next_[v]; }
    [[nodiscard]] VertexIndex hull_prev(VertexIndex v) const { return hull_prev_[v]; }
    void hull_link(VertexIndex a, VertexIndex b) {
        hull_next_[a] = b;
        hull_prev_[b] = a;
    }
    void hull_unlink(VertexIndex v) { hull_next_[v] = hull_prev_[v] = no_vertex; }
    /// Marks @p v inserted (for the location grid).
    void mark_inserted(VertexIndex v);

    /// Every live face's cycle, in face order.
    [[nodiscard]] std::vector<Cycle> faces() const;

private:
    [[nodiscard]] static std::uint64_t key(VertexIndex a, VertexIndex b) {
        return (std::uint64_t{a} << 32) | b;
    }
    void set_edges(FaceId f, const Cycle& c);
    void clear_edges(FaceId f);
    [[nodiscard]] VertexIndex nearest_inserted(const Point3& q) const;
    /// The face around @p s whose angle at s holds the direction to q (kOuterFace if none);
    /// sets @p along when the direction runs along an edge s -> along.
    [[nodiscard]] FaceId face_towards(VertexIndex s, const Point3& q, VertexIndex& along);

    std::span<const Point3> p_;
    CountingPredicates& pred_;
    std::vector<Cycle> faces_;
    std::vector<bool> alive_;
    std::vector<FaceId> free_;
    std::size_t face_count_ = 0;
    std::size_t edge_count_ = 0;
    std::unordered_map<std::uint64_t, FaceId> left_;  ///< directed edge -> face on its left
    std::vector<FaceId> some_face_;                   ///< per vertex, a face around it
    std::vector<VertexIndex> hull_next_, hull_prev_;
    UniformGrid grid_;
    std::vector<bool> inserted_;
};

/// True when vertex i of @p c is a convex corner (strict left turn prev -> c[i] -> next).
[[nodiscard]] bool is_corner(std::span<const Point3> p,
                             const Cycle& c,
                             std::size_t i,
                             CountingPredicates& pred);
/// Positions in @p c of its convex corners, in cycle order.
[[nodiscard]] std::vector<std::size_t> corners(std::span<const Point3> p,
                                               const Cycle& c,
                                               CountingPredicates& pred);

}  // namespace dtm::methods::detail
