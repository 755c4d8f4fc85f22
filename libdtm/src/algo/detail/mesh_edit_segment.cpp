// SPDX-License-Identifier: MIT
//
// Segment insertion into the triangles (see mesh_edit.cpp for the method and references): the
// walk along the segment, the cavity retriangulation, and crossings of two constraints.
#include <algorithm>
#include <cmath>

#include "algo/detail/mesh_edit.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

/// Collinear q lies on the ray from a through b (same direction), decided by comparisons only.
bool same_direction(const Point2& a, const Point2& b, const Point2& q) {
    const auto sign = [](double from, double to) { return (to > from) - (to < from); };
    return sign(a.x, q.x) == sign(a.x, b.x) && sign(a.y, q.y) == sign(a.y, b.y);
}

}  // namespace

void MeshEditor::plan_piece(VertexId u, VertexId w, PiecePlan& plan) const {
    const GhostMesh& m = mesh_;
    const auto side = [&](VertexId v) { return orient(u, w, v); };
    plan.from = u;
    plan.to = w;
    plan.along = no_half_edge;
    plan.crossed_constraint = no_half_edge;
    plan.cavity.clear();
    plan.right_chain.clear();
    plan.left_chain.clear();

    // 1. Find the edge along u->w, or the triangle at u that the segment enters: (u, p, q) with
    // p right of the segment and q left of it.
    const HalfEdge start = vertex_edge_[u];
    HalfEdge e = start;
    HalfEdge sector = no_half_edge;
    do {
        const VertexId p = m.dest(e);
        if (p != ghost) {
            const int side_p = side(p);
            if (side_p == 0 && same_direction(m.p(u), m.p(w), m.p(p))) {
                plan.along = e;
                plan.to = p;
                return;
            }
            if (side_p < 0 && m.is_real(e) && side(m.org(prev(e))) > 0) {
                sector = e;
                break;
            }
        }
        e = m.twin(prev(e));  // the next edge counter-clockwise around u
    } while (e != start);
    if (sector == no_half_edge)
        throw Error("triangulation: breakline leaves the triangulated hull");

    // 2. Walk through the crossed triangles, collecting them and the cavity boundary (inner
    // half-edges: the cavity on their left).
    plan.cavity.push_back(static_cast<std::uint32_t>(tri_of(sector)));
    plan.right_chain.push_back(sector);       // u -> ... -> to
    plan.left_chain.push_back(prev(sector));  // reversed below: to -> ... -> u
    HalfEdge f = next(sector);                // crossed, from the right side to the left side
    for (;;) {
        if (m.edge_bits(f) != 0) {
            plan.crossed_constraint = f;
            return;
        }
        const HalfEdge g = m.twin(f);  // in the next triangle (q, p, v)
        const VertexId v = m.org(prev(g));
        if (v == ghost) throw Error("triangulation: breakline leaves the triangulated hull");
        plan.cavity.push_back(static_cast<std::uint32_t>(tri_of(g)));
        const int s = v == w ? 0 : side(v);
        if (s == 0) {
            plan.right_chain.push_back(next(g));
            plan.left_chain.push_back(prev(g));
            plan.to = v;
            break;
        }
        if (s < 0) {
            plan.right_chain.push_back(next(g));
            f = prev(g);
        } else {
            plan.left_chain.push_back(prev(g));
            f = next(g);
        }
    }
    std::reverse(plan.left_chain.begin(), plan.left_chain.end());
}

/// One side of a cavity: the polygon's vertices in order, the outer twin and the constraint
/// bits of each boundary edge (vertex i -> i + 1); the closing base runs from the last vertex
/// back to the first. An edge both of whose triangles are in the cavity without being crossed
/// (the segment passes around its end, whose whole star it crosses) lies on the boundary twice,
/// once in each direction: its two boundary edges are linked to each other (`partner`, an index
/// into both sides' edges, right first) once both new triangles exist.
struct MeshEditor::Polygon {
    std::vector<VertexId> vertex;
    std::vector<HalfEdge> outside;
    std::vector<std::uint8_t> bits;
    std::vector<std::uint32_t> partner;
    std::size_t first = 0;  ///< index of this side's first edge among both sides' edges

    void clear() {
        vertex.clear();
        outside.clear();
        bits.clear();
        partner.clear();
    }
};

