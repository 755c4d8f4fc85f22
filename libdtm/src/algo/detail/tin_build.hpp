// SPDX-License-Identifier: MIT
/// @file
/// @brief From the kernel's triangles to a Tin: triangles with neighbour links, the domain
/// (boundary, holes, hole seeds, maximum edge length) and the canonical order.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "algo/detail/ghost_mesh.hpp"
#include "dtm/algo/triangulate.hpp"

namespace dtm::detail {

/// A Tin under construction: per triangle, the ConstraintBits of the edge opposite v[i].
struct TinDraft {
    Tin tin;
    /// Per triangle; empty when no edge of the TIN is constrained (nothing to store or scan).
    std::vector<std::array<std::uint8_t, 3>> edge_bits;

    [[nodiscard]] bool any_constraint() const noexcept { return !edge_bits.empty(); }
    [[nodiscard]] std::uint8_t bits(std::size_t t, int i) const noexcept {
        return edge_bits.empty() ? 0 : edge_bits[t][static_cast<std::size_t>(i)];
    }
};

/// The real triangles of @p ghosts as the Tin's, in place (tin_build_triangles.cpp), with their
/// constraint bits when ghosts.bits is not empty; vertex v of the kernel becomes
/// ghosts.points[v].id. Consumes @p ghosts.
[[nodiscard]] TinDraft ghost_mesh_to_tin(GhostMesh& ghosts, std::vector<Point3> vertices);

/// Removes the triangles outside the boundaries, inside holes (rings and seeds) and, with
/// options.max_edge, the long border triangles. @return the number removed.
std::size_t apply_domain(TinDraft& draft,
                         bool has_boundary,
                         const std::vector<Point2>& hole_seeds,
                         double max_edge);

/// Peels border triangles whose border edge is unconstrained and longer than @p max_edge,
/// repeatedly from the outside inwards. @return the number removed.
std::size_t trim_long_edges(TinDraft& draft, double max_edge);

/// Drops the triangles with keep[t] == false and fixes the neighbour links.
void compact(TinDraft& draft, const std::vector<bool>& keep);

/// Canonical order (see Tin) and the constraint list.
void finish_tin(TinDraft& draft);

/// The kind a TIN lists for an edge with these ConstraintBits (the strongest of them).
[[nodiscard]] inline ConstraintKind constraint_kind_of(std::uint8_t bits) noexcept {
    if (bits & constraint_boundary) return ConstraintKind::boundary;
    if (bits & constraint_hole) return ConstraintKind::hole;
    if (bits & constraint_breakline) return ConstraintKind::breakline;
    return ConstraintKind::soft_breakline;
}

}  // namespace dtm::detail
