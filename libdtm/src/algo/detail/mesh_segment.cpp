// SPDX-License-Identifier: MIT
//
// Segment insertion into the edge mesh (see mesh_edit.cpp for the method and references): the
// walk along the segment, the cavity retriangulation, and crossings of two constraints.
#include <algorithm>
#include <cmath>

#include "algo/detail/mesh_edit.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

/// Collinear q lies on the ray from a through b (same direction), decided by comparisons only.
bool same_direction(const Point2& a, const Point2& b, const Point2& q)
{
    const auto sign = [](double from, double to) { return (to > from) - (to < from); };
    return sign(a.x, q.x) == sign(a.x, b.x) && sign(a.y, q.y) == sign(a.y, b.y);
}

}  // namespace

void MeshEditor::plan_piece(VertexId u, VertexId w, PiecePlan& plan) const
{
    const EdgeMesh& m = mesh_;
    const auto side = [&](VertexId v) { return orient(u, w, v); };
    plan.from = u;
    plan.to = w;
    plan.along = no_edge;
    plan.crossed_constraint = no_edge;
    plan.crossed.clear();
    plan.right_chain.clear();
    plan.left_chain.clear();

    // 1. Find the edge along u->w, or the triangle at u that the segment enters.
    const EdgeId start = vertex_edge_[u];
    EdgeId e = start;
    EdgeId sector = no_edge;
    int side_e = side(m.dest(e));
    do {
        const VertexId p = m.dest(e);
        if (side_e == 0 && same_direction(m.p(u), m.p(w), m.p(p))) {
            plan.along = e;
            plan.to = p;
            return;
        }
        const EdgeId next = m.onext[e];
        const int side_next = side(m.dest(next));
        if (side_e < 0 && side_next > 0 && is_triangle(e)) {
            sector = e;
            break;
        }
        e = next;
        side_e = side_next;
    } while (e != start);
    if (sector == no_edge) throw Error("triangulation: breakline leaves the triangulated hull");

    // 2. Walk through the crossed triangles, collecting crossed edges and the cavity boundary.
    plan.right_chain.push_back(sector);                  // u -> ... -> to
    plan.left_chain.push_back(m.lnext(m.lnext(sector)));  // reversed: ... -> u
    EdgeId f = m.lnext(sector);  // from the right side to the left side of u->w
    for (;;) {
        if (m.is_constrained(f)) {
            plan.crossed_constraint = f;
            return;
        }
        plan.crossed.push_back(f);
        const EdgeId g = m.oprev[f];  // p -> v, v the apex beyond f
        const VertexId v = m.dest(g);
        const int s = v == w ? 0 : side(v);
        if (s == 0) {
            plan.right_chain.push_back(g);
            plan.left_chain.push_back(m.lnext(g));
            plan.to = v;
            break;
        }
        if (s < 0) {
            plan.right_chain.push_back(g);
            f = m.lnext(g);
        } else {
            plan.left_chain.push_back(m.lnext(g));
            f = g;
        }
    }
    std::reverse(plan.left_chain.begin(), plan.left_chain.end());
    return;
}

void MeshEditor::apply_piece(const PiecePlan& plan, std::uint8_t bits, EdgeSlots& slots)
{
    EdgeMesh& m = mesh_;
    if (plan.along != no_edge) {
        m.constrained[plan.along >> 1] |= bits;
        return;
    }
    // Replace the crossed edges by the segment and retriangulate both sides.
    for (const EdgeId c : plan.crossed) delete_edge(c, slots);
    const EdgeId segment = m.connect(slots, plan.left_chain.back(), plan.left_chain.front());
    m.constrained[segment >> 1] = bits;
    vertex_edge_[plan.from] = segment;
    fill_cavity(segment, plan.left_chain, slots);
    fill_cavity(EdgeMesh::sym(segment), plan.right_chain, slots);
}

