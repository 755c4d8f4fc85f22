// SPDX-License-Identifier: MIT
/// @file
/// @brief The Guibas-Stolfi merge of the divide and conquer on triangles with ghosts, over any
/// mesh access: the kernel's GhostMesh (32-bit slots) and the distributed run's band of
/// triangles (64-bit global slots, dist/band_mesh.hpp) run this same code, so a merge across
/// ranks makes the same decisions and writes the same slots as the serial one.
///
/// A mesh access M provides: types Vertex and Edge (unsigned), M::ghost_vertex,
/// M::half_edge(slot, i), Vertex& org(Edge), Vertex dest(Edge), Edge& twin(Edge),
/// bond(Edge, Edge), set_triangle(slot, a, b, c), orient(a, b, c) and incircle(a, b, c, d) (the
/// exact predicates on the vertices' coordinates), and before(frame, a, b) (the strict order of
/// a cut's frame, kd_order.hpp). Half-edge i of slot t is (t << 2) | i for both.
///
/// References: L. Guibas, J. Stolfi, ACM Transactions on Graphics 4(2), 1985 (the merge);
/// J. R. Shewchuk, "Triangle", 1996 (ghost triangles, the merge as flips with the ghost vertex).
#pragma once

#include <array>
#include <cstdint>

namespace dtm::detail {

template <class E>
constexpr E edge_next(E h) noexcept {
    return (h & 3u) == 2 ? h - 2 : h + 1;
}
template <class E>
constexpr E edge_prev(E h) noexcept {
    return (h & 3u) == 0 ? h + 2 : h - 1;
}

/// Where a subtree's hull is entered by its parent's merge, in the parent's frame: the base of
/// the ghost triangle out of the last vertex (the left half's lower tangent search starts there)
/// and of the one into the first vertex (the right half's).
template <class E>
struct GhostHull {
    E last_out;
    E first_in;
};

/// The next ghost along the hull (outer face on the left): (a, b) -> (b, c).
template <class M>
typename M::Edge next_ghost(M& m, typename M::Edge base) {
    return edge_next(m.twin(edge_next(base)));
}
template <class M>
typename M::Edge prev_ghost(M& m, typename M::Edge base) {
    return edge_prev(m.twin(edge_prev(base)));
}

/// The hull handles in @p frame, found by walking the hull once from the ghost base @p start.
template <class M>
GhostHull<typename M::Edge> hull_handles(M& m, typename M::Edge start, int frame) {
    using Edge = typename M::Edge;
    using Vertex = typename M::Vertex;
    GhostHull<Edge> hull{start, start};
    Vertex last = m.org(start);
    Vertex first = m.dest(start);
    for (Edge g = next_ghost(m, start); g != start; g = next_ghost(m, g)) {
        const Vertex a = m.org(g);
        const Vertex b = m.dest(g);
        if (m.before(frame, last, a)) {
            last = a;
            hull.last_out = g;
        }
        if (m.before(frame, b, first)) {
            first = b;
            hull.first_in = g;
        }
    }
    return hull;
}

/// Deletes the edge of @p x, a half-edge a -> b of a real triangle (a, b, y) whose twin lies
/// in a ghost (b, a, ghost) facing the gap, by flipping it with the ghost vertex: the real
/// triangle becomes the ghost (a, ghost, y) and the ghost becomes (b, y, ghost). Half-edges
/// x (now a -> ghost) and y -> a keep their places.
template <class M>
void delete_by_ghost_flip(M& m, typename M::Edge x) {
    using Edge = typename M::Edge;
    using Vertex = typename M::Vertex;
    const Edge x1 = edge_next(x);   // b -> y
    const Edge g0 = m.twin(x);      // b -> a
    const Edge g1 = edge_next(g0);  // a -> ghost
    const Vertex y = m.org(edge_next(x1));
    const Edge across = m.twin(x1);
    const Edge outer = m.twin(g1);
    m.org(x1) = M::ghost_vertex;
    m.org(g1) = y;
    m.bond(x, outer);
    m.bond(g0, across);
    m.bond(x1, g1);
}

/// The Guibas-Stolfi merge on triangles. The left half lies before the right one in the
/// frame of the cut. Returns the base of a ghost on the merged hull.
///
/// The gap between the halves is covered by their ghosts; the merge adds two triangles: the
/// ghost below the lower tangent (permanent) and the "upper" ghost (l, r, ghost) above the
/// current base edge l - r. Each zip step turns the upper ghost into the real triangle
/// (l, r, c) and the ghost of the half the candidate c came from into the next upper ghost.
/// An edge of a half that the new edge would make non-Delaunay is deleted by flipping it
/// with the ghost vertex: its triangle becomes a ghost facing the gap (Shewchuk's scheme).
/// Every decision (tangent, candidates, deletions, choice) is the same as in the quad-edge
/// formulation, so the triangulation is the same.
template <class M>
typename M::Edge ghost_merge(M& m,
                             GhostHull<typename M::Edge> left,
                             GhostHull<typename M::Edge> right,
                             std::array<std::uint64_t, 2> slots) {
    using Edge = typename M::Edge;
    using Vertex = typename M::Vertex;
    // Lower common tangent: lg is a ghost base l -> x of the left half, rg one y -> r of
    // the right half.
    Edge lg = left.last_out;
    Edge rg = right.first_in;
    for (;;) {
        const Vertex l = m.org(lg);
        const Vertex r = m.dest(rg);
        if (m.orient(r, l, m.dest(lg)) > 0) {
            lg = next_ghost(m, lg);
        } else if (m.orient(l, m.org(rg), r) > 0) {
            rg = prev_ghost(m, rg);
        } else {
            break;
        }
    }
    Vertex l = m.org(lg);
    Vertex r = m.dest(rg);
    // The ghost below the tangent (r, l, ghost) and the upper ghost (l, r, ghost).
    const std::uint64_t below = slots[0];
    const std::uint64_t upper = slots[1];
    const Edge ghost_above_l = m.twin(edge_prev(lg));  // l -> ghost, in the ghost into l
    const Edge ghost_above_r = m.twin(edge_next(rg));  // ghost -> r, in the ghost out of r
    m.set_triangle(below, r, l, M::ghost_vertex);
    m.set_triangle(upper, l, r, M::ghost_vertex);
    m.bond(M::half_edge(below, 0), M::half_edge(upper, 0));
    m.bond(M::half_edge(below, 1), edge_prev(lg));
    m.bond(M::half_edge(below, 2), edge_next(rg));
    m.bond(M::half_edge(upper, 1), ghost_above_r);
    m.bond(M::half_edge(upper, 2), ghost_above_l);
    Edge up = M::half_edge(upper, 0);  // l -> r in the upper ghost

    for (;;) {
        const Edge up1 = edge_next(up);   // r -> ghost
        const Edge up2 = edge_next(up1);  // ghost -> l
        // Left candidate: l -> c, the edge of the left half next to the gap.
        Edge lcand = m.twin(edge_prev(m.twin(up2)));
        Vertex lc = m.dest(lcand);
        bool lvalid = lc != r && m.orient(lc, l, r) > 0;
        if (lvalid) {
            bool deleted = false;
            for (;;) {
                const Edge a1 = edge_next(lcand);  // c -> c2 in the triangle left of lcand
                const Vertex c2 = m.org(edge_next(a1));
                if (c2 == M::ghost_vertex || c2 == r || !m.incircle(l, r, lc, c2)) break;
                delete_by_ghost_flip(m, lcand);
                lcand = m.twin(edge_prev(lcand));  // l -> c2
                lc = c2;
                deleted = true;
            }
            if (deleted) lvalid = lc != r && m.orient(lc, l, r) > 0;
        }
        // Right candidate: r -> c, the base of the right half's ghost next to the gap.
        const Edge rcand = edge_next(m.twin(up1));
        Vertex rc = m.dest(rcand);
        bool rvalid = rc != l && m.orient(rc, l, r) > 0;
        if (rvalid) {
            bool deleted = false;
            for (;;) {
                const Edge b0 = m.twin(rcand);  // c -> r in the triangle right of rcand
                const Edge b1 = edge_next(b0);  // r -> d2
                const Vertex d2 = m.dest(b1);
                if (d2 == M::ghost_vertex || d2 == l || !m.incircle(l, r, rc, d2)) break;
                delete_by_ghost_flip(m, b0);  // rcand is now r -> d2
                rc = d2;
                deleted = true;
            }
            if (deleted) rvalid = rc != l && m.orient(rc, l, r) > 0;
        }
        if (!lvalid && !rvalid) break;
        if (!lvalid || (rvalid && m.incircle(lc, l, r, rc))) {
            // (l, r, rc); the right ghost (r, rc, ghost) becomes the upper ghost (l, rc,
            // ghost).
            const Edge below_rc = m.twin(rcand);  // rc -> r
            const Edge left_ghost = m.twin(up2);
            m.org(up2) = rc;
            m.org(rcand) = l;
            m.bond(up1, below_rc);
            m.bond(up2, rcand);
            m.bond(edge_next(edge_next(rcand)), left_ghost);
            up = rcand;
            r = rc;
        } else {
            // (l, r, lc); the left ghost (lc, l, ghost) becomes the upper ghost (lc, r, ghost).
            const Edge g0 = m.twin(lcand);
            const Edge g1 = edge_next(g0);
            const Edge right_ghost = m.twin(up1);
            m.org(up2) = lc;
            m.org(g1) = r;
            m.bond(up1, g0);
            m.bond(up2, lcand);
            m.bond(g1, right_ghost);
            up = g0;
            l = lc;
        }
    }
    return M::half_edge(below, 0);
}

}  // namespace dtm::detail