void MeshEditor::apply_piece(const PiecePlan& plan, std::uint8_t bits) {
    GhostMesh& m = mesh_;
    if (plan.along != no_half_edge) {
        m.set_edge_bits(plan.along, m.edge_bits(plan.along) | bits);
        return;
    }
    // Read both sides before the cavity's slots are rewritten.
    constexpr std::uint32_t none = 0xffffffffu;
    thread_local Polygon right;
    thread_local Polygon left;
    thread_local std::vector<std::pair<HalfEdge, std::uint32_t>> boundary;  // sorted by code
    thread_local std::vector<HalfEdge> made;  // the new half-edge of every boundary edge
    right.clear();
    left.clear();
    boundary.clear();
    std::uint32_t id = 0;
    for (const auto& [chain, polygon] :
         {std::pair{&plan.right_chain, &right}, std::pair{&plan.left_chain, &left}}) {
        polygon->first = id;
        for (const HalfEdge h : *chain) {
            polygon->vertex.push_back(m.org(h));
            polygon->outside.push_back(m.twin(h));
            polygon->bits.push_back(m.edge_bits(h));
            boundary.emplace_back(h, id++);
        }
        polygon->vertex.push_back(m.dest(chain->back()));
    }
    std::sort(boundary.begin(), boundary.end());
    for (Polygon* polygon : {&right, &left}) {
        for (const HalfEdge out : polygon->outside) {
            const auto at = std::lower_bound(boundary.begin(), boundary.end(),
                                             std::pair<HalfEdge, std::uint32_t>{out, 0});
            polygon->partner.push_back(at != boundary.end() && at->first == out ? at->second
                                                                                : none);
        }
    }
    made.assign(id, no_half_edge);
    std::size_t next_slot = 0;
    const HalfEdge base = fill_polygon(right, plan.cavity, next_slot, no_half_edge, bits, made);
    fill_polygon(left, plan.cavity, next_slot, base, bits, made);
    for (const Polygon* polygon : {&right, &left}) {
        for (std::size_t i = 0; i < polygon->partner.size(); ++i) {
            const std::uint32_t other = polygon->partner[i];
            const std::size_t self = polygon->first + i;
            if (other != none && self < other) bond(made[self], made[other], polygon->bits[i]);
        }
    }
}

HalfEdge MeshEditor::fill_polygon(const Polygon& polygon,
                                  const std::vector<std::uint32_t>& slots,
                                  std::size_t& next_slot,
                                  HalfEdge base_twin,
                                  std::uint8_t base_bits,
                                  std::vector<HalfEdge>& made) {
    // Explicit stack of sub-polygons: vertices [lo, hi] with the base hi -> lo, and what the base
    // is bonded to (the parent triangle's edge, or for the whole polygon @p base_twin).
    struct Sub {
        std::size_t lo;
        std::size_t hi;
        HalfEdge twin;
        std::uint8_t bits;
    };
    const std::vector<VertexId>& v = polygon.vertex;
    // A boundary edge is linked to the triangle outside, or (a doubled edge) noted for its
    // partner.
    const auto boundary = [&](HalfEdge h, std::size_t i) {
        if (polygon.partner[i] == 0xffffffffu) {
            bond(h, polygon.outside[i], polygon.bits[i]);
        } else {
            made[polygon.first + i] = h;
        }
    };
    thread_local std::vector<Sub> subs;
    subs.assign(1, {0, v.size() - 1, base_twin, base_bits});
    HalfEdge first_base = no_half_edge;
    while (!subs.empty()) {
        const Sub sub = subs.back();
        subs.pop_back();
        const VertexId a = v[sub.lo];
        const VertexId b = v[sub.hi];
        std::size_t best = sub.lo + 1;
        for (std::size_t j = sub.lo + 2; j < sub.hi; ++j) {
            if (geom::incircle(mesh_.p(b), mesh_.p(a), mesh_.p(v[best]), mesh_.p(v[j])) > 0) {
                best = j;
            }
        }
        const std::size_t t = slots[next_slot++];
        set_triangle(t, b, a, v[best]);  // b -> a (base), a -> c, c -> b
        if (sub.twin != no_half_edge) {
            bond(half_edge(t, 0), sub.twin, sub.bits);
        } else {
            first_base = half_edge(t, 0);
        }
        if (best == sub.lo + 1) {
            boundary(half_edge(t, 1), sub.lo);
        } else {
            subs.push_back({sub.lo, best, half_edge(t, 1), 0});
        }
        if (best == sub.hi - 1) {
            boundary(half_edge(t, 2), sub.hi - 1);
        } else {
            subs.push_back({best, sub.hi, half_edge(t, 2), 0});
        }
    }
    return first_base;
}