void MeshEditor::insert_piece(const Work& work, std::vector<Work>& stack)
{
    PiecePlan& plan = piece_scratch_;
    plan_piece(work.a, work.b, plan);
    if (plan.crossed_constraint != no_edge) {
        cross_constraint(work.a, work.b, work.bits, plan.crossed_constraint, stack);
        return;
    }
    ensure_slots(plan.crossed.size() + 4);
    apply_piece(plan, work.bits, slots_);
    if (plan.to != work.b) stack.push_back({plan.to, work.b, work.bits});
}

void MeshEditor::plan_segment(VertexId a, VertexId b, SegmentPlan& plan) const
{
    plan.piece_count = 0;
    plan.vertices.clear();
    plan.crosses_constraint = false;
    VertexId u = a;
    while (u != b) {
        if (plan.piece_count == plan.pieces.size()) plan.pieces.emplace_back();
        PiecePlan& piece = plan.pieces[plan.piece_count];
        plan_piece(u, b, piece);
        if (piece.crossed_constraint != no_edge) {
            plan.crosses_constraint = true;
            return;
        }
        ++plan.piece_count;
        plan.vertices.push_back(piece.from);
        plan.vertices.push_back(piece.to);
        for (const EdgeId e : piece.right_chain) plan.vertices.push_back(mesh_.dest(e));
        for (const EdgeId e : piece.left_chain) plan.vertices.push_back(mesh_.org[e]);
        u = piece.to;
    }
}

void MeshEditor::apply_segment(const SegmentPlan& plan, std::uint8_t bits, EdgeSlots& slots)
{
    for (std::size_t i = 0; i < plan.piece_count; ++i) apply_piece(plan.pieces[i], bits, slots);
}

void MeshEditor::fill_cavity(EdgeId first_base, const std::vector<EdgeId>& edges,
                             EdgeSlots& slots)
{
    // Explicit stack of sub-polygons: base edge plus a range of boundary edges in `edges`
    // (boundary ccw from dest(base) back to org(base), polygon on the left of each).
    struct Piece {
        EdgeId base;
        std::size_t lo;
        std::size_t hi;
    };
    EdgeMesh& m = mesh_;
    thread_local std::vector<Piece> pieces;  // apply_segment runs on several threads at once
    pieces.assign(1, {first_base, 0, edges.size()});
    while (!pieces.empty()) {
        const Piece piece = pieces.back();
        pieces.pop_back();
        if (piece.hi - piece.lo < 3) continue;  // already a triangle
        const VertexId u = m.org[piece.base];
        const VertexId w = m.dest(piece.base);
        std::size_t best = piece.lo + 1;
        for (std::size_t j = piece.lo + 2; j < piece.hi; ++j) {
            const VertexId c = m.org[edges[best]];
            const VertexId q = m.org[edges[j]];
            if (geom::incircle(m.p(u), m.p(w), m.p(c), m.p(q)) > 0) best = j;
        }
        EdgeId into_c = edges[best - 1];
        if (best > piece.lo + 1) {
            into_c = m.connect(slots, piece.base, edges[best]);
            pieces.push_back({EdgeMesh::sym(into_c), piece.lo, best});
        }
        if (best < piece.hi - 1) {
            const EdgeId c_to_u = m.connect(slots, into_c, piece.base);
            pieces.push_back({EdgeMesh::sym(c_to_u), best, piece.hi});
        }
    }
}

void MeshEditor::cross_constraint(VertexId u, VertexId w, std::uint8_t bits, EdgeId f,
                                  std::vector<Work>& stack)
{
    EdgeMesh& m = mesh_;
    const VertexId p = m.org[f];
    const VertexId r = m.dest(f);
    const std::uint8_t f_bits = m.constrained[f >> 1];
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
        m.constrained[f >> 1] = 0;
        legalize(f);
        // A soft (2-D) line takes its height from the hard one it crosses.
        const double z_x = bits == constraint_soft ? z_old
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
    crossings_.push_back({m.p(x), z_at_x, z_new,
                          heights_compared && std::abs(z_at_x - z_new) > z_tolerance_});
    stack.push_back({x, w, bits});
    stack.push_back({u, x, bits});
}

}  // namespace dtm::detail
