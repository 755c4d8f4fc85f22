// SPDX-License-Identifier: MIT
/// @file
/// @brief Edge flips on a Tin and the criterion test of one edge, shared by the local-optimality
/// check (criteria.cpp) and the Lawson optimiser (optimize.cpp).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "dtm/algo/criteria.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// The constrained edges of a Tin, for O(log m) membership.
class ConstrainedEdgeSet {
public:
    explicit ConstrainedEdgeSet(const Tin& tin);
    [[nodiscard]] bool contains(VertexIndex a, VertexIndex b) const noexcept {
        const auto key = a < b ? std::pair{a, b} : std::pair{b, a};
        return std::binary_search(edges_.begin(), edges_.end(), key);
    }

private:
    std::vector<std::pair<VertexIndex, VertexIndex>> edges_;
};

/// The convex quadrilateral around the edge in slot @p slot of triangle @p t (the edge opposite
/// its vertex `slot`): t = (c, a, b), its neighbour u = (d, b, a); counter-clockwise boundary
/// c, a, d, b. `valid` is false for a border edge.
struct EdgeQuad {
    bool valid = false;
    TriangleIndex t = no_triangle;
    TriangleIndex u = no_triangle;
    int t_slot = 0;  ///< slot of the edge in t (t.v[t_slot] == c)
    int u_slot = 0;  ///< slot of the edge in u (u.v[u_slot] == d)
    VertexIndex a = no_vertex, b = no_vertex, c = no_vertex, d = no_vertex;
};
[[nodiscard]] EdgeQuad edge_quad(const Tin& tin, TriangleIndex t, int slot) noexcept;

/// True when both new triangles (c, a, d) and (d, b, c) would be strictly counter-clockwise.
[[nodiscard]] bool quad_is_convex(const Tin& tin, const EdgeQuad& q) noexcept;

/// Would flipping the quad's diagonal ab into cd strictly improve @p criterion? The caller has
/// checked that the edge is interior, unconstrained and its quadrilateral strictly convex.
[[nodiscard]] bool flip_improves(const Tin& tin, const EdgeQuad& q, Criterion criterion);

/// Whether the edge at (t, slot) is a candidate and a flip would improve it (all checks).
[[nodiscard]] bool edge_improvable(const Tin& tin,
                                   const ConstrainedEdgeSet& constrained,
                                   TriangleIndex t,
                                   int slot,
                                   Criterion criterion);

/// Replaces ab by cd: t becomes (c, a, d), u becomes (d, b, c); neighbour links updated.
void flip(Tin& tin, const EdgeQuad& q) noexcept;

}  // namespace dtm::detail