void MeshEditor::insert_piece(const Work& work, std::vector<Work>& stack) {
    PiecePlan& plan = piece_scratch_;
    plan_piece(work.a, work.b, plan);
    if (plan.crossed_constraint != no_half_edge) {
        cross_constraint(work.a, work.b, work.bits, plan.crossed_constraint, stack);
        return;
    }
    apply_piece(plan, work.bits);
    if (plan.to != work.b) stack.push_back({plan.to, work.b, work.bits});
}

void MeshEditor::plan_segment(VertexId a, VertexId b, SegmentPlan& plan) const {
    plan.piece_count = 0;
    plan.vertices.clear();
    plan.crosses_constraint = false;
    VertexId u = a;
    while (u != b) {
        if (plan.piece_count == plan.pieces.size()) plan.pieces.emplace_back();
        PiecePlan& piece = plan.pieces[plan.piece_count];
        plan_piece(u, b, piece);
        if (piece.crossed_constraint != no_half_edge) {
            plan.crosses_constraint = true;
            return;
        }
        ++plan.piece_count;
        plan.vertices.push_back(piece.from);
        plan.vertices.push_back(piece.to);
        for (const HalfEdge e : piece.right_chain) plan.vertices.push_back(mesh_.dest(e));
        for (const HalfEdge e : piece.left_chain) plan.vertices.push_back(mesh_.org(e));
        u = piece.to;
    }
}

void MeshEditor::apply_segment(const SegmentPlan& plan, std::uint8_t bits) {
    for (std::size_t i = 0; i < plan.piece_count; ++i) apply_piece(plan.pieces[i], bits);
}

void MeshEditor::cross_constraint(
    VertexId u, VertexId w, std::uint8_t bits, HalfEdge f, std::vector<Work>& stack) {
    GhostMesh& m = mesh_;
    const VertexId p = m.org(f);
    const VertexId r = m.dest(f);
    const std::uint8_t f_bits = m.edge_bits(f);
    // Intersection of u-w and p-r, in coordinates relative to u (exact differences for nearby
    // points), parameters t along u->w and s along p->r.
    const Point2 pu = m.p(u);
    const double wx = m.p(w).x - pu.x, wy = m.p(w).y - pu.y;
    const double px = m.p(p).x - pu.x, py = m.p(p).y - pu.y;
    const double rx = m.p(r).x - m.p(p).x, ry = m.p(r).y - m.p(p).y;
    const double denom = wx * ry - wy * rx;
    double t = (px * ry - py * rx) / denom;
    double s = (px * wy - py * wx) / denom;
    t = std::clamp(t, 0.0, 1.0);
    s = std::clamp(s, 0.0, 1.0);
    const Point2 at{pu.x + t * wx, pu.y + t * wy};
    const double z_new = z_[u] + t * (z_[w] - z_[u]);
    const double z_old = z_[p] + s * (z_[r] - z_[p]);

    VertexId x;
    if (at == m.p(p)) {
        x = p;
    } else if (at == m.p(r)) {
        x = r;
    } else {
        // Take the old constraint out and restore the constrained Delaunay property without it
        // (Lawson flips), so that inserting x and then the four pieces keeps the mesh a CDT at
        // every step; the old line is re-inserted through x below.
        m.set_edge_bits(f, 0);
        legalize(f);
        // A soft (2-D) line takes its height from the hard one it crosses.
        const double z_x = bits == constraint_soft     ? z_old
                           : f_bits == constraint_soft ? z_new
                                                       : 0.5 * (z_new + z_old);
        x = insert_point(at, z_x, vertex_edge_[p]);
        if (x != p && x != r) {
            stack.push_back({x, r, f_bits});
            stack.push_back({p, x, f_bits});
        } else {
            stack.push_back({p, r, f_bits});
        }
    }
    const double z_at_x = x == p || x == r ? z_[x] : z_old;
    const bool heights_compared = bits != constraint_soft && f_bits != constraint_soft;
    crossings_.push_back(
        {m.p(x), z_at_x, z_new, heights_compared && std::abs(z_at_x - z_new) > z_tolerance_});
    stack.push_back({x, w, bits});
    stack.push_back({u, x, bits});
}

}  // namespace dtm::detail
